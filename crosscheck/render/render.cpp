// Scene -> softraster and Scene -> vkref adapters, one frame or prepared for many (see render.hpp). Both draw every Draw through
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

SoftrasterScene::SoftrasterScene(const Scene& scene, const softraster::ContextOptions& options)
    : scene_(scene),
      options_(options),
      context_(options) {
  softraster::Result<softraster::Framebuffer> framebuffer =
      softraster::Framebuffer::create(scene.width, scene.height, scene.depthFormat, scene.samples);
  if (framebuffer) {
    framebuffer_ = std::move(*framebuffer);
  } else {
    framebufferStatus_ = framebuffer.status().prefixed("softraster");
  }
  draws_.reserve(scene.draws.size());  // each draw's vertices and uniforms in its model's types
  for (const Draw& draw : scene.draws) draws_.push_back(draw.shading->prepareSoftraster(draw.mesh, drawParameters(scene, draw)));
}

softraster::Status SoftrasterScene::render() {
  if (!framebufferStatus_) return framebufferStatus_;
  // Timed: clear, draws, MSAA resolve (not the framebuffer's allocation, not the Frame).
  const auto start = Clock::now();
  // The 1/z buffer is cleared to 0 (infinitely far); it is not a Vulkan mode.
  framebuffer_.clear(scene_.clearColour,
                     options_.depthMode == softraster::DepthMode::InverseZ ? 0.0f : scene_.clearDepth);
  for (std::size_t i = 0; i < scene_.draws.size(); ++i) {
    const Draw& draw = scene_.draws[i];
    const softraster::Status status = draws_[i].draw(context_, draw.state, draw.indexed, draw.indices, framebuffer_);
    if (!status) return status.prefixed("softraster: draw '" + draw.name + "'");
  }
  if (scene_.samples > 1) framebuffer_.resolveInto(resolved_);  // as vkref reads Vulkan's back
  milliseconds_ = millisecondsSince(start);
  return {};
}

namespace {

Frame frameFrom(const Scene& scene, softraster::Framebuffer& framebuffer, double milliseconds, bool move) {
  Frame frame;
  frame.milliseconds = milliseconds;
  frame.width = scene.width;
  frame.height = scene.height;
  frame.depthFormat = scene.depthFormat;
  frame.depth.resize(framebuffer.depthStorage().size());
  for (std::size_t i = 0; i < frame.depth.size(); ++i) frame.depth[i] = framebuffer.depth(i);
  if (move) {
    frame.rgba = std::move(framebuffer.colour());
    frame.depthStorage = std::move(framebuffer.depthStorage());
  } else {
    frame.rgba = framebuffer.colour();
    frame.depthStorage = framebuffer.depthStorage();
  }
  return frame;
}

}  // namespace

Frame SoftrasterScene::frame() const {
  softraster::Framebuffer copy = scene_.samples > 1 ? resolved_ : framebuffer_;
  return frameFrom(scene_, copy, milliseconds_, true);
}

Frame SoftrasterScene::takeFrame() { return frameFrom(scene_, output(), milliseconds_, true); }

softraster::Result<Frame> renderSoftraster(const Scene& scene, const softraster::ContextOptions& options) {
  SoftrasterScene prepared(scene, options);
  if (const softraster::Status status = prepared.render(); !status) return status;
  return prepared.takeFrame();
}

softraster::Result<softraster::Framebuffer> renderSoftrasterSamples(const Scene& scene,
                                                                   const softraster::ContextOptions& options) {
  SoftrasterScene prepared(scene, options);
  if (const softraster::Status status = prepared.render(); !status) return status;
  return prepared.samples();
}

softraster::Result<vkref::PreparedFrame> prepareVulkan(const Scene& scene, vkref::Renderer& renderer) {
  std::vector<vkref::ShaderProgram> programs;  // one per draw, alive until the frame is prepared
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
    (draw.shading->uniformBuffer ? call.uniformData : call.pushConstants) =
        draw.shading->uniformBytes(drawParameters(scene, draw));
    for (const Draw::Texture& t : draw.textures) call.textures.push_back({t.texture.get(), t.sampler});
    request.draws.push_back(std::move(call));
  }
  auto prepared = renderer.prepare(request);
  if (!prepared) return prepared.status().prefixed("vulkan");
  return std::move(*prepared);
}

softraster::Result<Frame> readVulkan(const Scene& scene, vkref::Renderer& renderer, const vkref::PreparedFrame& prepared) {
  auto readBack = renderer.readBack(prepared);
  if (!readBack) return readBack.status().prefixed("vulkan");
  vkref::FrameImages images = std::move(*readBack);
  Frame frame;
  frame.width = images.width;
  frame.height = images.height;
  frame.rgba = std::move(images.rgba);
  frame.depth = std::move(images.depth);
  frame.depthFormat = scene.depthFormat;
  frame.depthStorage = std::move(images.depthStorage);
  return frame;
}

softraster::Result<Frame> renderVulkan(const Scene& scene, vkref::Renderer& renderer) {
  // Timed: the submission alone (clear, draws, resolve), as softraster's span is its clear, draws
  // and resolve; preparing (uploads, pipelines, recording) and reading back are not.
  auto prepared = prepareVulkan(scene, renderer);
  if (!prepared) return prepared.status();
  const auto start = Clock::now();
  if (softraster::Status submitted = renderer.submit(*prepared); !submitted) return submitted.prefixed("vulkan");
  const double milliseconds = millisecondsSince(start);
  auto frame = readVulkan(scene, renderer, *prepared);
  if (frame) frame->milliseconds = milliseconds;
  return frame;
}

softraster::Result<std::unique_ptr<vkref::Renderer>> openVulkan(const vkref::DeviceOptions& options) {
  return vkref::Renderer::create(options);
}

}  // namespace crosscheck
