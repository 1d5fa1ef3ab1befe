// The exact method's draw loop: one draw call as a list of stage calls, each stage in its file:
//   vertex processing (geometry/vertex_processing) -> primitive assembly and vertex batches
//   (geometry/primitive_assembly) -> clipping (geometry/clipping) -> the draw pipeline's float
//   cull (geometry/culling) -> depth bias of unfilled polygons (geometry/polygon_offset) -> polygon
//   modes (geometry/unfilled) -> snapping, the fixed-point cull
//   and setup (exact/triangle_setup, exact/line_point_setup) -> coverage and fragments
//   (fragment/shade, over exact/rasterizer and exact/interpolation).
// A draw of filled triangles snaps each vertex once, beside its shading, into a compact copy of
// its position and clip mask; a batch is clip-tested and the triangles that need no clipping are
// culled from it (the same bits as snapping per triangle), so a culled triangle reads 12 bytes of
// each vertex and nothing else.
// Primitives reach the fragment stage in submission order; with more than one thread the band
// queue (fast/bands.hpp) draws them band by band in parallel, each band in that order.
// With more than one thread the front end runs in parallel too, in rounds of primitives sized
// by the records they keep: the vertices are shaded in ranges, and a round's primitives are cut
// into consecutive ranges (whole vertex batches for triangles), each run by one front-end worker
// (its clipping scratch, and a recorder of the band queue with a list of its own); then the
// band queue draws the round. A worker's range follows the one before it in the draw, so the
// bands see the primitives in submission order and the output does not depend on the threads.
// The same loop serves the scalar path and the fast path: only the fragment stage differs. It
// serves the course's methods too (course/draw.hpp): with Course a course::CourseTriangles, every
// filled triangle goes to it after the front end, instead of snapping, setup and the fragment
// stage. Such a draw is only ever one of filled triangles: the Context draws lines, points and
// polygon modes line and point by the scalar exact path for a course method, so a course
// instantiation compiles no line or point code (one copy less of it per shader and format).
// Primitive restart cuts the indices into runs, each drawn as a draw of its own (its own vertex
// batches); provoking vertex last changes assembly, clipping's fan, setup's reordering of
// clockwise triangles and which vertex gives flat varyings (the stages say how).
// A draw that writes depth opens the tiles' depth bounds its compare op may move, or forgets
// them when its fragment stage does not keep them (fast/depth_tiles.hpp).
// Deliberately absent: validation of the draw (pipeline.hpp's Context does it before any work)
// and any choice of method or instruction set (the Context makes those and instantiates this).
#pragma once

#include <softraster/detail/course/draw.hpp>
#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/line_point_setup.hpp>
#include <softraster/detail/exact/scratch.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/fast/bands.hpp>
#include <softraster/detail/fast/depth_tiles.hpp>
#include <softraster/detail/fast/pool.hpp>
#include <softraster/detail/fragment/shade.hpp>
#include <softraster/detail/geometry/clipping.hpp>
#include <softraster/detail/geometry/culling.hpp>
#include <softraster/detail/geometry/polygon_offset.hpp>
#include <softraster/detail/geometry/line_stipple.hpp>
#include <softraster/detail/geometry/primitive_assembly.hpp>
#include <softraster/detail/geometry/unfilled.hpp>
#include <softraster/detail/geometry/vertex_processing.hpp>
#include <softraster/detail/geometry/viewport.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/shader.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace softraster::detail {

// The Course parameter of a draw of the exact method: no course method.
struct NoCourseMethod {};

// Fragments: the fragment stage, FragmentStage (scalar, fragment/shade.hpp) or the fast path's
// fast::FastFragmentStage (fast/fragments.hpp); both take the same calls and give the same bits.
// Course: NoCourseMethod, or course::CourseTriangles (a course method draws the filled triangles).
template <class Shader, bool Fused, DepthFormat Format, class Fragments = FragmentStage<Shader, Fused, Format>,
          class Course = NoCourseMethod>
