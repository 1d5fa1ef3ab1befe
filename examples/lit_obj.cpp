// Example: an OBJ mesh (v, vn and f lines; polygons split into fans) lit per pixel by one
// directional light, drawn into a 1-sample framebuffer and written as a PNG.
//   lit_obj MESH.obj OUT.png [WIDTH HEIGHT]
// Shows: a shader written once over its float type (so the SIMD fast path shades 8 pixels at a
// time), matrices from GLM in Vulkan's clip space (softraster/glm.hpp), errors as Status/Result.
// Deliberately not a general OBJ loader: no materials, no texture coordinates, no groups.
#define GLM_FORCE_DEPTH_ZERO_TO_ONE  // GLM's projections give z in [0, w], as Vulkan (and softraster) want
#include "png.hpp"

#include <softraster/glm.hpp>
#include <softraster/pipeline.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

// sqrt for both of a shader's float types: the library's FloatBatch has no transcendental
// functions, so a shader that needs one writes it per lane.
float squareRoot(float x) { return std::sqrt(x); }
softraster::FloatBatch squareRoot(softraster::FloatBatch x) {
  float lanes[softraster::kBatchLanes];
  x.store(lanes);
  for (float& lane : lanes) lane = std::sqrt(lane);
  return softraster::FloatBatch::load(lanes);
}

struct LitShader {
  struct Vertex {
    softraster::Vec3 position;
    softraster::Vec3 normal;
  };
  struct Uniforms {
    softraster::Mat4 modelViewProjection;
    softraster::Mat4 model;             // object to world (normals: its rotation only here)
    softraster::Vec4 towardsLight;      // world space, unit length
    softraster::Vec4 colour{0.85f, 0.55f, 0.3f, 1.0f};
  };
  static constexpr int kVaryings = 3;  // the world-space normal

  static softraster::Vec4 vertex(const Uniforms& u, const Vertex& in, float* normal) {
    const softraster::Vec4 n = softraster::transform(u.model, {in.normal.x, in.normal.y, in.normal.z, 0.0f});
    normal[0] = n.x, normal[1] = n.y, normal[2] = n.z;
    return softraster::transform(u.modelViewProjection, {in.position.x, in.position.y, in.position.z, 1.0f});
  }

