// vkref::Renderer on the plain Vulkan C API (1.3: dynamic rendering, synchronization2): only the
// orchestration. create() opens the device (device.cpp) and the pipeline cache (pipelines.cpp);
// prepare() checks the request, creates its images (resources.cpp), uploads its vertices,
// indices and uniform blocks into one buffer each, uploads its textures (textures.cpp), takes its
// pipelines from the cache and records its two command
// buffers: the render pass (passes.cpp) and the copies to the host (readback.cpp); submit() runs
// the first, readBack() the second and unpacks the images.
// Deliberately synchronous: every submission is waited for before the call returns, so a frame
// is never in flight between calls. Nothing is printed and nothing is global; failures come back
// as one line of text.
#include <vkref/renderer.hpp>

#include "device.hpp"
#include "passes.hpp"
#include "pipelines.hpp"
#include "readback.hpp"
#include "resources.hpp"
#include "textures.hpp"

#include <utility>

namespace vkref {

using softraster::Result;
using softraster::Status;

struct Renderer::Impl {
  std::unique_ptr<detail::Device> device;
  std::unique_ptr<detail::PipelineCache> pipelines;  // destroyed before the device
};

// What prepare() made. Members are destroyed in reverse order: the command buffers (after any
// unfinished submission) before the buffers and images they use.
struct PreparedFrame::Impl {
  const detail::Device* device = nullptr;  // of the Renderer that prepared the frame
  detail::Targets targets;
  detail::Geometry geometry;
  detail::UniformSet uniforms;
  detail::FrameTextures textures;
  detail::HostImages host;
  std::unique_ptr<detail::Commands> commands;
  bool submitted = false;
};

// ---- PreparedFrame -----------------------------------------------------------------------------

PreparedFrame::PreparedFrame() = default;
PreparedFrame::PreparedFrame(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
PreparedFrame::PreparedFrame(PreparedFrame&&) noexcept = default;
PreparedFrame& PreparedFrame::operator=(PreparedFrame&&) noexcept = default;
PreparedFrame::~PreparedFrame() = default;
std::uint32_t PreparedFrame::width() const { return impl_ ? impl_->targets.width : 0; }
std::uint32_t PreparedFrame::height() const { return impl_ ? impl_->targets.height : 0; }

// ---- Renderer ----------------------------------------------------------------------------------

Renderer::Renderer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Renderer::~Renderer() = default;

Result<std::unique_ptr<Renderer>> Renderer::create(const DeviceOptions& options) {
  auto impl = std::make_unique<Impl>();
  auto device = detail::Device::create(options);
  if (!device) return device.status();
  impl->device = std::move(*device);
  auto pipelines = detail::PipelineCache::create(*impl->device);
  if (!pipelines) return pipelines.status();
  impl->pipelines = std::move(*pipelines);
  return std::unique_ptr<Renderer>(new Renderer(std::move(impl)));
}

std::string Renderer::deviceName() const { return impl_->device->name; }
std::vector<std::string> Renderer::validationMessages() const { return impl_->device->messages(); }
std::size_t Renderer::cachedPipelines() const { return impl_->pipelines->size(); }

Result<PreparedFrame> Renderer::prepare(const FrameRequest& request) {
  const detail::Device& device = *impl_->device;
  if (Status s = detail::checkFrame(request, device); !s) return s;
  const std::uint32_t width = request.width, height = request.height;
  const std::vector<DrawCall>& draws = request.draws;
  std::vector<const DrawCall*> drawn;  // the draws not skipped, in order
  std::vector<std::size_t> numbers;    // and their indices in request.draws, for messages
  for (std::size_t i = 0; i < draws.size(); ++i) {
    if (detail::isEmpty(draws[i])) continue;
    if (Status s = detail::checkDraw(draws[i], width, height, device); !s)
      return s.prefixed("draw " + std::to_string(i));
    drawn.push_back(&draws[i]);
    numbers.push_back(i);
  }

  auto frame = std::make_unique<PreparedFrame::Impl>();
  frame->device = &device;
  const detail::TargetFormat format{
      .width = width,
      .height = height,
      .depthFormat = detail::kDepthFormats[static_cast<std::size_t>(request.depthFormat)],
      .samples = request.samples == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT};
  auto targets = detail::createTargets(device, width, height, format.depthFormat, format.samples);
  if (!targets) return targets.status();
  frame->targets = std::move(*targets);
  auto host = detail::createHostImages(device, frame->targets, request.depthFormat);
  if (!host) return host.status();
  frame->host = std::move(*host);
  auto geometry = detail::uploadGeometry(device, drawn);
  if (!geometry) return geometry.status();
  frame->geometry = std::move(*geometry);
  auto uniforms = detail::UniformSet::create(device, impl_->pipelines->uniformSetLayout(), frame->geometry);
  if (!uniforms) return uniforms.status();
  frame->uniforms = std::move(*uniforms);
  auto textures = detail::FrameTextures::create(device, impl_->pipelines->textureSetLayout(), drawn);
  if (!textures) return textures.status();
  frame->textures = std::move(*textures);

  std::vector<detail::PassDraw> passDraws(drawn.size());
  detail::PipelineCache::FrameMemo memo;
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const DrawCall& d = *drawn[i];
    auto pipeline = impl_->pipelines->get(d, format, memo);
    if (!pipeline)
      return pipeline.status().prefixed("draw " + std::to_string(numbers[i]) + " (program '" + d.program->name + "')");
    detail::PassDraw& p = passDraws[i];
    p.pipeline = *pipeline;
    p.bindVertices = !d.program->attributes.empty();
    p.vertexOffset = frame->geometry.ranges[i].vertexOffset;
    p.indexed = d.indexed;
    p.firstIndex = frame->geometry.ranges[i].firstIndex;
    p.count = d.indexed ? static_cast<std::uint32_t>(d.indices.size()) : detail::vertexCount(d);
    p.pushConstants = d.pushConstants;
    p.bindUniforms = !d.uniformData.empty();
    p.uniformOffset = frame->geometry.ranges[i].uniformOffset;
    p.textures = frame->textures.setOf(i);
  }

  auto commands = detail::Commands::create(device);
  if (!commands) return commands.status();
  frame->commands = std::move(*commands);
  const detail::FramePass pass{.targets = &frame->targets,
                               .clearColour = request.clearColour,
                               .clearDepth = request.clearDepth,
                               .layout = impl_->pipelines->layout(),
                               .vertices = frame->geometry.vertices.handle(),
                               .indices = frame->geometry.indices.handle(),
                               .uniforms = frame->uniforms.handle(),
                               .draws = passDraws};
  if (Status s = detail::recordRenderPass(frame->commands->render(), pass); !s) return s;
  if (Status s = detail::recordCopies(frame->commands->copy(), frame->targets, frame->host); !s) return s;
  return PreparedFrame(std::move(frame));
}

Status Renderer::submit(PreparedFrame& frame) {
  if (!frame.impl_) return Status::error("submit: the frame is empty (not prepared, or moved from)");
  if (frame.impl_->device != impl_->device.get())
    return Status::error("submit: the frame was prepared by another Renderer");
  if (Status s = frame.impl_->commands->submitAndWait(frame.impl_->commands->render()); !s) return s;
  frame.impl_->submitted = true;
  return {};
}

Result<FrameImages> Renderer::readBack(const PreparedFrame& frame) {
  if (!frame.impl_) return Status::error("readBack: the frame is empty (not prepared, or moved from)");
  const PreparedFrame::Impl& f = *frame.impl_;
  if (f.device != impl_->device.get()) return Status::error("readBack: the frame was prepared by another Renderer");
  if (!f.submitted) return Status::error("readBack: the frame has not been submitted");
  if (Status s = f.commands->submitAndWait(f.commands->copy()); !s) return s;
  return detail::unpack(f.host, f.targets.width, f.targets.height);
}

Result<FrameImages> Renderer::render(const FrameRequest& request) {
  auto frame = prepare(request);
  if (!frame) return frame.status();
  if (Status s = submit(*frame); !s) return s;
  return readBack(*frame);
}

}  // namespace vkref