class ExactDraw {
 public:
  static constexpr int N = Shader::kVaryings;
  using Vertex = ShadedVertex<N>;

  // pool: the Context's threads (nullptr or one thread: everything on the calling thread);
  // scratch: the vectors this draw fills, kept by the Context between draws; options: the
  // Context's: its deviations and allowAvx512 (for the fragment stage), and a course method's
  // method and affineVaryings.
  // pass: a pass the band queue may defer the draw into (fast/deferred_draws.hpp), or nullptr.
  ExactDraw(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
            bool inverseZ, DrawScratch& scratch, ThreadPool* pool = nullptr, const ContextOptions& options = {},
            PassRecording* pass = nullptr)
      : state_(state),
        rs_(state.rasterization),
        uniforms_(uniforms),
        viewport_(resolveViewport(state.viewport, framebuffer.width(), framebuffer.height())),
        transform_(makeViewportTransform(viewport_)),
        region_(drawRegion(state.scissor, viewport_, framebuffer.width(), framebuffer.height())),
        multisample_(framebuffer.samples() == 4),
        specDeviations_(options.deviations == Deviations::Spec),
        // With 4x MSAA the fragment stage may also touch the column and row lavapipe's scissor
        // planes reach (MsaaRegionEdges); the bands (fast/bands.hpp) cover them too.
        fragments_(pool, scratch, state, uniforms, framebuffer, viewport_,
                   multisample_ ? msaaRegionEdges(region_, state.scissor, options.deviations).rasterRegion : region_,
                   inverseZ, options, pass),
        shaded_(scratch.vector<Vertex>(ScratchSlot::ShadedVertices)),
        snapped_(scratch.vector<SnappedVertex>(ScratchSlot::SnappedVertices)),
        lines_(scratch.vector<LineIndices>(ScratchSlot::Lines)),
        course_(makeCourse(state, uniforms, framebuffer, inverseZ, options, scratch)) {
    // A deferred draw that keeps the bounds opens them band by band as it is drawn (bands.hpp).
    const bool keeps = kKeepsDepthTiles && !inverseZ;
    if (!keeps || !fragments_.deferred()) fast::prepareDepthTiles(framebuffer, state.depth, keeps);
  }

  // Draws vertices[indices[k]] in order, assembled by the state's topology.
  // A course method's draw must be one of filled triangles (the top comment).
  void run(std::span<const typename Shader::Vertex> vertices, std::span<const std::uint32_t> indices) {
    if (region_.empty()) return;
    if constexpr (kCourse) assert(isTriangleTopology(state_.topology) && rs_.polygonMode == PolygonMode::Fill);
    shadeVertices(vertices);
    forEachRestartRun(indices, state_.primitiveRestartEnable, [&](std::span<const std::uint32_t> run) {
      if constexpr (kCourse) {
        drawTriangles(run);
      } else if (state_.topology == Topology::PointList) {
        drawPoints(run);
      } else if (isLineTopology(state_.topology)) {
        drawLines(run);
      } else {
        drawTriangles(run);
      }
    });
    fragments_.endRound();
  }

 private:
  static constexpr InterpolationSet<N> kInterpolation = interpolationOf<Shader>();
  static constexpr bool kCourse = !std::is_same_v<Course, NoCourseMethod>;
  // Whether every fragment of the draw goes through a stage that keeps the tiles' depth bounds.
  static constexpr bool kKeepsDepthTiles = [] {
    if constexpr (requires { Fragments::kKeepsDepthTiles; }) return Fragments::kKeepsDepthTiles && !kCourse;
    return false;
  }();

  Course makeCourse(const PipelineState& state, const typename Shader::Uniforms& uniforms, Framebuffer& framebuffer,
                    bool inverseZ, const ContextOptions& options, DrawScratch& scratch) const {
    if constexpr (kCourse) {
      return Course(state, uniforms, framebuffer, viewport_, region_, inverseZ, options, scratch);
    } else {
      return {};
    }
  }

  using Queue = BandQueue<Fragments, typename Shader::Uniforms, N>;

