// softraster's entry point: a Context draws points, lines and triangles (lists, strips, fans, the
// adjacency topologies with their adjacent vertices skipped), indexed or not, with primitive
// restart on strips and fans, with a shader type into a Framebuffer, following lavapipe's rules
// to the bit (the "exact" method). A draw is validated as a whole before any work, then handed to the
// method's draw loop (detail/exact/draw.hpp: the stages, in order), instantiated for the
// framebuffer's depth format, for how fmuladd rounds and for the fragment stage: the SIMD fast
// path (detail/fast/) where options.hpp's Method::Exact allows it, else the scalar one.
// Coverage: polygon modes fill, line and point (lavapipe's draw-pipeline path: in point mode x
// and y are clipped at 2w, measured); 4x MSAA for every primitive and polygon mode
// (Framebuffer::resolve() resolves as lavapipe does; Bresenham lines with multisampling off, as
// lavapipe draws them); depth bias for filled triangles and for polygon modes line and point
// (Mesa's offset stage: geometry/polygon_offset.hpp); the course's 1/z depth buffer;
// blending with every core factor and op, blend constants and the colour write mask; the stencil
// test with front and back state on the D24_UNORM_S8_UINT and D32_SFLOAT_S8_UINT formats; stippled
// lines and provoking vertex last (VK_EXT_line_rasterization, VK_EXT_provoking_vertex); negative
// viewport heights; the sample mask, alpha to coverage and alpha to one (fragment/coverage.hpp);
// up to kMaxColourAttachments colour attachments, each of its own format and blend state, filled
// by a shader's colour outputs (ColourOutputs, shader.hpp; drawn on the scalar path).
// Where lavapipe deviates from the spec, ContextOptions::deviations chooses.
// Conventions are Vulkan's: clip space x right, y down, z in [0, w]; window origin at the top
// left, pixel centres at +0.5; front faces counter-clockwise as seen in the image by default;
// docs/library.md has them all, with the 4x sample positions.
// A Context holds no global state and reports errors through Status; it never prints. It owns
// its threads (ContextOptions::threads). Threads: a Context may be shared (its draws are const;
// draws from several threads take turns where they use the Context's threads), but one Context
// per thread, each with its own Framebuffer, avoids that wait; a Framebuffer must not be drawn
// into or read from two threads at once. A steady-state draw allocates nothing: its vectors are
// the Context's scratch (detail/exact/scratch.hpp). A Pass (pass.hpp) keeps a render pass's
// draws and draws them together, band by band (the same bits, fewer trips over the framebuffer).
// Exactness needs every float operation rounded on its own: the installed target passes
// -ffp-contract=off to its users (CMake and pkg-config); under Clang the library's own code is
// also compiled with `#pragma clang fp contract(off)`, whatever the flags.
// The course's rasterization methods (Method::Scanline, Trapezoid, Barycentric: options.hpp,
// detail/course/) take the same loop with their own triangle setup, coverage and interpolation.
// A shader that samples textures (texture.hpp, kQuads) is shaded in 2x2 quads on both exact
// paths, so its derivatives are lavapipe's.
// Deliberately absent: dual-source blending, the 1/z depth buffer with 4x MSAA.
#pragma once

#if defined(__clang__)
#pragma float_control(push)
#pragma clang fp contract(off)
#endif

#include <softraster/detail/exact/draw.hpp>
#include <softraster/detail/exact/scratch.hpp>
#include <softraster/detail/fast/fragments.hpp>
#include <softraster/detail/geometry/largest_index.hpp>
#include <softraster/detail/instruction_set.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/limits.hpp>
#include <softraster/options.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>
#include <softraster/status.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace softraster {

class Pass;  // pass.hpp

class Context {
 public:
  explicit Context(ContextOptions options = {})
      : options_(options),
        pool_(std::make_unique<detail::ThreadPool>(
            options.threads != 0 ? options.threads : std::max(1u, std::thread::hardware_concurrency()))),
        scratch_(std::make_unique<detail::ScratchPool>()) {}

  const ContextOptions& options() const { return options_; }
  // Threads drawing, the caller's included (options().threads, or the core count for 0).
  unsigned threads() const { return pool_->threads(); }

