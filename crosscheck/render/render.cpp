// Scene -> softraster and Scene -> vkref adapters (see render.hpp). Both draw every Draw through
// its row of the shading-model table (shaders/shading_models.hpp); neither knows a model by name.
#include "render/render.hpp"

#include <softraster/pipeline.hpp>

#include <shading_models.hpp>

#include <chrono>
#include <string>

namespace crosscheck {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// What every shading model reads of a draw besides its mesh.
shaders::DrawParameters parametersOf(const Scene& scene, const Draw& draw) {
  return {scene.viewProjection, draw.pointSize};
}

// A shading model's compiled SPIR-V pair and the vertex layout of its C++ twin, for vkref.
vkref::ShaderProgram programOf(const shaders::ShadingModel& model) {
  vkref::ShaderProgram p;
  p.name = std::string(model.name);
  p.vertexSpirv = model.vertexSpirv;
  p.fragmentSpirv = model.fragmentSpirv;
  p.attributes.assign(model.attributes.begin(), model.attributes.end());
  p.vertexStride = model.vertexStride;
  return p;
}

}  // namespace

namespace {

// Clears `framebuffer` and draws the scene into it (every sample, not resolved).
softraster::Status drawScene(const Scene& scene, const softraster::Context& context,
                             const std::vector<shaders::SoftrasterDraw>& draws, softraster::Framebuffer& framebuffer) {
  // The 1/z buffer is cleared to 0 (infinitely far); it is not a Vulkan mode.
  framebuffer.clear(scene.clearColour,
                    context.options().depthMode == softraster::DepthMode::InverseZ ? 0.0f : scene.clearDepth);
  for (std::size_t i = 0; i < scene.draws.size(); ++i) {
    const Draw& draw = scene.draws[i];
    const softraster::Status status = draws[i].draw(context, draw.state, draw.indexed, draw.indices, framebuffer);
    if (!status) return status.prefixed("softraster: draw '" + draw.name + "'");
  }
  return {};
}

// Each draw's vertices and uniforms in its model's types.
std::vector<shaders::SoftrasterDraw> softrasterDraws(const Scene& scene) {
  std::vector<shaders::SoftrasterDraw> draws;
  draws.reserve(scene.draws.size());
  for (const Draw& draw : scene.draws) draws.push_back(draw.shading->prepareSoftraster(draw.mesh, parametersOf(scene, draw)));
  return draws;
}

}  // namespace

softraster::Result<softraster::Framebuffer> renderSoftrasterSamples(const Scene& scene,
                                                                   const softraster::ContextOptions& options) {
  softraster::Framebuffer framebuffer(scene.width, scene.height, scene.depthFormat, scene.samples);
  const softraster::Context context(options);
  if (softraster::Status drawn = drawScene(scene, context, softrasterDraws(scene), framebuffer); !drawn) return drawn;
  return framebuffer;
}

softraster::Result<Frame> renderSoftraster(const Scene& scene, const softraster::ContextOptions& options) {
  softraster::Framebuffer framebuffer(scene.width, scene.height, scene.depthFormat, scene.samples);
  const softraster::Context context(options);
  const std::vector<shaders::SoftrasterDraw> draws = softrasterDraws(scene);
  // Timed: clear, draws, MSAA resolve (not the framebuffer's allocation, not the Frame below).
  const auto start = Clock::now();
  if (softraster::Status drawn = drawScene(scene, context, draws, framebuffer); !drawn) return drawn;
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
    call.program = &programs.emplace_back(programOf(*draw.shading));
    call.state = draw.state;
    call.vertexData = draw.shading->vertexBytes(draw.mesh);
    call.indexed = draw.indexed;
    call.indices = draw.indices;
    call.pushConstants = draw.shading->uniformBytes(parametersOf(scene, draw));
    request.draws.push_back(std::move(call));
  }
  // Timed: the submission alone (clear, draws, resolve), as softraster's span is its clear, draws
  // and resolve; preparing (uploads, pipelines, recording) and reading back are not.
  auto prepared = renderer.prepare(request);
  if (!prepared) return prepared.status().prefixed("vulkan");
  const auto start = Clock::now();
  if (softraster::Status submitted = renderer.submit(*prepared); !submitted) return submitted.prefixed("vulkan");
  const double milliseconds = millisecondsSince(start);
  auto readBack = renderer.readBack(*prepared);
  if (!readBack) return readBack.status().prefixed("vulkan");
  vkref::FrameImages images = std::move(*readBack);
  Frame frame;
  frame.milliseconds = milliseconds;
  frame.width = images.width;
  frame.height = images.height;
  frame.rgba = std::move(images.rgba);
  frame.depth = std::move(images.depth);
  frame.depthFormat = scene.depthFormat;
  frame.depthStorage = std::move(images.depthStorage);
  return frame;
}

softraster::Result<std::unique_ptr<vkref::Renderer>> openVulkan(const vkref::DeviceOptions& options) {
  return vkref::Renderer::create(options);
}

}  // namespace crosscheck