  // One front-end worker: where its set-up primitives go and its clipping scratch.
  struct Worker {
    typename Queue::Recorder sink;
    ClippedPolygon<N> polygon;
    // The stencil face of the lines and points being drawn: front, but for an unfilled
    // back-facing polygon's in Deviations::Spec (lavapipe gives them the front face).
    bool facingFront = true;
    // The stipple counter of stippled polygon-mode lines: Mesa's stipple stage keeps one for the
    // whole draw, reset by each triangle that reaches the unfilled stage with its reset flag.
    std::uint32_t stippleCounter = 0;
  };

  // Rounds of the parallel front end (the top comment): each after the first has as many
  // primitives as the records of the one before say will keep about kRoundRecordBytes of records,
  // within [kMinRoundPrimitives, kMaxRoundPrimitives]. Each round costs two batches of the pool
  // and their waits, while a round's records are written on one core and read on another, best
  // from the last-level cache: a million-triangle sphere with back faces culled (few records a
  // triangle: most are culled or miss every pixel centre) took 15% less time in rounds of 2^17
  // triangles than of 2^15, while a 100k-triangle wireframe (three records a triangle) took 15%
  // more (softraster_benchmarks, 2 threads).
  // Where the rounds fall never changes the pixels (each band draws its primitives in order).
  static constexpr std::size_t kRoundRecordBytes = std::size_t{12} << 20;
  static constexpr std::size_t kMinRoundPrimitives = 1u << 12, kMaxRoundPrimitives = 1u << 17;
  static constexpr std::size_t kFirstRoundPrimitives = 1u << 15;

  // The primitives of the round after one of `primitives` that kept `bytes` of records.
  static std::size_t nextRoundPrimitives(std::size_t bytes, std::size_t primitives) {
    if (bytes == 0) return kMaxRoundPrimitives;
    const double next = static_cast<double>(kRoundRecordBytes) * static_cast<double>(primitives) / static_cast<double>(bytes);
    return static_cast<std::size_t>(
        std::clamp(next, static_cast<double>(kMinRoundPrimitives), static_cast<double>(kMaxRoundPrimitives)));
  }
  // The fewest primitives a draw needs before its front end is shared out: fewer are set up by
  // the calling thread in one round. A batch of the pool costs a few microseconds (its threads
  // spin between batches), so a draw of a few hundred primitives already gains from sharing its
  // front end out.
  static constexpr std::size_t kParallelPrimitives = 512;
  static constexpr std::size_t kVertexRange = 1024;  // vertices per task of the parallel vertex stage

  // run(worker, begin, end) over [0, count) in rounds, each cut into consecutive ranges that
  // start at a multiple of `align` (the vertex batches), one per worker, on the pool's threads
  // when there are enough primitives; the band queue draws each round.
  // oneRange: the whole draw as one range on the calling thread (a stipple counter runs through it).
  template <class Range>
  void forEachRange(std::size_t count, std::size_t align, bool oneRange, Range&& range) {
    ThreadPool* pool = fragments_.pool();
    if (pool == nullptr || count < kParallelPrimitives || oneRange) {
      Worker worker{fragments_.recorder(0), {}, true, 0};
      range(worker, 0, count);
      return;
    }
    const std::size_t workers = fragments_.workers();
    std::size_t round = kFirstRoundPrimitives;
    for (std::size_t start = 0, end = 0; start < count; start = end) {
      end = std::min(count, start + std::max<std::size_t>(1, round / align) * align);  // rounds start on a batch too
      const std::size_t per = ((end - start + workers - 1) / workers + align - 1) / align * align;
      pool->run(workers, [&](std::size_t k) {
        const std::size_t begin = std::min(end, start + k * per);
        Worker worker{fragments_.recorder(static_cast<unsigned>(k)), {}, true, 0};
        range(worker, begin, std::min(end, begin + per));
      });
      round = nextRoundPrimitives(fragments_.endRound(), end - start);
    }
  }