  // Framebuffer::resolveInto on this context's threads, rows shared out among them (the same
  // bytes whatever the thread count): `multisampled`'s resolve into `out`. Not thread-safe
  // against a draw into either framebuffer.
  void resolveInto(const Framebuffer& multisampled, Framebuffer& out) const {
    if (&out == &multisampled || multisampled.samples() == 1 || pool_->threads() == 1) {
      multisampled.resolveInto(out);
      return;
    }
    multisampled.prepareResolve(out);
    struct Rows {
      const Framebuffer& in;
      Framebuffer& out;
      std::uint32_t height;
    } rows{multisampled, out, multisampled.height()};
    // One reference captured: the task fits std::function's own storage (no allocation).
    pool_->run((rows.height + kResolveRows - 1) / kResolveRows, [&rows](std::size_t k) {
      const auto y0 = static_cast<std::uint32_t>(k) * kResolveRows;
      rows.in.resolveRows(rows.out, y0, std::min(rows.height - 1, y0 + kResolveRows - 1));
    });
  }

  // vkCmdDraw: vertices 0..n-1 in order, assembled by state.topology. Shader must meet
  // ShaderInterface (shader.hpp); a type that does not fails to compile here with one message.
  // Formats: the depth formats this call is compiled for, none meaning all three. The pipeline
  // is instantiated per format, so naming the one a program uses (draw<S, DepthFormat::D32Sfloat>)
  // compiles a third of the code; a framebuffer of another format is then an error. A
  // depth/stencil format is drawn by its depth aspect's instantiation (formats.hpp: naming
  // D32Sfloat or D32SfloatS8Uint compiles the same code and draws both).
  template <class Shader, DepthFormat... Formats>
  Status draw(const PipelineState& state, const typename detail::ShaderParameters<Shader>::Uniforms& uniforms,
              typename detail::ShaderParameters<Shader>::Vertices vertices, Framebuffer& framebuffer) const {
    return drawSequence<Shader, Formats...>(state, uniforms, vertices, framebuffer, nullptr);
  }

  // vkCmdDrawIndexed. An index past the end of `vertices` is an error and nothing is drawn.
  // Indices that do not complete a primitive are ignored, as Vulkan does. Formats: as for draw.
  template <class Shader, DepthFormat... Formats>
  Status drawIndexed(const PipelineState& state, const typename detail::ShaderParameters<Shader>::Uniforms& uniforms,
                     typename detail::ShaderParameters<Shader>::Vertices vertices,
                     std::span<const std::uint32_t> indices, Framebuffer& framebuffer) const {
    return drawIndices<Shader, Formats...>(state, uniforms, vertices, indices, framebuffer, nullptr);
  }

 private:
  friend class Pass;
  static constexpr std::uint32_t kResolveRows = 32;  // rows per task of resolveInto

  // draw(), deferred into `pass` where it can be (fast/deferred_draws.hpp; nullptr: not).
  template <class Shader, DepthFormat... Formats>
  Status drawSequence(const PipelineState& state, const typename detail::ShaderParameters<Shader>::Uniforms& uniforms,
                      typename detail::ShaderParameters<Shader>::Vertices vertices, Framebuffer& framebuffer,
                      detail::PassRecording* pass) const {
    if constexpr (!checkShaderInterface<Shader>()) {
      return Status::error("not a shader");  // unreachable: checkShaderInterface has failed the build
    } else {
      const detail::ScratchPool::Lease scratch = scratch_->lease();
      std::vector<std::uint32_t>& sequence = (*scratch).vector<std::uint32_t>(detail::ScratchSlot::IndexSequence);
      sequence.resize(vertices.size());
      for (std::size_t i = 0; i < sequence.size(); ++i) sequence[i] = static_cast<std::uint32_t>(i);
      return drawPrimitives<Shader, Formats...>(state, uniforms, vertices, sequence, framebuffer, *scratch, pass);
    }
  }

