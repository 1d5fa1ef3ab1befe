// Scene -> softraster and Scene -> vkref adapters (see render.hpp).
#include "render.hpp"

#include <softraster/pipeline.hpp>

#include <shaders/vertex_color_frag.spv.h>
#include <shaders/vertex_color_vert.spv.h>

#include <chrono>
#include <cstring>
#include <iterator>

namespace crosscheck {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// The vertex_color pair as vkref needs it: SPIR-V from the build, layout from the C++ twin.
vkref::ShaderProgram vertexColorProgram() {
  vkref::ShaderProgram program;
  program.name = "vertex_color";
  program.vertexSpirv = {vertex_color_vert_spirv, std::size(vertex_color_vert_spirv)};
  program.fragmentSpirv = {vertex_color_frag_spirv, std::size(vertex_color_frag_spirv)};
  program.attributes.assign(shaders::VertexColor::kAttributes.begin(), shaders::VertexColor::kAttributes.end());
  program.vertexStride = sizeof(shaders::VertexColor::Vertex);
  return program;
}

template <class T>
std::vector<std::byte> bytesOf(const T* data, std::size_t count) {
  std::vector<std::byte> bytes(sizeof(T) * count);
  std::memcpy(bytes.data(), data, bytes.size());
  return bytes;
}

}  // namespace

std::optional<Frame> renderSoftraster(const Scene& scene, std::string* error,
                                     const softraster::ContextOptions& options) {
  const auto start = Clock::now();
  softraster::Framebuffer framebuffer(scene.width, scene.height);
  framebuffer.clear(scene.clearColour, scene.clearDepth);
  const softraster::Context context(options);
  for (const Draw& draw : scene.draws) {
    const shaders::VertexColor::Uniforms uniforms{scene.viewProjection};
    const softraster::Status status = context.draw<shaders::VertexColor>(
        draw.state, uniforms, std::span<const shaders::VertexColor::Vertex>(draw.vertices),
        std::span<const std::uint32_t>(draw.indices), framebuffer);
    if (!status) {
      *error = "softraster: draw '" + draw.name + "': " + status.message();
      return std::nullopt;
    }
  }
  Frame frame;
  frame.milliseconds = millisecondsSince(start);
  frame.width = scene.width;
  frame.height = scene.height;
  frame.rgba = std::move(framebuffer.colour());
  frame.depth = std::move(framebuffer.depth());
  return frame;
}

std::optional<Frame> renderVulkan(const Scene& scene, vkref::Renderer& renderer, std::string* error) {
  const vkref::ShaderProgram vertexColor = vertexColorProgram();
  vkref::FrameRequest request;
  request.width = scene.width;
  request.height = scene.height;
  request.clearColour = {scene.clearColour.x, scene.clearColour.y, scene.clearColour.z, scene.clearColour.w};
  request.clearDepth = scene.clearDepth;
  for (const Draw& draw : scene.draws) {
    vkref::DrawCall call;
    call.program = &vertexColor;
    call.state = draw.state;
    call.vertexData = bytesOf(draw.vertices.data(), draw.vertices.size());
    call.indices = draw.indices;
    const shaders::VertexColor::Uniforms uniforms{scene.viewProjection};
    call.pushConstants = bytesOf(&uniforms, 1);
    request.draws.push_back(std::move(call));
  }
  const auto start = Clock::now();
  vkref::FrameImages images;
  std::string vkError;
  if (!renderer.render(request, &images, &vkError)) {
    *error = "vulkan: " + vkError;
    return std::nullopt;
  }
  Frame frame;
  frame.milliseconds = millisecondsSince(start);
  frame.width = images.width;
  frame.height = images.height;
  frame.rgba = std::move(images.rgba);
  frame.depth = std::move(images.depth);
  return frame;
}

}  // namespace crosscheck