  void shadeVertices(std::span<const typename Shader::Vertex> vertices) {
    shaded_.resize(vertices.size());
    if (snapsVertices_) snapped_.resize(vertices.size());
    ThreadPool* pool = fragments_.pool();
    if (pool == nullptr || vertices.size() < 2 * kVertexRange) {
      shadeVertexRange(vertices, 0, vertices.size());
      return;
    }
    pool->run((vertices.size() + kVertexRange - 1) / kVertexRange, [&](std::size_t k) {
      const std::size_t begin = k * kVertexRange;
      // Reached through std::function, outside the flattened entry point: compiled again for the
      // stage's instruction set, so fmuladd stays one instruction.
      callCompiledFor<Fragments::kInstructionSet, &ExactDraw::shadeVertexRange>(
          *this, vertices, begin, std::min(vertices.size(), begin + kVertexRange));
    });
  }

  void shadeVertexRange(std::span<const typename Shader::Vertex> vertices, std::size_t begin, std::size_t end) {
    const bool clipDepth = !rs_.depthClampEnable;
    if (!snapsVertices_) {
      for (std::size_t i = begin; i < end; ++i) shaded_[i] = shadeVertex<Shader, Fused>(uniforms_, vertices[i], transform_, clipDepth);
      return;
    }
    for (std::size_t i = begin; i < end; ++i) {  // snapped while the vertex is at hand
      const Vertex v = shadeVertex<Shader, Fused>(uniforms_, vertices[i], transform_, clipDepth);
      snapped_[i] = {snapVertex(v.window, pixelOffset_), v.clipMask};
      shaded_[i] = v;
    }
  }

  // A range of the front end run by a worker, compiled for the stage's instruction set (a task of
  // the pool runs outside the flattened entry point).
  template <auto Member, class... Args>
  void runRange(Worker& worker, Args&&... args) {
    callCompiledFor<Fragments::kInstructionSet, Member>(*this, worker, std::forward<Args>(args)...);
  }

  void drawPoints(std::span<const std::uint32_t> indices) {
    forEachRange(indices.size(), 1, false, [&](Worker& worker, std::size_t begin, std::size_t end) {
      runRange<&ExactDraw::drawPointRange>(worker, indices.subspan(begin, end - begin));
    });
  }

  void drawPointRange(Worker& worker, std::span<const std::uint32_t> indices) {
    for (const std::uint32_t index : indices) {
      const Vertex& v = shaded_[index];
      if (pointSurvivesClipping(v)) drawPointHere(worker, v);
    }
  }

  // One run of lines (a draw, or a run between primitive restarts): the stipple counter is
  // local to it, as the lines of a strip are drawn in order.
  void drawLines(std::span<const std::uint32_t> indices) {
    assembleLines(state_.topology, indices, lines_);
    // A stipple counter runs on from line to line along a strip, so a stippled draw is one range.
    const bool oneRange = rs_.lineStipple.enable;
    forEachRange(lines_.size(), 1, oneRange, [&](Worker& worker, std::size_t begin, std::size_t end) {
      runRange<&ExactDraw::drawLineRange>(worker, std::span<const LineIndices>(lines_).subspan(begin, end - begin));
    });
  }

  void drawLineRange(Worker& worker, std::span<const LineIndices> lines) {
    Vertex clippedA, clippedB;
    std::uint32_t stippleCounter = 0;
    const bool resetEveryLine = stippleResetsEveryLine(state_.topology);
    for (const LineIndices& l : lines) {
      const Vertex& a = shaded_[l[0]];
      const Vertex& b = shaded_[l[1]];
      const std::uint32_t outside = a.clipMask | b.clipMask;
      if (resetEveryLine) stippleCounter = 0;
      if (outside == 0) {
        drawLineStippled(worker, a, b, stippleCounter);
      } else if ((a.clipMask & b.clipMask) == 0 &&
                 clipLine(a, b, outside, transform_, kInterpolation, clippedA, clippedB, provokingLast_)) {
        drawLineStippled(worker, clippedA, clippedB, stippleCounter);
      }
    }
  }

