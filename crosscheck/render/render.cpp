// Scene -> softraster and Scene -> vkref adapters, one frame or prepared for many (see render.hpp). Both draw every Draw through
// its row of the shading-model table (shaders/shading_models.hpp); neither knows a model by name.
#include "render/render.hpp"

#include <softraster/pass.hpp>
#include <softraster/pipeline.hpp>

#include <shading_models.hpp>

#include <chrono>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace crosscheck {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A shading model's compiled SPIR-V pair and the vertex layout of its C++ twin, for vkref.
// A depth pass's state for one of its draws: the draw's topology, polygon mode and line width,
// the pass's cull, front face, depth bias and depth test, the whole pass as viewport and scissor,
// and no colour written.
softraster::PipelineState passState(const DepthPass& pass, const Draw& draw) {
  softraster::PipelineState state = pass.state;
  state.topology = draw.state.topology;
  state.rasterization.polygonMode = draw.state.rasterization.polygonMode;
  state.rasterization.lineWidth = draw.state.rasterization.lineWidth;
  state.rasterization.lineRasterization = draw.state.rasterization.lineRasterization;
  state.blend.colorWriteMask = 0;
  return state;
}

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
      context_(options),
      pass_(context_) {
  std::vector<softraster::ColourFormat> formats{scene.colourFormat};
  for (const SceneColourAttachment& more : scene.moreColour) formats.push_back(more.format);
  softraster::Result<softraster::Framebuffer> framebuffer =
      softraster::Framebuffer::create(scene.width, scene.height, scene.depthFormat, scene.samples, formats);
  if (framebuffer) {
    framebuffer_ = std::move(*framebuffer);
  } else {
    framebufferStatus_ = framebuffer.status().prefixed("softraster");
  }
  for (const DepthPass& pass : scene.passes) {
    Pass& p = passes_.emplace_back();
    softraster::Result<softraster::Framebuffer> target =
        softraster::Framebuffer::create(pass.width, pass.height, softraster::DepthFormat::D32Sfloat, 1);
    if (target) {
      p.framebuffer = std::move(*target);
    } else if (framebufferStatus_) {
      framebufferStatus_ = target.status().prefixed("softraster: pass '" + pass.name + "'");
    }
    p.depth = std::make_unique<softraster::Texture>();
    for (std::size_t i : pass.draws) {
      const Draw& draw = scene.draws[i];
      p.draws.push_back(pass.shading->prepareSoftraster(draw.mesh, passDrawParameters(pass, draw)));
      p.states.push_back(passState(pass, draw));
    }
  }
  draws_.reserve(scene.draws.size());  // each draw's vertices and uniforms in its model's types
  for (const Draw& draw : scene.draws) {
    shaders::DrawParameters parameters = drawParameters(scene, draw);
    for (std::size_t t = 0; t < draw.textures.size() && t < parameters.textures.size(); ++t) {
      if (draw.textures[t].pass >= 0) parameters.textures[t].texture = passes_[static_cast<std::size_t>(draw.textures[t].pass)].depth.get();
    }
    draws_.push_back(draw.shading->prepareSoftraster(draw.mesh, parameters));
  }
}

softraster::Status SoftrasterScene::render() {
  if (!framebufferStatus_) return framebufferStatus_;
  // Timed: clear, draws, MSAA resolve (not the framebuffer's allocation, not the Frame).
  const auto start = Clock::now();
  for (std::size_t k = 0; k < passes_.size(); ++k) {  // each depth pass, then its depth as a texture
    const DepthPass& pass = scene_.passes[k];
    Pass& p = passes_[k];
    p.framebuffer.clear({0, 0, 0, 0}, pass.clearDepth);
    pass_.begin(p.framebuffer);
    for (std::size_t i = 0; i < p.draws.size(); ++i) {
      const Draw& draw = scene_.draws[pass.draws[i]];
      const softraster::Status status = p.draws[i].draw(pass_, p.states[i], draw.indexed, draw.indices);
      if (!status) return status.prefixed("softraster: pass '" + pass.name + "': draw '" + draw.name + "'");
    }
    pass_.end();
    softraster::Result<softraster::Texture> depth = softraster::Texture::fromDepth(p.framebuffer);
    if (!depth) return depth.status().prefixed("softraster: pass '" + pass.name + "'");
    *p.depth = std::move(*depth);
  }
  // The 1/z buffer is cleared to 0 (infinitely far); it is not a Vulkan mode.
  clearColours_.assign(1, scene_.clearColour);
  for (const SceneColourAttachment& more : scene_.moreColour) clearColours_.push_back(more.clearColour);
  framebuffer_.clear(clearColours_, options_.depthMode == softraster::DepthMode::InverseZ ? 0.0f : scene_.clearDepth,
                     scene_.clearStencil);
  pass_.begin(framebuffer_);
  for (std::size_t i = 0; i < scene_.draws.size(); ++i) {
    const Draw& draw = scene_.draws[i];
    const softraster::Status status = draws_[i].draw(pass_, draw.state, draw.indexed, draw.indices);
    if (!status) return status.prefixed("softraster: draw '" + draw.name + "'");
  }
  pass_.end();
  if (scene_.samples > 1) context_.resolveInto(framebuffer_, resolved_);  // as vkref reads Vulkan's back
  milliseconds_ = millisecondsSince(start);
  return {};
}