  template <class F>
  static softraster::Vec4T<F> fragment(const Uniforms& u, const F* normal) {
    const F length = squareRoot(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    const F facing = (normal[0] * u.towardsLight.x + normal[1] * u.towardsLight.y + normal[2] * u.towardsLight.z) / length;
    using softraster::sseMax;  // unqualified: FloatBatch's own is found by argument-dependent lookup
    const F light = F(0.15f) + F(0.85f) * sseMax(facing, F(0.0f));
    return {u.colour.x * light, u.colour.y * light, u.colour.z * light, F(1.0f)};
  }
};
static_assert(softraster::ShaderInterface<LitShader>);  // the same check Context::draw makes

// The mesh as a triangle list, one vertex per corner; normals from the file, or the face's own.
softraster::Result<std::vector<LitShader::Vertex>> readObj(const std::string& path) {
  std::ifstream file(path);
  if (!file) return softraster::Status::error(path + ": cannot open");
  std::vector<softraster::Vec3> positions, normals;
  std::vector<LitShader::Vertex> triangles;
  std::string line;
  for (int number = 1; std::getline(file, line); ++number) {
    std::istringstream words(line);
    std::string kind;
    words >> kind;
    if (kind == "v" || kind == "vn") {
      softraster::Vec3 v;
      if (!(words >> v.x >> v.y >> v.z)) return softraster::Status::error(path + ":" + std::to_string(number) + ": bad vector");
      (kind == "v" ? positions : normals).push_back(v);
    } else if (kind == "f") {
      std::vector<LitShader::Vertex> corners;
      bool hasNormals = true;
      for (std::string corner; words >> corner;) {
        // "p", "p/t", "p//n" or "p/t/n", 1-based
        const std::size_t slash = corner.find('/'), last = corner.rfind('/');
        const long p = std::stol(corner.substr(0, slash));
        const long n = slash != std::string::npos && last != slash ? std::stol(corner.substr(last + 1)) : 0;
        if (p < 1 || static_cast<std::size_t>(p) > positions.size() || n < 0 || static_cast<std::size_t>(n) > normals.size()) {
          return softraster::Status::error(path + ":" + std::to_string(number) + ": index out of range");
        }
        hasNormals = hasNormals && n > 0;
        corners.push_back({positions[static_cast<std::size_t>(p - 1)], n > 0 ? normals[static_cast<std::size_t>(n - 1)] : softraster::Vec3{}});
      }
      if (corners.size() < 3) return softraster::Status::error(path + ":" + std::to_string(number) + ": a face needs 3 corners");
      if (!hasNormals) {
        const glm::vec3 a = softraster::toGlm(corners[0].position), b = softraster::toGlm(corners[1].position);
        const glm::vec3 c = softraster::toGlm(corners[2].position);
        const softraster::Vec3 n = softraster::fromGlm(glm::normalize(glm::cross(b - a, c - a)));
        for (LitShader::Vertex& corner : corners) corner.normal = n;
      }
      for (std::size_t i = 1; i + 1 < corners.size(); ++i) triangles.insert(triangles.end(), {corners[0], corners[i], corners[i + 1]});
    }
  }
  if (triangles.empty()) return softraster::Status::error(path + ": no faces");
  return triangles;
}

softraster::Status run(const std::string& meshPath, const std::string& outPath, std::uint32_t width, std::uint32_t height) {
  softraster::Result<std::vector<LitShader::Vertex>> mesh = readObj(meshPath);
  if (!mesh) return mesh.status();
  // Frame the mesh: its bounding box's centre at the origin, its largest extent 2.
  glm::vec3 low(1e30f), high(-1e30f);
  for (const LitShader::Vertex& v : *mesh) {
    low = glm::min(low, softraster::toGlm(v.position));
    high = glm::max(high, softraster::toGlm(v.position));
  }
  const glm::vec3 extent = high - low;
  const float scale = 2.0f / std::max({extent.x, extent.y, extent.z, 1e-6f});
  const glm::mat4 model = glm::rotate(glm::mat4(1.0f), glm::radians(-35.0f), glm::vec3(1, 0, 0)) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(scale)) * glm::translate(glm::mat4(1.0f), -(low + high) * 0.5f);
  const glm::mat4 view = glm::lookAt(glm::vec3(0, 0.6f, 3.2f), glm::vec3(0), glm::vec3(0, 1, 0));
  // GLM's projection is GL's with y up; softraster's clip space has y down: flip it.
  const glm::mat4 projection = softraster::flipClipY(
      glm::perspective(glm::radians(45.0f), static_cast<float>(width) / static_cast<float>(height), 0.1f, 20.0f));

  LitShader::Uniforms uniforms;
  uniforms.modelViewProjection = softraster::fromGlm(projection * view * model);
  // Normals: the model's rotation (its scale is uniform, so only the length changes, and the
  // fragment shader divides that out).
  uniforms.model = softraster::fromGlm(model);
  uniforms.towardsLight = softraster::fromGlm(glm::vec4(glm::normalize(glm::vec3(-0.4f, 0.8f, 0.6f)), 0.0f));

  softraster::Result<softraster::Framebuffer> framebuffer = softraster::Framebuffer::create(width, height);
  if (!framebuffer) return framebuffer.status();
  framebuffer->clear({0.08f, 0.09f, 0.12f, 1.0f}, 1.0f);
  softraster::PipelineState state;  // triangle list, back faces culled, counter-clockwise in front, depth LESS
  const softraster::Context context;
  // Naming the framebuffer's depth format compiles the pipeline for that format only (a third of
  // the code, and of the compile time); without it, draw<LitShader> works with any format.
  if (softraster::Status status = context.draw<LitShader, softraster::DepthFormat::D32Sfloat>(state, uniforms, *mesh, *framebuffer);
      !status) {
    return status;
  }
  if (!writePng(outPath, width, height, framebuffer->colour())) return softraster::Status::error(outPath + ": cannot write");
  std::printf("wrote %s (%ux%u, %zu triangles, %u threads)\n", outPath.c_str(), width, height, mesh->size() / 3,
              context.threads());
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: lit_obj MESH.obj OUT.png [WIDTH HEIGHT]\n");
    return 2;
  }
  const std::uint32_t width = argc == 5 ? static_cast<std::uint32_t>(std::stoul(argv[3])) : 640;
  const std::uint32_t height = argc == 5 ? static_cast<std::uint32_t>(std::stoul(argv[4])) : 480;
  if (const softraster::Status status = run(argv[1], argv[2], width, height); !status) {
    std::fprintf(stderr, "lit_obj: %s\n", status.message().c_str());  // only main() prints
    return 1;
  }
  return 0;
}
