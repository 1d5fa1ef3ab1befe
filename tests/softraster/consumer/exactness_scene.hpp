// The frames the exactness test draws, shared by both of its sides: exactness_reference.cpp,
// built inside the project with the project's flags, writes them to a file; consumer/exactness.cpp,
// built outside against the installed package with a compiler's default flags, draws them again
// and compares every colour and depth byte. The shader is the project's own Phong twin
// (shaders/lit.hpp, lit per vertex: the lighting, pow included, runs inside the pipeline's fused
// and fast entry points, where a contracting compiler would fuse it), so the arithmetic compared
// is the one the conformance suite checks against lavapipe. Per vertex rather than per pixel to
// keep the four builds of this file quick (the per-pixel fragment code is instantiated per
// depth format and compare op).
// The frames cover both float paths: the SIMD fast path (fused fmuladd, 1 and 4 samples) and the
// scalar path with fused and with separate fmuladd, and lines and points (polygon modes), all
// with D32_SFLOAT depth: the draws name that one format (Context::draw's Formats), so each of the
// test's four builds of this file compiles three pipelines rather than nine. The geometry uses only + - * / and sqrt (correctly rounded everywhere), never
// sin or cos, whose library results may differ between the two builds.
// Deliberately no file format beyond what the test needs: a name, the sizes, then raw bytes.
#pragma once

#include <lit.hpp>

#include <softraster/framebuffer.hpp>
#include <softraster/pipeline.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace exactness {

using Shader = shaders::PhongVertex;
inline constexpr softraster::DepthFormat kDepth = softraster::DepthFormat::D32Sfloat;  // every frame's

// One rendered frame: every sample's colour (RGBA8) and depth as stored.
struct Frame {
  std::string name;
  std::uint32_t width = 0, height = 0, samples = 0;
  std::vector<std::uint8_t> colour;
  std::vector<std::uint32_t> depth;
};

// A sphere of radius 1 made from a cube whose faces are split into n x n quads, each point
// pushed out to the sphere; normals are the positions, colours vary with the position.
inline void sphere(int n, std::vector<Shader::Vertex>& vertices, std::vector<std::uint32_t>& indices) {
  const float axes[6][3][3] = {
      {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}, {1, 0, 0}},
      {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}}, {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {0, 1, 0}, {1, 0, 0}},
  };
  for (const auto& face : axes) {
    const std::uint32_t first = static_cast<std::uint32_t>(vertices.size());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const float s = 2.0f * static_cast<float>(i) / static_cast<float>(n) - 1.0f;
        const float t = 2.0f * static_cast<float>(j) / static_cast<float>(n) - 1.0f;
        float p[3];
        for (int k = 0; k < 3; ++k) p[k] = face[0][k] + s * face[1][k] + t * face[2][k];
        const float length = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const softraster::Vec3 q{p[0] / length, p[1] / length, p[2] / length};
        vertices.push_back({q, q, {0.5f + 0.4f * q.x, 0.5f + 0.3f * q.y, 0.6f - 0.3f * q.z, 1.0f}});
      }
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const std::uint32_t a = first + static_cast<std::uint32_t>(j * (n + 1) + i), b = a + 1;
        const std::uint32_t c = a + static_cast<std::uint32_t>(n + 1), d = c + 1;
        indices.insert(indices.end(), {a, b, d, a, d, c});
      }
    }
  }
}

// Camera space: the sphere at (0.2, -0.1, 3.2), turned a little; Vulkan clip space (y down, z in
// [0, w]) from a perspective with near 1 and far 10.
inline Shader::Uniforms uniforms(float aspect) {
  softraster::Mat4 model = softraster::Mat4::identity();
  model.at(0, 0) = 0.8f, model.at(0, 2) = 0.6f, model.at(2, 0) = -0.6f, model.at(2, 2) = 0.8f;
  model.at(0, 3) = 0.2f, model.at(1, 3) = -0.1f, model.at(2, 3) = 3.2f;
  const float f = 1.7320508f, far = 10.0f, near = 1.0f;
  softraster::Mat4 projection;
  projection.at(0, 0) = f / aspect;
  projection.at(1, 1) = f;
  projection.at(2, 2) = far / (far - near);
  projection.at(2, 3) = -(far * near) / (far - near);
  projection.at(3, 2) = 1.0f;
  Shader::Uniforms u;
  u.modelViewProjection = softraster::multiply(projection, model);
  u.modelToLighting = model;
  u.normalToLighting = model;
  u.lightPosition = {1.5f, -2.0f, 0.5f, 1.0f};
  u.lightPower = {0.9f, 0.85f, 0.7f, 1.0f};
  u.indirect = {0.12f, 0.1f, 0.15f, 1.0f};
  u.specular = {0.6f, 0.6f, 0.6f, 24.0f};
  u.pointSize = 3.0f;
  return u;
}

