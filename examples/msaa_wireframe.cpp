// Example: a spinning cube's faces drawn with 4x MSAA, resolved to one sample per pixel, then its
// edges drawn over the resolved image as 1.5-pixel lines (polygon mode Line), written as a PNG.
//   msaa_wireframe OUT.png [WIDTH HEIGHT]
// Shows: a multisampled Framebuffer and resolve(), depth bias keeping the faces behind their own
// edges, a second shader and state for the overlay, GLM's matrices in Vulkan's clip space.
// The overlay is drawn after the resolve on purpose: crisp one-sample edges over smoothed faces
// (4x MSAA lines would be resolved too).
// Deliberately one mesh and one light-free colour per face: the point is the passes, not shading.
#define GLM_FORCE_DEPTH_ZERO_TO_ONE  // GLM's projections give z in [0, w], as Vulkan (and softraster) want
#include "png.hpp"

#include <softraster/glm.hpp>
#include <softraster/pipeline.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <string>
#include <vector>

namespace {

// The one depth format used, named in the draws so only its pipeline is compiled.
constexpr softraster::DepthFormat kDepth = softraster::DepthFormat::D32Sfloat;

// The faces: each vertex carries its face's colour.
struct FaceShader {
  struct Vertex {
    softraster::Vec3 position;
    softraster::Vec4 colour;
  };
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
  };
  static constexpr int kVaryings = 4;
  static constexpr softraster::InterpolationSet<kVaryings> kInterpolation{
      softraster::Interpolation::Flat, softraster::Interpolation::Flat, softraster::Interpolation::Flat,
      softraster::Interpolation::Flat};
  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* colour) {
    for (int i = 0; i < 4; ++i) colour[i] = in.colour[i];
    return softraster::transform(u.modelViewProjection, {in.position.x, in.position.y, in.position.z, 1.0f});
  }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms&, const F* colour) {
    return {colour[0], colour[1], colour[2], colour[3]};
  }
};

// The edges: one colour from the uniforms, the same vertices.
struct InkShader {
  using Vertex = FaceShader::Vertex;
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
    softraster::Vec4 ink{0.05f, 0.05f, 0.05f, 1.0f};
  };
  static constexpr int kVaryings = 0;
  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float*) {
    return softraster::transform(u.modelViewProjection, {in.position.x, in.position.y, in.position.z, 1.0f});
  }
  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F*) {
    return {F(u.ink.x), F(u.ink.y), F(u.ink.z), F(u.ink.w)};
  }
};

// A unit cube as 12 counter-clockwise triangles seen from outside (GL's convention, which the y
// flip keeps), 4 vertices per face.
void cube(std::vector<FaceShader::Vertex>& vertices, std::vector<std::uint32_t>& indices) {
  const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const softraster::Vec4 colours[6] = {{0.9f, 0.3f, 0.2f, 1}, {0.2f, 0.7f, 0.3f, 1}, {0.2f, 0.4f, 0.9f, 1},
                                       {0.9f, 0.8f, 0.2f, 1}, {0.7f, 0.3f, 0.8f, 1}, {0.3f, 0.8f, 0.8f, 1}};
  for (int f = 0; f < 6; ++f) {
    const glm::vec3 n = normals[f];
    const glm::vec3 u = glm::abs(n.y) > 0.5f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 v = glm::cross(n, u);  // (u, v, n) right-handed: u then v turns counter-clockwise seen from outside
    const auto first = static_cast<std::uint32_t>(vertices.size());
    for (const glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
      vertices.push_back({softraster::fromGlm(0.5f * (n + c.x * u + c.y * v)), colours[f]});
    }
    indices.insert(indices.end(), {first, first + 1, first + 2, first, first + 2, first + 3});
  }
}

softraster::Status run(const std::string& outPath, std::uint32_t width, std::uint32_t height) {
  std::vector<FaceShader::Vertex> vertices;
  std::vector<std::uint32_t> indices;
  cube(vertices, indices);
  const glm::mat4 model = glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(1, 0, 0)),
                                      glm::radians(40.0f), glm::vec3(0, 1, 0));
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 0, 2.6f), glm::vec3(0), glm::vec3(0, 1, 0));
  const glm::mat4 projection = softraster::flipClipY(
      glm::perspective(glm::radians(45.0f), static_cast<float>(width) / static_cast<float>(height), 0.1f, 10.0f));
  const softraster::Mat4 mvp = softraster::fromGlm(projection * view * model);
  const softraster::Context context;

  // Pass 1: the faces, 4 samples per pixel, pushed back a little so their edges win pass 2's test.
  softraster::Result<softraster::Framebuffer> samples =
      softraster::Framebuffer::create(width, height, kDepth, 4);
  if (!samples) return samples.status();
  samples->clear({0.95f, 0.95f, 0.92f, 1.0f}, 1.0f);
  softraster::PipelineState faces;
  faces.rasterization.depthBias = {true, 1.0f, 0.0f, 1.0f};
  if (softraster::Status s = context.drawIndexed<FaceShader, kDepth>(faces, {mvp}, vertices, indices, *samples); !s) {
    return s.prefixed("faces");
  }
  // Pass 2: the resolve (colour averaged, depth sample 0), then the edges over it.
  softraster::Framebuffer image = samples->resolve();
  softraster::PipelineState edges;
  edges.rasterization.polygonMode = softraster::PolygonMode::Line;
  edges.rasterization.lineWidth = 1.5f;
  edges.depth.compareOp = softraster::CompareOp::LessOrEqual;
  edges.depth.writeEnable = false;
  if (softraster::Status s = context.drawIndexed<InkShader, kDepth>(edges, {mvp}, vertices, indices, image); !s) {
    return s.prefixed("edges");
  }
  if (!writePng(outPath, width, height, image.colour())) return softraster::Status::error(outPath + ": cannot write");
  std::printf("wrote %s (%ux%u, 4x MSAA faces, %zu edges' triangles)\n", outPath.c_str(), width, height, indices.size() / 3);
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 4) {
    std::fprintf(stderr, "usage: msaa_wireframe OUT.png [WIDTH HEIGHT]\n");
    return 2;
  }
  const std::uint32_t width = argc == 4 ? static_cast<std::uint32_t>(std::stoul(argv[2])) : 480;
  const std::uint32_t height = argc == 4 ? static_cast<std::uint32_t>(std::stoul(argv[3])) : 360;
  if (const softraster::Status status = run(argv[1], width, height); !status) {
    std::fprintf(stderr, "msaa_wireframe: %s\n", status.message().c_str());  // only main() prints
    return 1;
  }
  return 0;
}