namespace {

// A Frame's colour is R, G, B, A bytes, as vkref reads it back: `bytes` (a copy of an
// attachment's storage in `format`) turned into that, B8G8R8A8's red and blue swapped back; a
// wider format keeps its texels in `words` and the bytes become their view.
void colourImage(softraster::ColourFormat format, std::vector<std::uint8_t>& bytes, std::vector<std::uint32_t>& words) {
  if (softraster::swapsRedBlue(format)) {
    for (std::size_t i = 0; i + 3 < bytes.size(); i += 4) std::swap(bytes[i], bytes[i + 2]);
  }
  // An empty image (no samples in a single-sample frame) has no data() to copy from.
  if (bytes.empty() || (!softraster::isTenBit(format) && !softraster::isFloat(format))) return;
  const std::size_t texelBytes = softraster::colourBytes(format), texels = bytes.size() / texelBytes;
  words.resize(bytes.size() / 4);
  std::memcpy(words.data(), bytes.data(), bytes.size());
  bytes.resize(4 * texels);
  const auto* stored = reinterpret_cast<const std::uint8_t*>(words.data());
  for (std::size_t i = 0; i < texels; ++i) {
    const auto view = softraster::Framebuffer::viewBytes(format, stored + texelBytes * i);
    std::memcpy(bytes.data() + 4 * i, view.data(), 4);
  }
}

// `samples`: the framebuffer before the resolve (with MSAA), whose every sample the frame also
// carries (copied: the next render() draws into it again).
Frame frameFrom(const Scene& scene, softraster::Framebuffer& framebuffer, const softraster::Framebuffer* samples,
                double milliseconds, bool move) {
  Frame frame;
  if (samples) {
    frame.samples = samples->samples();
    frame.sampleRgba = samples->colour();
    frame.sampleDepthStorage = samples->depthStorage();
    frame.sampleStencil = samples->stencilStorage();
  }
  frame.milliseconds = milliseconds;
  frame.width = scene.width;
  frame.height = scene.height;
  frame.depthFormat = scene.depthFormat;
  frame.depth.resize(framebuffer.depthStorage().size());
  for (std::size_t i = 0; i < frame.depth.size(); ++i) frame.depth[i] = framebuffer.depth(i);
  if (move) {
    frame.rgba = std::move(framebuffer.colour());
    frame.depthStorage = std::move(framebuffer.depthStorage());
    frame.stencil = std::move(framebuffer.stencilStorage());
  } else {
    frame.rgba = framebuffer.colour();
    frame.depthStorage = framebuffer.depthStorage();
    frame.stencil = framebuffer.stencilStorage();
  }
  frame.colourFormat = framebuffer.colourFormat();
  colourImage(frame.colourFormat, frame.rgba, frame.colourWords);
  colourImage(frame.colourFormat, frame.sampleRgba, frame.sampleColourWords);
  for (std::uint32_t a = 1; a < framebuffer.colourAttachments(); ++a) {
    ColourImage& more = frame.moreColour.emplace_back();
    more.colourFormat = framebuffer.colourFormat(a);
    more.rgba = move ? std::move(framebuffer.colour(a)) : framebuffer.colour(a);
    if (samples) more.sampleRgba = samples->colour(a);
    colourImage(more.colourFormat, more.rgba, more.colourWords);
    colourImage(more.colourFormat, more.sampleRgba, more.sampleColourWords);
  }
  return frame;
}

}  // namespace

