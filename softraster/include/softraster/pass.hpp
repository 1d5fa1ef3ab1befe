// Pass: a render pass's draws into one framebuffer, drawn together. With more than one thread,
// a draw on the fast path is set up when it is called (vertex shading, clipping, setup, binning)
// and its primitives are kept; the pass draws every band of every kept draw in one sweep when it
// ends (or when its kept records pass a budget, or before a draw that cannot wait), band by band
// and draw after draw. Each pixel sees its primitives in the order they were submitted, so the
// framebuffer holds the same bits as the same draws made one by one with Context::draw; what
// changes is the time: a frame of many draws visits each band once instead of once per draw
// (lavapipe, too, bins a whole render pass before it rasterizes), and the threads are not made
// to wait for each other at the end of every draw.
// A deferred draw keeps copies of its PipelineState and uniforms; its vertices and indices are
// read during the call. Anything the uniforms point to (textures) must stay alive and unchanged
// until end().
// Between begin() and end() the framebuffer belongs to the pass: clear it before begin(), read it
// (or resolve it, or make a texture of it) after end(), and draw into it only through the pass.
// A draw that is not on the fast path (the scalar method, a course method, a format the fast
// path does not blend, a shader without batches) draws the kept ones first, then itself at once.
// Errors are the draw's own and leave the pass as it was. With one thread a pass draws each draw
// at its call, as Context::draw does. The pass's slots (one per draw, of its shader's type) are
// kept from one pass to the next, so a pass that repeats the last one's draws allocates nothing.
// Deliberately absent: several framebuffers (attachments) switched inside one pass, subpasses.
#pragma once

#include <softraster/pipeline.hpp>

#include <memory>

namespace softraster {

class Pass {
 public:
  explicit Pass(const Context& context)
      : context_(context),
        recording_(context.threads() > 1 ? std::make_unique<detail::PassRecording>(*context.pool_) : nullptr) {}
  Pass(const Pass&) = delete;
  Pass& operator=(const Pass&) = delete;
  ~Pass() { end(); }

  // Starts a pass on `framebuffer` (an open pass is ended first).
  void begin(Framebuffer& framebuffer) {
    end();
    framebuffer_ = &framebuffer;
    if (recording_) recording_->start(framebuffer);
  }

  // Context::draw and Context::drawIndexed into the pass's framebuffer (Formats: as there).
  template <class Shader, DepthFormat... Formats>
  Status draw(const PipelineState& state, const typename detail::ShaderParameters<Shader>::Uniforms& uniforms,
              typename detail::ShaderParameters<Shader>::Vertices vertices) {
    if (framebuffer_ == nullptr) return notBegun();
    return context_.drawSequence<Shader, Formats...>(state, uniforms, vertices, *framebuffer_, recording_.get());
  }
  template <class Shader, DepthFormat... Formats>
  Status drawIndexed(const PipelineState& state, const typename detail::ShaderParameters<Shader>::Uniforms& uniforms,
                     typename detail::ShaderParameters<Shader>::Vertices vertices,
                     std::span<const std::uint32_t> indices) {
    if (framebuffer_ == nullptr) return notBegun();
    return context_.drawIndices<Shader, Formats...>(state, uniforms, vertices, indices, *framebuffer_,
                                                    recording_.get());
  }

  // Draws what the pass kept; the framebuffer then holds every draw. Nothing happens without an
  // open pass.
  void end() {
    if (framebuffer_ == nullptr) return;
    if (recording_) recording_->finish();
    framebuffer_ = nullptr;
  }

  bool open() const { return framebuffer_ != nullptr; }

 private:
  static Status notBegun() { return Status::error("the pass has no framebuffer: call Pass::begin first"); }

  const Context& context_;
  std::unique_ptr<detail::PassRecording> recording_;  // null with one thread: every draw is drawn at its call
  Framebuffer* framebuffer_ = nullptr;
};

}  // namespace softraster