  // drawIndexed(), deferred into `pass` where it can be.
  template <class Shader, DepthFormat... Formats>
  Status drawIndices(const PipelineState& state, const typename detail::ShaderParameters<Shader>::Uniforms& uniforms,
                     typename detail::ShaderParameters<Shader>::Vertices vertices,
                     std::span<const std::uint32_t> indices, Framebuffer& framebuffer,
                     detail::PassRecording* pass) const {
    if constexpr (!checkShaderInterface<Shader>()) {
      return Status::error("not a shader");  // unreachable: checkShaderInterface has failed the build
    } else {
      // The largest index first (detail/geometry/largest_index.hpp; a restart index counts as 0),
      // the offending one only on failure.
      const bool restart = state.primitiveRestartEnable;
      const auto outOfRange = [&](std::uint32_t index) {
        return index >= vertices.size() && !(restart && index == kPrimitiveRestartIndex);
      };
      if (!indices.empty() && detail::largestIndex(indices, restart) >= vertices.size()) {
        const auto past = std::find_if(indices.begin(), indices.end(), outOfRange);
        const auto i = static_cast<std::size_t>(past - indices.begin());
        return Status::error("index " + std::to_string(i) + " (" + std::to_string(*past) +
                             ") is past the last vertex (" + std::to_string(vertices.size()) + " vertices)");
      }
      const detail::ScratchPool::Lease scratch = scratch_->lease();
      return drawPrimitives<Shader, Formats...>(state, uniforms, vertices, indices, framebuffer, *scratch, pass);
    }
  }

  // Whether this context can draw `state` into `framebuffer` at all: one error, before any work.
  Status validate(const PipelineState& state, const Framebuffer& framebuffer) const {
    const RasterizationState& rs = state.rasterization;
    if (framebuffer.width() == 0 || framebuffer.height() == 0) {
      return Status::error("framebuffer has no pixels (make it with Framebuffer::create)");
    }
    if (state.topology > Topology::TriangleStripWithAdjacency) return Status::error("unknown topology");
    if (state.primitiveRestartEnable && !detail::isStripOrFanTopology(state.topology)) {
      return Status::error("primitive restart with a list topology needs primitiveTopologyListRestart "
                           "(VUID-VkPipelineInputAssemblyStateCreateInfo-topology-06252), which softraster does not offer");
    }
    if (rs.provokingVertex > ProvokingVertex::Last) return Status::error("unknown provoking vertex mode");
    if (options_.deviations > Deviations::Spec) return Status::error("unknown deviations choice");
    if (rs.lineStipple.enable && !(rs.lineStipple.factor >= 1 && rs.lineStipple.factor <= 256)) {
      return Status::error("line stipple factor " + std::to_string(rs.lineStipple.factor) +
                           " is outside [1, 256] (VUID-VkGraphicsPipelineCreateInfo-stippledLineEnable-02767)");
    }
    if (!isCourseMethod(options_.method) && options_.method != Method::Exact && options_.method != Method::ExactScalar) {
      return Status::error("unknown method");
    }
    if (options_.affineVaryings && !isCourseMethod(options_.method)) {
      return Status::error("affine varyings apply only to the course's methods (scanline, trapezoid, barycentric), not to " +
                           std::string(methodName(options_.method)));
    }
    if (options_.depthMode == DepthMode::InverseZ && framebuffer.depthFormat() != DepthFormat::D32Sfloat) {
      return Status::error("the 1/z depth buffer needs a D32_SFLOAT framebuffer");
    }
    if (framebuffer.samples() == 4) {
      if (options_.depthMode != DepthMode::Vulkan) {
        return Status::error("the 1/z depth buffer takes one sample per pixel (no 4x MSAA)");
      }
    }
    if (!(rs.lineWidth >= DeviceLimits::kMinLineWidth && rs.lineWidth <= DeviceLimits::kMaxLineWidth)) {
      return Status::error("line width " + std::to_string(rs.lineWidth) + " is outside lineWidthRange [1, 255]");
    }
    if (Status viewport = validateViewport(state.viewport); !viewport) return viewport;
    const Scissor& sc = state.scissor;
    if (sc.x < 0 || sc.y < 0) return Status::error("scissor x and y must not be negative");
    if (std::int64_t{sc.x} + sc.width > INT32_MAX || std::int64_t{sc.y} + sc.height > INT32_MAX) {
      return Status::error("scissor x + width and y + height must fit in a 32-bit signed integer");
    }
    for (std::uint32_t a = 0; a < framebuffer.colourAttachments(); ++a) {
      const BlendState b = attachmentBlend(state, a);
      // Which attachment, named only in an error (so a valid draw allocates nothing here).
      const auto error = [a](const char* what, const char* detail = "") {
        return Status::error(std::string(what) + (a == 0 ? "" : " (colour attachment " + std::to_string(a) + ")") + detail);
      };
      for (BlendFactor f : {b.srcColorBlendFactor, b.dstColorBlendFactor, b.srcAlphaBlendFactor, b.dstAlphaBlendFactor}) {
        if (f > BlendFactor::SrcAlphaSaturate) return error("unknown blend factor", " (dual-source factors are not supported)");
      }
      if (b.colorBlendOp > BlendOp::Max || b.alphaBlendOp > BlendOp::Max) return error("unknown blend op");
      if (b.colorWriteMask > kColourRGBA) return error("colour write mask", " has bits other than R, G, B and A");
    }
    if (state.blend.logicOp > LogicOp::Set) return Status::error("unknown logic op");
    const MultisampleState& ms = state.multisample;
    if (ms.sampleShadingEnable && !(ms.minSampleShading >= 0.0f && ms.minSampleShading <= 1.0f)) {
      return Status::error("minSampleShading must be in [0, 1] (VUID-VkPipelineMultisampleStateCreateInfo-"
                           "minSampleShading-00786)");
    }
    if (rs.lineRasterization > LineRasterization::Bresenham) return Status::error("unknown line rasterization mode");
    if (rs.lineRasterization == LineRasterization::Bresenham &&
        (ms.alphaToCoverageEnable || ms.alphaToOneEnable || ms.sampleShadingEnable)) {
      return Status::error("alpha to coverage, alpha to one and sample shading need rectangular lines "
                           "(VUID-VkGraphicsPipelineCreateInfo-lineRasterizationMode-02766)");
    }
    const DepthState& ds = state.depth;
    if (ds.compareOp > CompareOp::Always) return Status::error("unknown depth compare op");
    for (const StencilOpState* face : {&ds.front, &ds.back}) {
      if (face->compareOp > CompareOp::Always) return Status::error("unknown stencil compare op");
      for (StencilOp op : {face->failOp, face->passOp, face->depthFailOp}) {
        if (op > StencilOp::DecrementAndWrap) return Status::error("unknown stencil op");
      }
    }
    return {};
  }

