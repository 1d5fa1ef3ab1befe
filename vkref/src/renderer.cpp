// vkref::Renderer on the plain Vulkan C API (1.3: dynamic rendering, synchronization2): only the
// orchestration. create() opens the device (device.cpp) and the pipeline cache (pipelines.cpp);
// prepare() checks the request, creates its images (each colour attachment's and depth's:
// resources.cpp), uploads its vertices, indices and uniform blocks into one buffer each, uploads
// its textures (textures.cpp), takes its pipelines from the cache and records its two command
// buffers: the render pass with any depth passes before it (passes.cpp) and the copies to the
// host (readback.cpp), with MSAA also the per-sample read-back (samples.cpp); submit() runs
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
#include "samples.hpp"
#include "textures.hpp"

#include <span>
#include <utility>
#include <vector>

namespace vkref {

using softraster::Result;
using softraster::Status;

struct Renderer::Impl {
  std::unique_ptr<detail::Device> device;
  std::unique_ptr<detail::PipelineCache> pipelines;  // destroyed before the device
  std::unique_ptr<detail::SampleReader> sampleReader;  // made with the first multisampled frame
};

// What prepare() made. Members are destroyed in reverse order: the command buffers (after any
// unfinished submission) before the buffers and images they use.
struct PreparedFrame::Impl {
  const detail::Device* device = nullptr;  // of the Renderer that prepared the frame
  detail::Targets targets;
  std::vector<detail::Image> depthPassImages;  // one per FrameRequest::depthPasses, D32_SFLOAT, sampled later
  detail::Geometry geometry;
  detail::UniformSet uniforms;
  detail::FrameTextures textures;
  detail::HostImages host;
  std::unique_ptr<detail::FrameSamples> samples;  // with MSAA: every sample's read-back
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
  // Every draw not skipped, in recording order: each depth pass's, then the frame's own; with
  // where each pass's run begins, and names for messages.
  std::vector<const DrawCall*> drawn;
  std::vector<std::string> names;
  std::vector<std::size_t> passBegin;
  const std::size_t passes = request.depthPasses.size();
  constexpr VkFormat kShadowFormat = VK_FORMAT_D32_SFLOAT;
  for (std::size_t k = 0; k < passes; ++k) {
    const DepthPass& pass = request.depthPasses[k];
    const std::string passName = "depth pass " + std::to_string(k);
    if (pass.width == 0 || pass.height == 0 || pass.width > device.limits.maxFramebufferWidth ||
        pass.height > device.limits.maxFramebufferHeight || pass.width > device.limits.maxImageDimension2D ||
        pass.height > device.limits.maxImageDimension2D)
      return Status::error(passName + ": size " + std::to_string(pass.width) + "x" + std::to_string(pass.height) +
                           " out of range");
    if (!(pass.clearDepth >= 0 && pass.clearDepth <= 1)) return Status::error(passName + ": clearDepth outside [0, 1]");
    passBegin.push_back(drawn.size());
    for (std::size_t i = 0; i < pass.draws.size(); ++i) {
      const DrawCall& d = pass.draws[i];
      if (detail::isEmpty(d)) continue;
      const std::string name = passName + " draw " + std::to_string(i);
      if (!d.textures.empty()) return Status::error(name + ": a depth pass's draws sample nothing");
      if (Status s = detail::checkDraw(d, pass.width, pass.height, 0, device); !s) return s.prefixed(name);
      drawn.push_back(&d);
      names.push_back(name);
    }
  }
  const auto colourCount = static_cast<std::uint32_t>(1 + request.moreColour.size());  // checked by checkFrame
  const std::size_t firstOwn = drawn.size();
  passBegin.push_back(firstOwn);
  for (std::size_t i = 0; i < request.draws.size(); ++i) {
    const DrawCall& d = request.draws[i];
    if (detail::isEmpty(d)) continue;
    const std::string name = "draw " + std::to_string(i);
    for (std::size_t t = 0; t < d.textures.size(); ++t) {
      const int pass = d.textures[t].depthPass;
      if (pass >= 0 && static_cast<std::size_t>(pass) >= passes)
        return Status::error(name + ": texture " + std::to_string(t) + " names depth pass " + std::to_string(pass) +
                             " of " + std::to_string(passes));
      if (pass >= 0 && d.textures[t].texture != nullptr)
        return Status::error(name + ": texture " + std::to_string(t) + " names a depth pass and a texture");
    }
    if (Status s = detail::checkDraw(d, width, height, colourCount, device); !s) return s.prefixed(name);
    drawn.push_back(&d);
    names.push_back(name);
  }