  // A line past clipping: whole, or the pieces its stipple pattern keeps (geometry/line_stipple).
  void drawLineStippled(Worker& worker, const Vertex& a, const Vertex& b, std::uint32_t& counter) {
    if (!rs_.lineStipple.enable) {
      drawLineHere(worker, a, b);
      return;
    }
    Vertex flatA = a, flatB = b;
    flatShadeLine(flatA, flatB, kInterpolation, provokingLast_);
    stippleLine(flatA, flatB, rs_.lineStipple, rs_.lineRasterization != LineRasterization::Bresenham, counter,
                [&](const Vertex& p, const Vertex& q) { drawLine(worker, p, q); });
  }

  // Triangles in vertex batches: a batch with no vertex outside the frustum goes straight to
  // setup; one that clips goes through the draw pipeline (float cull, clipping, polygon modes).
  void drawTriangles(std::span<const std::uint32_t> indices) {
    winding_ = windingFilter(rs_);
    if (!winding_.drawClockwise && !winding_.drawCounterClockwise) return;
    const std::size_t batchSize = trianglesPerBatch(state_.topology);
    // Stippled polygon-mode lines: the stipple counter may run on from one triangle to the next
    // (drawCulled), so the draw is one range.
    const bool oneRange = rs_.lineStipple.enable && rs_.polygonMode == PolygonMode::Line;
    forEachRange(triangleCount(state_.topology, indices.size()), batchSize, oneRange,
                 [&](Worker& worker, std::size_t begin, std::size_t end) {
                   runRange<&ExactDraw::drawTriangleRange>(worker, indices, begin, end);
                 });
  }

  // Triangles [begin, end) of the draw, assembled from `indices` batch by batch as the range is
  // drawn (on the worker's thread, not beforehand on the calling one); begin starts a vertex batch.
  void drawTriangleRange(Worker& worker, std::span<const std::uint32_t> indices, std::size_t begin, std::size_t end) {
    const bool unfilled = rs_.polygonMode != PolygonMode::Fill;
    const std::size_t batchSize = trianglesPerBatch(state_.topology);
    std::array<TriangleIndices, kMaxTrianglesPerBatch> assembled;
    for (std::size_t start = begin; start < end; start += batchSize) {
      const std::size_t count = std::min(batchSize, end - start);
      assembleTriangleRange(state_.topology, indices, start, count, assembled.data(), provokingLast_);
      const std::span<const TriangleIndices> batch(assembled.data(), count);
      const bool throughDrawPipeline =
          unfilled || (snapsVertices_ ? batchNeedsClipping(batch, snapped_) : batchNeedsClipping(batch, shaded_)) ||
          adjacencyNeedsClipping(state_.topology, indices, start, batch.size(), shaded_);
      for (const TriangleIndices& t : batch) {
        const Vertex& v0 = shaded_[t[0]];
        const Vertex& v1 = shaded_[t[1]];
        const Vertex& v2 = shaded_[t[2]];
        if (throughDrawPipeline) {
          drawThroughPipeline(worker, v0, v1, v2);
        } else if constexpr (kCourse) {
          drawTriangleHere(worker, v0, v1, v2);
        } else {  // snapped with the vertices: culled before any other vertex data is read
          drawFixedTriangle(worker, fixedTriangle(snapped_[t[0]].position, snapped_[t[1]].position, snapped_[t[2]].position),
                            v0, v1, v2);
        }
      }
    }
  }

  // The straight path of a range inlines the set-up of a triangle, a line or a point; the draw
  // pipeline (clipping, the unfilled stage) calls them from several places, through one copy
  // each compiled for the stage's instruction set (detail/instruction_set.hpp) rather than a
  // copy in every caller.
  void drawTriangle(Worker& worker, const Vertex& a, const Vertex& b, const Vertex& c) {
    callCompiledFor<Fragments::kInstructionSet, &ExactDraw::drawTriangleHere>(*this, worker, a, b, c);
  }
  void drawLine(Worker& worker, const Vertex& a, const Vertex& b) {
    callCompiledFor<Fragments::kInstructionSet, &ExactDraw::drawLineHere>(*this, worker, a, b);
  }
  void drawPoint(Worker& worker, const Vertex& v) {
    callCompiledFor<Fragments::kInstructionSet, &ExactDraw::drawPointHere>(*this, worker, v);
  }