// Draws every frame; the error names the frame.
inline softraster::Result<std::vector<Frame>> render() {
  std::vector<Shader::Vertex> vertices;
  std::vector<std::uint32_t> indices;
  sphere(12, vertices, indices);
  struct Setup {
    const char* name;
    softraster::DepthFormat format;  // kDepth: the one format the draws are compiled for
    std::uint32_t samples;
    softraster::Method method;
    bool fused;
    softraster::PolygonMode overlay;  // a second draw of the same sphere in this mode, or Fill for none
  };
  const Setup setups[] = {
      {"fast_d32", softraster::DepthFormat::D32Sfloat, 1, softraster::Method::Exact, true, softraster::PolygonMode::Fill},
      {"fast_msaa_d32", softraster::DepthFormat::D32Sfloat, 4, softraster::Method::Exact, true, softraster::PolygonMode::Fill},
      {"scalar_separate_d32_lines", softraster::DepthFormat::D32Sfloat, 1, softraster::Method::ExactScalar, false,
       softraster::PolygonMode::Line},
      {"scalar_fused_d32_points", softraster::DepthFormat::D32Sfloat, 1, softraster::Method::ExactScalar, true,
       softraster::PolygonMode::Point},
  };
  const std::uint32_t width = 96, height = 64;
  std::vector<Frame> frames;
  for (const Setup& setup : setups) {
    softraster::Result<softraster::Framebuffer> framebuffer =
        softraster::Framebuffer::create(width, height, setup.format, setup.samples);
    if (!framebuffer) return framebuffer.status().prefixed(setup.name);
    softraster::ContextOptions options;
    options.method = setup.method;
    options.threads = 2;
    options.fusedMultiplyAdd = setup.fused;
    const softraster::Context context(options);
    framebuffer->clear({0.05f, 0.05f, 0.1f, 1.0f}, 1.0f);
    const Shader::Uniforms u = uniforms(static_cast<float>(width) / static_cast<float>(height));
    softraster::PipelineState state;
    state.rasterization.cullMode = softraster::CullMode::None;  // back faces drawn, then hidden by depth
    if (softraster::Status s = context.drawIndexed<Shader, kDepth>(state, u, vertices, indices, *framebuffer); !s) {
      return s.prefixed(setup.name);
    }
    if (setup.overlay != softraster::PolygonMode::Fill) {
      state.rasterization.polygonMode = setup.overlay;
      state.depth.compareOp = softraster::CompareOp::LessOrEqual;
      if (softraster::Status s = context.drawIndexed<Shader, kDepth>(state, u, vertices, indices, *framebuffer); !s) {
        return s.prefixed(setup.name);
      }
    }
    frames.push_back({setup.name, width, height, setup.samples, framebuffer->colour(), framebuffer->depthStorage()});
  }
  return frames;
}

// The file both sides agree on: per frame a line "name width height samples", then the colour
// bytes, then the depth words' bytes.
inline bool write(const std::string& path, const std::vector<Frame>& frames) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return false;
  bool ok = true;
  for (const Frame& f : frames) {
    ok = ok && std::fprintf(file, "%s %u %u %u\n", f.name.c_str(), f.width, f.height, f.samples) > 0;
    ok = ok && std::fwrite(f.colour.data(), 1, f.colour.size(), file) == f.colour.size();
    ok = ok && std::fwrite(f.depth.data(), sizeof(std::uint32_t), f.depth.size(), file) == f.depth.size();
  }
  return std::fclose(file) == 0 && ok;
}

inline softraster::Result<std::vector<Frame>> read(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return softraster::Status::error(path + ": cannot open");
  std::vector<Frame> frames;
  char name[128];
  Frame f;
  while (std::fscanf(file, "%127s %u %u %u", name, &f.width, &f.height, &f.samples) == 4 && std::fgetc(file) == '\n') {
    f.name = name;
    const std::size_t samples = static_cast<std::size_t>(f.width) * f.height * f.samples;
    f.colour.resize(samples * 4);
    f.depth.resize(samples);
    if (std::fread(f.colour.data(), 1, f.colour.size(), file) != f.colour.size() ||
        std::fread(f.depth.data(), sizeof(std::uint32_t), f.depth.size(), file) != f.depth.size()) {
      std::fclose(file);
      return softraster::Status::error(path + ": frame '" + f.name + "' is cut short");
    }
    frames.push_back(f);
  }
  std::fclose(file);
  if (frames.empty()) return softraster::Status::error(path + ": no frames");
  return frames;
}

}  // namespace exactness