  auto frame = std::make_unique<PreparedFrame::Impl>();
  frame->device = &device;
  detail::TargetFormat format{
      .width = width,
      .height = height,
      .colourCount = colourCount,
      .colourFormats = {detail::kColourFormats[static_cast<std::size_t>(request.colourFormat)]},
      .depthFormat = detail::kDepthFormats[static_cast<std::size_t>(request.depthFormat)],
      .samples = request.samples == 4 ? VK_SAMPLE_COUNT_4_BIT : VK_SAMPLE_COUNT_1_BIT};
  std::vector<softraster::ColourFormat> moreColourFormats;
  for (std::size_t i = 0; i < request.moreColour.size(); ++i) {
    moreColourFormats.push_back(request.moreColour[i].format);
    format.colourFormats[i + 1] = detail::kColourFormats[static_cast<std::size_t>(request.moreColour[i].format)];
  }
  auto targets = detail::createTargets(device, width, height, format.colourFormats[0],
                                       std::span(format.colourFormats).subspan(1, colourCount - 1), format.depthFormat,
                                       format.samples);
  if (!targets) return targets.status();
  frame->targets = std::move(*targets);
  std::vector<VkImageView> passViews;
  for (const DepthPass& pass : request.depthPasses) {
    auto image = detail::Image::create(device, kShadowFormat,
                                       VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                       VK_IMAGE_ASPECT_DEPTH_BIT, pass.width, pass.height, VK_SAMPLE_COUNT_1_BIT);
    if (!image) return image.status().prefixed("depth pass");
    passViews.push_back(image->view());
    frame->depthPassImages.push_back(std::move(*image));
  }
  auto host =
      detail::createHostImages(device, frame->targets, request.colourFormat, moreColourFormats, request.depthFormat);
  if (!host) return host.status();
  frame->host = std::move(*host);
  if (frame->targets.multisampled()) {
    if (!impl_->sampleReader) {
      auto reader = detail::SampleReader::create(device);
      if (!reader) return reader.status().prefixed("per-sample read-back");
      impl_->sampleReader = std::move(*reader);
    }
    auto samples = detail::FrameSamples::create(device, *impl_->sampleReader, frame->targets);
    if (!samples) return samples.status().prefixed("per-sample read-back");
    frame->samples = std::move(*samples);
  }
  auto geometry = detail::uploadGeometry(device, drawn);
  if (!geometry) return geometry.status();
  frame->geometry = std::move(*geometry);
  auto uniforms = detail::UniformSet::create(device, impl_->pipelines->uniformSetLayout(), frame->geometry);
  if (!uniforms) return uniforms.status();
  frame->uniforms = std::move(*uniforms);
  auto textures = detail::FrameTextures::create(device, impl_->pipelines->textureSetLayout(), drawn, passViews);
  if (!textures) return textures.status();
  frame->textures = std::move(*textures);

  std::vector<detail::PassDraw> passDraws(drawn.size());
  detail::PipelineCache::FrameMemo memo;
  std::size_t pass = 0;  // the depth pass drawn[i] belongs to, while i < firstOwn
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    const DrawCall& d = *drawn[i];
    while (pass < passes && i >= passBegin[pass + 1]) ++pass;
    detail::TargetFormat target = format;
    if (i < firstOwn) {
      const DepthPass& p = request.depthPasses[pass];
      target = {.width = p.width, .height = p.height, .colourCount = 0, .colourFormats = {},
                .depthFormat = kShadowFormat, .samples = VK_SAMPLE_COUNT_1_BIT};
    }
    auto pipeline = impl_->pipelines->get(d, target, memo);
    if (!pipeline) return pipeline.status().prefixed(names[i] + " (program '" + d.program->name + "')");
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
  std::vector<detail::DepthPassRecord> passRecords;
  for (std::size_t k = 0; k < passes; ++k) {
    const DepthPass& p = request.depthPasses[k];
    passRecords.push_back({.image = frame->depthPassImages[k].handle(),
                           .view = frame->depthPassImages[k].view(),
                           .width = p.width,
                           .height = p.height,
                           .clearDepth = p.clearDepth,
                           .draws = std::span(passDraws).subspan(passBegin[k], passBegin[k + 1] - passBegin[k])});
  }

  auto commands = detail::Commands::create(device);
  if (!commands) return commands.status();
  frame->commands = std::move(*commands);
  const detail::FramePass framePass{.targets = &frame->targets,
                                    .clearColour = request.clearColour,
                                    .moreColour = request.moreColour,
                                    .clearDepth = request.clearDepth,
                                    .clearStencil = request.clearStencil,
                                    .layout = impl_->pipelines->layout(),
                                    .vertices = frame->geometry.vertices.handle(),
                                    .indices = frame->geometry.indices.handle(),
                                    .uniforms = frame->uniforms.handle(),
                                    .draws = std::span(passDraws).subspan(firstOwn),
                                    .depthPasses = passRecords};
  if (Status s = detail::recordRenderPass(frame->commands->render(), framePass); !s) return s;
  if (Status s = detail::recordCopies(frame->commands->copy(), frame->targets, frame->host, frame->samples.get()); !s) return s;
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
  FrameImages images = detail::unpack(f.host, f.targets.width, f.targets.height);
  if (f.samples) {
    if (Status s = f.samples->unpack(images, f.host.colourFormat, f.host.moreColourFormats, f.host.depthFormat); !s)
      return s;
  }
  return images;
}

Result<FrameImages> Renderer::render(const FrameRequest& request) {
  auto frame = prepare(request);
  if (!frame) return frame.status();
  if (Status s = submit(*frame); !s) return s;
  return readBack(*frame);
}

}  // namespace vkref