  // Mesa's draw pipeline for one triangle: clip, float cull, then fill or the unfilled stage.
  void drawThroughPipeline(Worker& worker, const Vertex& v0, const Vertex& v1, const Vertex& v2) {
    const std::uint32_t outside = v0.clipMask | v1.clipMask | v2.clipMask;
    if (outside == 0) {
      if (survivesPipelineCull(v0.window, v1.window, v2.window, rs_)) drawCulled(worker, v0, v1, v2, 7u, true);
      return;
    }
    if ((v0.clipMask & v1.clipMask & v2.clipMask) != 0) return;  // entirely outside one plane
    ClippedPolygon<N>& polygon = worker.polygon;
    if (!clipTriangle(v0, v1, v2, outside, transform_, kInterpolation, polygon, rs_.polygonMode == PolygonMode::Point,
                      provokingLast_)) {
      return;
    }
    for (int i = 2; i < polygon.count; ++i) {  // a fan from vertex 0: (0, i-1, i), or (i-1, i, 0)
      const Vertex& p0 = polygon.vertices[0];
      const Vertex& p1 = polygon.vertices[static_cast<std::size_t>(i - 1)];
      const Vertex& p2 = polygon.vertices[static_cast<std::size_t>(i)];
      const Vertex& a = provokingLast_ ? p1 : p0;
      const Vertex& b = provokingLast_ ? p2 : p1;
      const Vertex& c = provokingLast_ ? p0 : p2;
      if (survivesPipelineCull(a.window, b.window, c.window, rs_)) {
        drawCulled(worker, a, b, c, fanTriangleEdgeFlags(polygon, i, provokingLast_), i == 2);
      }
    }
  }

  // A triangle past the draw pipeline's cull: filled, or as lines or points (depth-biased first).
  // resetStipple: the triangle carries Mesa's DRAW_PIPE_RESET_STIPPLE, as every unclipped
  // triangle does and, of a clipped one, the first of its fan (draw_pipe_clip.c emit_poly): its
  // lines start the stipple counter at 0; the fan's later triangles continue it.
  void drawCulled(Worker& worker, const Vertex& a, const Vertex& b, const Vertex& c, unsigned edgeFlags,
                  bool resetStipple) {
    if constexpr (!kCourse) {  // a course method draws filled triangles only (run())
      if (rs_.polygonMode != PolygonMode::Fill) {
        drawUnfilled(worker, a, b, c, edgeFlags, resetStipple);
        return;
      }
    }
    drawTriangle(worker, a, b, c);
  }

  // A triangle of polygon mode line or point: its edges or its vertices.
  void drawUnfilled(Worker& worker, const Vertex& a, const Vertex& b, const Vertex& c, unsigned edgeFlags,
                    bool resetStipple) {
    Vertex biased[3] = {a, b, c};
    if (rs_.depthBias.enable) offsetUnfilledTriangle(biased[0], biased[1], biased[2], rs_.depthBias, Format);
    // lavapipe's unfilled stage passes the polygon's facing on only to a shader that reads
    // gl_FrontFacing; its lines and points are otherwise front-facing (stencil state included).
    worker.facingFront = !(specDeviations_ || ReadsFrontFacing<Shader>) ||
                         facesFrontInPipeline(a.window, b.window, c.window, rs_.frontFace);
    if (resetStipple) worker.stippleCounter = 0;
    drawUnfilledTriangle(
        rs_.polygonMode, biased[0], biased[1], biased[2], edgeFlags, kInterpolation,
        [&](const Vertex& p, const Vertex& q) {
          if (!rs_.lineStipple.enable) {
            drawLine(worker, p, q);
            return;
          }
          // The unfilled stage has flat-shaded the triangle already; the stipple stage follows it.
          stippleLine(p, q, rs_.lineStipple, rs_.lineRasterization != LineRasterization::Bresenham,
                      worker.stippleCounter, [&](const Vertex& s, const Vertex& e) { drawLine(worker, s, e); });
        },
        [&](const Vertex& p) { drawPoint(worker, p); }, provokingLast_);
    worker.facingFront = true;
  }