  // Vulkan's VkViewport rules with lavapipe's limits (limits.hpp); width and height 0 mean the
  // whole framebuffer (state.hpp), so only the given sizes are checked.
  static Status validateViewport(const Viewport& vp) {
    for (float v : {vp.x, vp.y, vp.width, vp.height, vp.minDepth, vp.maxDepth}) {
      if (!std::isfinite(v)) return Status::error("viewport values must be finite");
    }
    if (vp.width == 0 && vp.height == 0) return {};
    if (!(vp.width > 0 && vp.height != 0)) {
      return Status::error("viewport width must be positive and height non-zero (a negative height flips y)");
    }
    if (vp.width > DeviceLimits::kMaxViewportDimension || std::fabs(vp.height) > DeviceLimits::kMaxViewportDimension) {
      return Status::error("viewport width and |height| must be at most maxViewportDimensions (16384)");
    }
    const float top = std::fmin(vp.y, vp.y + vp.height), bottom = std::fmax(vp.y, vp.y + vp.height);
    if (vp.x < DeviceLimits::kViewportBoundsMin || top < DeviceLimits::kViewportBoundsMin ||
        vp.x + vp.width > DeviceLimits::kViewportBoundsMax || bottom > DeviceLimits::kViewportBoundsMax) {
      return Status::error("viewport must lie within viewportBoundsRange [-32768, 32768]");
    }
    if (!(vp.minDepth >= 0 && vp.minDepth <= 1 && vp.maxDepth >= 0 && vp.maxDepth <= 1)) {
      return Status::error("viewport minDepth and maxDepth must be in [0, 1]");
    }
    return {};
  }