Frame SoftrasterScene::frame() const {
  softraster::Framebuffer copy = scene_.samples > 1 ? resolved_ : framebuffer_;
  return frameFrom(scene_, copy, scene_.samples > 1 ? &framebuffer_ : nullptr, milliseconds_, true);
}

Frame SoftrasterScene::takeFrame() {
  return frameFrom(scene_, output(), scene_.samples > 1 ? &framebuffer_ : nullptr, milliseconds_, true);
}

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
  std::vector<vkref::ShaderProgram> programs;  // one per draw, alive until the frame is prepared (never reallocated)
  vkref::FrameRequest request;
  request.width = scene.width;
  request.height = scene.height;
  request.clearColour = {scene.clearColour.x, scene.clearColour.y, scene.clearColour.z, scene.clearColour.w};
  request.clearDepth = scene.clearDepth;
  request.clearStencil = scene.clearStencil;
  request.colourFormat = scene.colourFormat;
  for (const SceneColourAttachment& more : scene.moreColour) {
    request.moreColour.push_back(
        {more.format, {more.clearColour.x, more.clearColour.y, more.clearColour.z, more.clearColour.w}});
  }
  request.depthFormat = scene.depthFormat;
  request.samples = scene.samples;
  std::size_t passDraws = 0;
  for (const DepthPass& pass : scene.passes) passDraws += pass.draws.size();
  programs.reserve(scene.draws.size() + passDraws);
  for (const DepthPass& pass : scene.passes) {
    vkref::DepthPass& passRequest = request.depthPasses.emplace_back();
    passRequest.width = pass.width;
    passRequest.height = pass.height;
    passRequest.clearDepth = pass.clearDepth;
    for (std::size_t i : pass.draws) {
      const Draw& draw = scene.draws[i];
      vkref::DrawCall call;
      call.program = &programs.emplace_back(programOf(*pass.shading));
      call.state = passState(pass, draw);
      call.vertexData = pass.shading->vertexBytes(draw.mesh);
      call.indexed = draw.indexed;
      call.indices = draw.indices;
      (pass.shading->uniformBuffer ? call.uniformData : call.pushConstants) =
          pass.shading->uniformBytes(passDrawParameters(pass, draw));
      passRequest.draws.push_back(std::move(call));
    }
  }
  for (const Draw& draw : scene.draws) {
    vkref::DrawCall call;
    call.program = &programs.emplace_back(programOf(*draw.shading));
    call.state = draw.state;
    call.vertexData = draw.shading->vertexBytes(draw.mesh);
    call.indexed = draw.indexed;
    call.indices = draw.indices;
    (draw.shading->uniformBuffer ? call.uniformData : call.pushConstants) =
        draw.shading->uniformBytes(drawParameters(scene, draw));
    for (const Draw::Texture& t : draw.textures) call.textures.push_back({t.texture.get(), t.sampler, t.pass});
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
  frame.colourFormat = scene.colourFormat;
  frame.colourWords = std::move(images.colourWords);
  frame.depth = std::move(images.depth);
  frame.depthFormat = scene.depthFormat;
  frame.depthStorage = std::move(images.depthStorage);
  frame.stencil = std::move(images.stencil);
  frame.samples = images.samples;
  frame.sampleRgba = std::move(images.sampleRgba);
  frame.sampleColourWords = std::move(images.sampleColourWords);
  frame.sampleDepthStorage = std::move(images.sampleDepthStorage);
  frame.sampleStencil = std::move(images.sampleStencil);
  for (std::size_t a = 0; a < images.moreColour.size() && a < scene.moreColour.size(); ++a) {
    vkref::ColourImages& read = images.moreColour[a];
    ColourImage& more = frame.moreColour.emplace_back();
    more.colourFormat = scene.moreColour[a].format;
    more.rgba = std::move(read.rgba);
    more.colourWords = std::move(read.colourWords);
    more.sampleRgba = std::move(read.sampleRgba);
    more.sampleColourWords = std::move(read.sampleColourWords);
  }
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
