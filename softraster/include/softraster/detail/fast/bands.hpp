// BandQueue: the fragment stage the draw loop talks to when the Context has more than one
// thread. It records each set-up primitive (its edges, bounds and interpolants) instead of
// shading it, bins the records into bands of kBandRows rows of the draw region, and then draws
// the bands in parallel (ThreadPool, fast/pool.hpp): each band by one thread, with its own
// fragment stage clipped to the band, replaying its records in submission order.
// Every pixel belongs to exactly one band and sees its primitives in submission order, so the
// output is the same bits whatever the thread count (tests/softraster/fast_path_test.cpp).
// Records are drawn in chunks of kChunk primitives, so memory stays bounded for any draw; the
// records and bins are the Context's scratch (exact/scratch.hpp), so a draw allocates none.
// A clear pending on the framebuffer (Framebuffer::clear) is written by the first chunk, each
// band's rows (full width) by the band's thread just before it draws them; rows outside the
// draw region by the calling thread.
// With no pool (one thread) it forwards every call straight to one stage (whose framebuffer
// access writes a pending clear whole).
// Deliberately absent: square tiles (bands are simpler to bin and balance as well on 2-8 threads),
// a per-tile depth range.
#pragma once

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/scratch.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/fast/pool.hpp>
#include <softraster/detail/fragment/shade.hpp>
#include <softraster/detail/geometry/viewport.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

namespace softraster::detail {

template <class Stage, class Uniforms, int N>
class BandQueue {
 public:
  static constexpr int kBandRows = 32;
  static constexpr std::size_t kChunk = 16384;  // ~3 MB of records: few enough hand-overs to the threads

  BandQueue(ThreadPool* pool, DrawScratch& scratch, const PipelineState& state, const Uniforms& uniforms,
            Framebuffer& framebuffer, const Viewport& viewport, const PixelRect& region, bool inverseZ,
            Deviations deviations = Deviations::Driver)
      : pool_(pool != nullptr && pool->threads() > 1 ? pool : nullptr),
        state_(state),
        uniforms_(uniforms),
        framebuffer_(framebuffer),
        viewport_(viewport),
        region_(region),
        inverseZ_(inverseZ),
        deviations_(deviations),
        records_(scratch.vector<Record>(ScratchSlot::BandRecords)),
        bins_(scratch.vector<std::vector<std::uint32_t>>(ScratchSlot::BandBins)) {
    records_.clear();
    if (pool_ == nullptr) direct_.emplace(state, uniforms, framebuffer, viewport, region, inverseZ, deviations);
  }

  template <int E>
  void shadePixels(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) {
    if (direct_) {
      direct_->shadePixels(edges, bounds, t);
      return;
    }
    Record& r = records_.emplace_back();
    r.kind = E == 3 ? Kind::Triangle : Kind::Quad;
    std::copy(edges, edges + E, r.edges);
    r.bounds = bounds;
    r.interpolants = t;
    if (records_.size() == kChunk) flush();
  }

  void shadeSamples(const EdgeFunction (&edges)[3], const PixelRect& bounds, const TriangleInterpolants<N>& t) {
    if (direct_) {
      direct_->shadeSamples(edges, bounds, t);
      return;
    }
    Record& r = records_.emplace_back();
    r.kind = Kind::SampledTriangle;
    std::copy(edges, edges + 3, r.edges);
    r.bounds = bounds;
    r.interpolants = t;
    if (records_.size() == kChunk) flush();
  }

  // Draws what is still recorded; call once at the end of the draw.
  void finish() {
    if (!direct_ && (!records_.empty() || framebuffer_.clearPending())) flush();
  }

 private:
  enum class Kind : std::uint8_t { Triangle, Quad, SampledTriangle };
  struct Record {
    Kind kind;
    EdgeFunction edges[4];
    PixelRect bounds;
    TriangleInterpolants<N> interpolants;
  };

  void flush() {
    const int bands = (region_.y1 - region_.y0) / kBandRows + 1;
    bins_.resize(static_cast<std::size_t>(bands));
    for (auto& bin : bins_) bin.clear();
    for (std::size_t i = 0; i < records_.size(); ++i) {
      const PixelRect box = intersect(records_[i].bounds, region_);
      if (box.empty()) continue;
      const int first = (box.y0 - region_.y0) / kBandRows, last = (box.y1 - region_.y0) / kBandRows;
      for (int b = first; b <= last; ++b) bins_[static_cast<std::size_t>(b)].push_back(static_cast<std::uint32_t>(i));
    }
    const std::optional<Framebuffer::PendingClear> clear = framebuffer_.takePendingClear();
    if (clear) {  // the rows no band covers
      if (region_.y0 > 0) framebuffer_.clearRows(*clear, 0, static_cast<std::uint32_t>(region_.y0 - 1));
      framebuffer_.clearRows(*clear, static_cast<std::uint32_t>(region_.y1 + 1), framebuffer_.height() - 1);
    }
    pool_->run(static_cast<std::size_t>(bands), [this, &clear](std::size_t band) {
      if (clear) {
        const PixelRect rows = bandRows(band);
        framebuffer_.clearRows(*clear, static_cast<std::uint32_t>(rows.y0), static_cast<std::uint32_t>(rows.y1));
      }
      drawBand(band);
    });
    records_.clear();
  }

  // The draw region's rows of one band.
  PixelRect bandRows(std::size_t band) const {
    PixelRect rows = region_;
    rows.y0 = region_.y0 + static_cast<int>(band) * kBandRows;
    rows.y1 = std::min(region_.y1, rows.y0 + kBandRows - 1);
    return rows;
  }

  // One band's records, drawn by the calling thread. The band task is reached through
  // std::function, outside the Context's flattened entry point, so it is compiled for the
  // stage's instruction set and flattened here again.
  void drawBand(std::size_t band) const { callCompiledFor<Stage::kInstructionSet, &BandQueue::replay>(*this, band); }

  void replay(std::size_t band) const {
    const std::vector<std::uint32_t>& bin = bins_[band];
    if (bin.empty()) return;
    const Stage stage(state_, uniforms_, framebuffer_, viewport_, bandRows(band), inverseZ_, deviations_);
    for (const std::uint32_t i : bin) {
      const Record& r = records_[i];
      const EdgeFunction triangle[3] = {r.edges[0], r.edges[1], r.edges[2]};
      switch (r.kind) {
        case Kind::Triangle: stage.shadePixels(triangle, r.bounds, r.interpolants); break;
        case Kind::Quad: stage.shadePixels(r.edges, r.bounds, r.interpolants); break;
        case Kind::SampledTriangle: stage.shadeSamples(triangle, r.bounds, r.interpolants); break;
      }
    }
  }

  ThreadPool* pool_;
  const PipelineState& state_;
  const Uniforms& uniforms_;
  Framebuffer& framebuffer_;
  Viewport viewport_;
  PixelRect region_;
  bool inverseZ_;
  Deviations deviations_;
  std::optional<Stage> direct_;
  std::vector<Record>& records_;                    // the Context's scratch, kept between draws
  std::vector<std::vector<std::uint32_t>>& bins_;   // (bins keep their capacity too)
};

}  // namespace softraster::detail