  // Snapping, the fixed-point cull, setup and fragments of one filled triangle; or the course
  // method's own cull, setup, coverage and interpolation.
  void drawTriangleHere(Worker& worker, const Vertex& a, const Vertex& b, const Vertex& c) {
    if constexpr (kCourse) {
      if (provokingLast_) {
        course_.drawTriangle(c, a, b, winding_);  // the same winding, the provoking vertex first
      } else {
        course_.drawTriangle(a, b, c, winding_);
      }
    } else {
      drawExactTriangle(worker, a, b, c);
    }
  }

  void drawExactTriangle(Worker& worker, const Vertex& a, const Vertex& b, const Vertex& c) {
    drawFixedTriangle(worker, snapTriangle(a.window, b.window, c.window, pixelOffset_), a, b, c);
  }

  // The same, its vertices snapped already (`fixed`: a, b and c's window x and y).
  void drawFixedTriangle(Worker& worker, FixedTriangle fixed, const Vertex& a, const Vertex& b, const Vertex& c) {
    const int area = fixedAreaSign(fixed);
    if (area == 0 || (area > 0 ? !winding_.drawCounterClockwise : !winding_.drawClockwise)) return;
    if (!multisample_ && missesEveryPixelCentre(fixed)) return;  // no pixel to draw: skip the setup
    // From here on the triangle is counter-clockwise: a negative one continues as (a, c, b),
    // keeping the provoking vertex first, or as (b, a, c) with provoking vertex last.
    const bool swapFirst = area < 0 && provokingLast_;
    const bool swapLast = area < 0 && !provokingLast_;
    const Vertex& v0 = swapFirst ? b : a;
    const Vertex& v1 = swapFirst ? a : (swapLast ? c : b);
    const Vertex& v2 = swapLast ? b : c;
    if (area < 0) {
      const int i = provokingLast_ ? 0 : 2;
      std::swap(fixed.x[1], fixed.x[i]);
      std::swap(fixed.y[1], fixed.y[i]);
    }
    const TriangleEdges edges = setupEdges(fixed);
    fragments_.prefetch(edges.bounds);
    TriangleInterpolants<N> interpolants =
        setupInterpolants(v0, v1, v2, kInterpolation, rs_.depthBias, Format, pixelOffset_, provokingLast_);
    interpolants.frontFacing = (area > 0) == (rs_.frontFace == FrontFace::CounterClockwise);  // the stencil face
    if (multisample_) {
      worker.sink.shadeSamples(edges.edges, edges.bounds, interpolants);
    } else {
      worker.sink.shadePixels(edges.edges, edges.bounds, interpolants);
    }
  }

