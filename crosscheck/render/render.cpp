// Scene -> softraster and Scene -> vkref adapters (see render.hpp).
#include "render/render.hpp"

#include <softraster/pipeline.hpp>

#include <shaders/vertex_color_flat_frag.spv.h>
#include <shaders/vertex_color_flat_vert.spv.h>
#include <shaders/vertex_color_frag.spv.h>
#include <shaders/vertex_color_noperspective_frag.spv.h>
#include <shaders/vertex_color_noperspective_vert.spv.h>
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

// A shading model's compiled SPIR-V pair and the vertex layout of its C++ twin.
template <class Shader, std::size_t VertWords, std::size_t FragWords>
vkref::ShaderProgram program(const char* name, const std::uint32_t (&vert)[VertWords],
                             const std::uint32_t (&frag)[FragWords]) {
  vkref::ShaderProgram p;
  p.name = name;
  p.vertexSpirv = {vert, VertWords};
  p.fragmentSpirv = {frag, FragWords};
  p.attributes.assign(Shader::kAttributes.begin(), Shader::kAttributes.end());
  p.vertexStride = sizeof(typename Shader::Vertex);
  return p;
}

vkref::ShaderProgram programFor(ShadingModel model) {
  switch (model) {
    case ShadingModel::VertexColorFlat:
      return program<shaders::VertexColorFlat>("vertex_color_flat", vertex_color_flat_vert_spirv,
                                               vertex_color_flat_frag_spirv);
    case ShadingModel::VertexColorNoPerspective:
      return program<shaders::VertexColorNoPerspective>("vertex_color_noperspective",
                                                        vertex_color_noperspective_vert_spirv,
                                                        vertex_color_noperspective_frag_spirv);
    case ShadingModel::VertexColor:
      break;
  }
  return program<shaders::VertexColor>("vertex_color", vertex_color_vert_spirv, vertex_color_frag_spirv);
}

// Calls f with a value of the C++ shader type of `model` (all vertex_color variants share
// their vertex and uniform types).
template <class F>
softraster::Status withShader(ShadingModel model, F&& f) {
  switch (model) {
    case ShadingModel::VertexColorFlat: return f(shaders::VertexColorFlat{});
    case ShadingModel::VertexColorNoPerspective: return f(shaders::VertexColorNoPerspective{});
    case ShadingModel::VertexColor: break;
  }
  return f(shaders::VertexColor{});
}

template <class T>
std::vector<std::byte> bytesOf(const T* data, std::size_t count) {
  std::vector<std::byte> bytes(sizeof(T) * count);
  std::memcpy(bytes.data(), data, bytes.size());
  return bytes;
}

}  // namespace

softraster::Result<Frame> renderSoftraster(const Scene& scene, const softraster::ContextOptions& options) {
  softraster::Framebuffer framebuffer(scene.width, scene.height, scene.depthFormat, scene.samples);
  const softraster::Context context(options);
  // Timed: clear, draws, MSAA resolve (not the framebuffer's allocation, not the Frame below).
  const auto start = Clock::now();
  // The 1/z buffer is cleared to 0 (infinitely far); it is not a Vulkan mode.
  framebuffer.clear(scene.clearColour,
                    options.depthMode == softraster::DepthMode::InverseZ ? 0.0f : scene.clearDepth);
  for (const Draw& draw : scene.draws) {
    const softraster::Status status = withShader(draw.shading, [&](auto shader) {
      using Shader = decltype(shader);
      const typename Shader::Uniforms uniforms{scene.viewProjection, draw.pointSize};
      const std::span<const typename Shader::Vertex> vertices(draw.vertices);
      return draw.indexed ? context.drawIndexed<Shader>(draw.state, uniforms, vertices, draw.indices, framebuffer)
                          : context.draw<Shader>(draw.state, uniforms, vertices, framebuffer);
    });
    if (!status) return status.prefixed("softraster: draw '" + draw.name + "'");
  }
  if (framebuffer.samples() > 1) framebuffer = framebuffer.resolve();  // as vkref reads Vulkan's back
  const double milliseconds = millisecondsSince(start);
  Frame frame;
  frame.milliseconds = milliseconds;
  frame.width = scene.width;
  frame.height = scene.height;
  frame.rgba = std::move(framebuffer.colour());
  frame.depthFormat = scene.depthFormat;
  frame.depth.resize(framebuffer.depthStorage().size());
  for (std::size_t i = 0; i < frame.depth.size(); ++i) frame.depth[i] = framebuffer.depth(i);
  frame.depthStorage = std::move(framebuffer.depthStorage());
  return frame;
}

softraster::Result<Frame> renderVulkan(const Scene& scene, vkref::Renderer& renderer) {
  std::vector<vkref::ShaderProgram> programs;  // one per draw, alive until the frame is rendered
  programs.reserve(scene.draws.size());
  vkref::FrameRequest request;
  request.width = scene.width;
  request.height = scene.height;
  request.clearColour = {scene.clearColour.x, scene.clearColour.y, scene.clearColour.z, scene.clearColour.w};
  request.clearDepth = scene.clearDepth;
  request.depthFormat = scene.depthFormat;
  request.samples = scene.samples;
  for (const Draw& draw : scene.draws) {
    vkref::DrawCall call;
    call.program = &programs.emplace_back(programFor(draw.shading));
    call.state = draw.state;
    call.vertexData = bytesOf(draw.vertices.data(), draw.vertices.size());
    call.indexed = draw.indexed;
    call.indices = draw.indices;
    const shaders::VertexColor::Uniforms uniforms{scene.viewProjection, draw.pointSize};
    call.pushConstants = bytesOf(&uniforms, 1);
    request.draws.push_back(std::move(call));
  }
  // Timed: vkref's render(), the nearest span to softraster's that vkref offers today; it also
  // holds resource creation, upload and read-back. Time its submit alone once vkref splits
  // prepare / submit / read-back.
  const auto start = Clock::now();
  vkref::FrameImages images;
  std::string vkError;
  if (!renderer.render(request, &images, &vkError)) {
    return softraster::Status::error("vulkan: " + vkError);
  }
  Frame frame;
  frame.milliseconds = millisecondsSince(start);
  frame.width = images.width;
  frame.height = images.height;
  frame.rgba = std::move(images.rgba);
  frame.depth = std::move(images.depth);
  frame.depthFormat = scene.depthFormat;
  frame.depthStorage = std::move(images.depthStorage);
  return frame;
}

softraster::Result<std::unique_ptr<vkref::Renderer>> openVulkan(const vkref::DeviceOptions& options) {
  std::string error;
  std::unique_ptr<vkref::Renderer> renderer = vkref::Renderer::create(options, &error);
  if (!renderer) return softraster::Status::error(error);
  return renderer;
}

}  // namespace crosscheck