  // Validates, then picks the draw loop's instantiation for the depth format (among Formats, or
  // all when none are named) and fmuladd. A depth/stencil format draws with its depth aspect's
  // instantiation (formats.hpp): stencil is a run-time branch of the fragment stages.
  template <class Shader, DepthFormat... Formats>
  Status drawPrimitives(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                        std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                        Framebuffer& framebuffer, detail::DrawScratch& scratch, detail::PassRecording* pass) const {
    if (Status status = validate(state, framebuffer); !status) return status;
    constexpr std::uint32_t kOutputs = static_cast<std::uint32_t>(colourOutputsOf<Shader>());
    for (std::uint32_t a = kOutputs; a < framebuffer.colourAttachments(); ++a) {
      if (attachmentBlend(state, a).colorWriteMask != 0) {
        return Status::error("colour attachment " + std::to_string(a) + " has no fragment output (the shader writes " +
                             std::to_string(kOutputs) + "), so Vulkan leaves its colour undefined: give the shader an "
                             "output for it or set its colorWriteMask to 0");
      }
    }
    // No sample kept: nothing to draw (lavapipe discards the rasterization). Its 4x MSAA Bresenham
    // lines are drawn with multisampling off, where only a mask of 0 discards them.
    const bool broadcastLines = framebuffer.samples() == 4 && options_.deviations == Deviations::Driver &&
                                detail::isLineTopology(state.topology) &&
                                state.rasterization.lineRasterization == LineRasterization::Bresenham;
    if (broadcastLines ? state.multisample.sampleMask == 0
                       : detail::sampleCoverage(state.multisample, framebuffer.samples(), options_.deviations).sampleMask == 0) {
      return {};
    }
    if constexpr (UsesFragmentBuiltins<Shader>) {
      if (WritesFragDepth<Shader> && options_.depthMode != DepthMode::Vulkan) {
        return Status::error("gl_FragDepth needs the Vulkan depth mode, not the 1/z depth buffer");
      }
    }
    if (drawIfFormat<Shader, DepthFormat::D16Unorm, Formats...>(state, uniforms, vertices, indices, framebuffer, scratch,
                                                                pass) ||
        drawIfFormat<Shader, DepthFormat::X8D24UnormPack32, Formats...>(state, uniforms, vertices, indices, framebuffer,
                                                                        scratch, pass) ||
        drawIfFormat<Shader, DepthFormat::D32Sfloat, Formats...>(state, uniforms, vertices, indices, framebuffer, scratch,
                                                                 pass)) {
      return {};
    }
    return Status::error("the draw was compiled for other depth formats than the framebuffer's (Context::draw's Formats)");
  }

  // Draws with Format and returns true if the framebuffer has it and Formats allows it.
  template <class Shader, DepthFormat Format, DepthFormat... Formats>
  bool drawIfFormat(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                    std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                    Framebuffer& framebuffer, detail::DrawScratch& scratch, detail::PassRecording* pass) const {
    if constexpr (sizeof...(Formats) == 0 || ((depthAspect(Formats) == Format) || ...)) {
      if (depthAspect(framebuffer.depthFormat()) != Format) return false;
      drawWithFormat<Shader, Format>(state, uniforms, vertices, indices, framebuffer, scratch, pass);
      return true;
    } else {
      return false;
    }
  }

  template <class Shader, DepthFormat Format>
  void drawWithFormat(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                      std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                      Framebuffer& framebuffer, detail::DrawScratch& scratch, detail::PassRecording* pass) const {
    // A shader with the fragment built-ins is drawn by the exact method whatever the method. A
    // course method draws filled triangles; its lines, points and polygon modes line and point
    // are the exact method's, drawn by the scalar path below (as Method::ExactScalar draws them).
    if constexpr (!UsesFragmentBuiltins<Shader>) {
      if (isCourseMethod(options_.method) && detail::isTriangleTopology(state.topology) &&
          state.rasterization.polygonMode == PolygonMode::Fill) {
        if (pass != nullptr) pass->flush();  // drawn now: after the pass's deferred draws
        if (options_.fusedMultiplyAdd) {
          drawCourseFused<Shader, Format>(state, uniforms, vertices, indices, framebuffer, scratch);
        } else {
          drawCourse<Shader, false, Format>(state, uniforms, vertices, indices, framebuffer, scratch);
        }
        return;
      }
    }
#if SOFTRASTER_HAS_FAST_PATH
    if constexpr (ShadesBatches<Shader>) {
      // The fast path blends UNORM8 targets; sRGB, A2B10G10R10 and float targets have their own
      // arithmetic per pixel (fragment/colour.hpp): the scalar fragment stage.
      const ColourFormat colour = framebuffer.colourFormat();
      if (options_.method == Method::Exact && options_.fusedMultiplyAdd && detail::fast::cpuRunsFastPath() &&
          (colour == ColourFormat::R8G8B8A8Unorm || colour == ColourFormat::B8G8R8A8Unorm)) {
        drawFast<Shader, Format>(state, uniforms, vertices, indices, framebuffer, scratch, pass);
        return;
      }
    }
#endif
    if (pass != nullptr) pass->flush();  // drawn now: after the pass's deferred draws
    if (options_.fusedMultiplyAdd) {
      drawFused<Shader, Format>(state, uniforms, vertices, indices, framebuffer, scratch);
    } else {
      drawExact<Shader, false, Format>(state, uniforms, vertices, indices, framebuffer, scratch);
    }
  }