  // A line: single-sample, or with 4x MSAA as lavapipe draws it (exact/line_point_setup.hpp): its
  // quad snapped without the half-pixel offset and walked as lavapipe bins it, or, for Bresenham
  // lines of a line topology, which lavapipe draws with multisampling off, broadcast
  // (fragment/shade.hpp). Deviations::Spec: attributes at the fragment centre, every sample.
  void drawLineHere(Worker& worker, const Vertex& a, const Vertex& b) {
    const bool sampled = multisample_ && !broadcastLines_;
    const float snapOffset = sampled ? 0.0f : kPixelCentreOffset;
    LineSetup line;
    const bool drawn = rs_.lineRasterization == LineRasterization::Bresenham
                           ? setupBresenhamLine(a.window, b.window, rs_.lineWidth, line, snapOffset)
                           : setupRectangularLine(a.window, b.window, rs_.lineWidth, line, snapOffset);
    if (!drawn) return;
    const bool specLines = sampled && specDeviations_;
    TriangleInterpolants<N> interpolants =
        setupLineInterpolants(a, b, line, kInterpolation, provokingLast_, specLines ? 0.0f : kPixelCentreOffset);
    interpolants.frontFacing = worker.facingFront;
    const QuadEdges& quad = line.quad;
    if (!sampled) {
      if (broadcastLines_) {
        worker.sink.shadeBroadcast(quad.edges, quad.bounds, interpolants);
      } else {
        worker.sink.shadePixels(quad.edges, quad.bounds, interpolants);
      }
      return;
    }
    if (specLines) {
      worker.sink.shadeSamples(quad.edges, quad.sampleBounds, interpolants);
      return;
    }
    PixelRect box = quad.bounds;
    if (intersect(box, region_).empty()) return;  // lavapipe culls it
    box.x0 = std::max(box.x0, 0);
    box.y0 = std::max(box.y0, 0);
    // scissor_planes_needed: a left or top plane only where the box starts outside the region
    const unsigned regionPlanes = (box.x0 < region_.x0 ? MsaaRegionEdges::kLeftPlane : 0u) |
                                  (box.y0 < region_.y0 ? MsaaRegionEdges::kTopPlane : 0u);
    worker.sink.shadeSamples(quad.edges, msaaLineWalk(box, region_), interpolants, regionPlanes);
  }

  void drawPointHere(Worker& worker, const Vertex& v) {
    const QuadEdges quad = setupPoint(v.window, v.pointSize, multisample_ ? &region_ : nullptr);
    TriangleInterpolants<N> interpolants = setupPointInterpolants(v, kInterpolation);
    interpolants.frontFacing = worker.facingFront;
    if (multisample_) {
      worker.sink.shadeSamples(quad.edges, quad.bounds, interpolants);
    } else {
      worker.sink.shadePixels(quad.edges, quad.bounds, interpolants);
    }
  }

  // Constant for the draw.
  const PipelineState& state_;
  const RasterizationState& rs_;
  const typename Shader::Uniforms& uniforms_;
  Viewport viewport_;
  ViewportTransform transform_;
  PixelRect region_;
  bool multisample_;
  // Where snapping and plane origins put the pixel centre: 0.5 single-sample, 0 with 4x MSAA.
  float pixelOffset_ = multisample_ ? 0.0f : kPixelCentreOffset;
  bool provokingLast_ = rs_.provokingVertex == ProvokingVertex::Last;
  // Deviations::Spec: an unfilled polygon's lines and points take its stencil face, and MSAA lines
  // are drawn as the spec has them.
  bool specDeviations_;
  // 4x MSAA Bresenham lines of a line topology: lavapipe draws them with multisampling off
  // (lvp_pipeline.c disable_multisample; polygon mode line keeps it on).
  bool broadcastLines_ = multisample_ && rs_.lineRasterization == LineRasterization::Bresenham &&
                         isLineTopology(state_.topology);
  Queue fragments_;  // the stage, on one thread or in bands
  WindingFilter winding_{true, true};
  // Scratch: the Context's, reused across draws.
  std::vector<Vertex>& shaded_;
  // shaded_'s window x and y snapped, and its clip mask, for a draw of filled triangles by the
  // exact method: each vertex snapped once, not once per triangle; a batch is clip-tested and its
  // triangles culled from these 12 bytes a vertex, and only a triangle that may cover a pixel
  // centre reads its shaded vertices (a million-triangle sphere's 60-byte vertices miss the cache).
  struct SnappedVertex {
    FixedPoint position;
    std::uint32_t clipMask;
  };
  std::vector<SnappedVertex>& snapped_;
  bool snapsVertices_ = !kCourse && isTriangleTopology(state_.topology) && rs_.polygonMode == PolygonMode::Fill;
  std::vector<LineIndices>& lines_;
  [[no_unique_address]] Course course_;  // after viewport_ and region_, which it is made from
};

}  // namespace softraster::detail