  template <class Shader, bool Fused, DepthFormat Format>
  void drawExact(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                 std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                 Framebuffer& framebuffer, detail::DrawScratch& scratch) const {
    const bool inverseZ = options_.depthMode == DepthMode::InverseZ;
    detail::ExactDraw<Shader, Fused, Format>(state, uniforms, framebuffer, inverseZ, scratch, threadsFor(options_.method),
                                             options_)
        .run(vertices, indices);
  }

  // The fused path, compiled for CPUs with FMA so that std::fma is one instruction instead of a
  // library call (it is only taken where the CPU has FMA; results are the same either way).
  template <class Shader, DepthFormat Format>
#if defined(__x86_64__) && defined(__GNUC__)
  [[gnu::target("fma"), SOFTRASTER_FLATTEN]]
#endif
  void drawFused(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                 std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                 Framebuffer& framebuffer, detail::DrawScratch& scratch) const {
    drawExact<Shader, true, Format>(state, uniforms, vertices, indices, framebuffer, scratch);
  }

  // A course method: the same draw loop (front end, lines and points) with the course's triangles,
  // on the calling thread; the front end rounds fmuladd as the options say, like the exact method.
  template <class Shader, bool Fused, DepthFormat Format>
  void drawCourse(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                  std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                  Framebuffer& framebuffer, detail::DrawScratch& scratch) const {
    detail::ExactDraw<Shader, Fused, Format, detail::FragmentStage<Shader, Fused, Format>,
                      detail::course::CourseTriangles<Shader, Fused, Format>>(
        state, uniforms, framebuffer, options_.depthMode == DepthMode::InverseZ, scratch, nullptr, options_)
        .run(vertices, indices);
  }

  template <class Shader, DepthFormat Format>
#if defined(__x86_64__) && defined(__GNUC__)
  [[gnu::target("fma"), SOFTRASTER_FLATTEN]]
#endif
  void drawCourseFused(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                       std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                       Framebuffer& framebuffer, detail::DrawScratch& scratch) const {
    drawCourse<Shader, true, Format>(state, uniforms, vertices, indices, framebuffer, scratch);
  }

#if SOFTRASTER_HAS_FAST_PATH
  // The fast path: the same draw loop with the SIMD fragment stage, compiled for AVX2 and FMA and
  // flattened so the shader's batch code becomes AVX2 code (simd.hpp says why that works).
  template <class Shader, DepthFormat Format>
  [[gnu::target("avx2,fma"), SOFTRASTER_FLATTEN]]
  void drawFast(const PipelineState& state, const typename Shader::Uniforms& uniforms,
                std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices,
                Framebuffer& framebuffer, detail::DrawScratch& scratch, detail::PassRecording* pass) const {
    detail::ExactDraw<Shader, true, Format, detail::fast::FastFragmentStage<Shader, Format>>(
        state, uniforms, framebuffer, options_.depthMode == DepthMode::InverseZ, scratch, pool_.get(), options_, pass)
        .run(vertices, indices);
  }
#endif

  // The scalar path is the reference the fast one is checked against: it runs on the calling
  // thread alone, as one primitive after another, whatever the thread count.
  detail::ThreadPool* threadsFor(Method method) const { return method == Method::Exact ? pool_.get() : nullptr; }

  ContextOptions options_;
  std::unique_ptr<detail::ThreadPool> pool_;
  std::unique_ptr<detail::ScratchPool> scratch_;  // the draws' vectors, kept between draws (no allocation per draw)
};

}  // namespace softraster

#if defined(__clang__)
#pragma float_control(pop)
#endif
