// BandQueue: the fragment stage the draw loop talks to when the Context has more than one
// thread. The draw loop's front end hands it each set-up primitive (its edges, bounds and
// interpolants) through a Recorder; the queue keeps the primitive as a record instead of shading
// it, binned into the bands of kBandRows rows (at multiples of it) it touches, and at the end of
// each round of primitives draws the bands in parallel (ThreadPool, fast/pool.hpp): each band by
// one thread, with its own fragment stage clipped to the band, replaying its records in
// submission order.
// The front end itself may run on several threads (exact/draw.hpp): within a round, front-end
// worker k records into list k, its own records and bins, and a band replays list 0's records,
// then list 1's, and so on; worker k's primitives come after worker k-1's in the draw, so that is
// submission order. Every pixel belongs to exactly one band and sees its primitives in submission
// order, so the output is the same bits whatever the thread count (tests/crosscheck/fast_path_test.cpp).
// Rounds are bounded by the draw loop (kMaxRoundPrimitives there), so memory stays bounded for any
// draw; the records and bins are the Context's scratch (exact/scratch.hpp), so a draw allocates none.
// In a pass (softraster/pass.hpp, fast/deferred_draws.hpp) the draw is deferred instead: its
// records, with copies of its state and uniforms, go into the pass's slot for it (a BandQueue::Draw),
// and the pass draws the bands of all its draws at once; the queue then draws nothing itself
// but asks the pass to, once the pass's records pass its budget. A deferred draw opens a band's
// depth tiles (fast/depth_tiles.hpp) just before it draws there, not all of them at its start.
// A clear pending on the framebuffer (Framebuffer::clear) is written by the first round, each
// band's rows (full width) by the band's thread just before it draws them; rows outside the
// draw region by the calling thread.
// The pool's task k draws the k-th of equal runs of bands first, then helps with the others'
// (drawBandsInParallel, fast/deferred_draws.hpp), so the same rows tend to stay in the same
// core's cache draw after draw. A band asks for the
// colour and depth lines of its next small primitive while it draws the one before; a recorder
// asks for the lines of the record it will write a few records on, for writing (PREFETCHW).
// With no pool (one thread) every Recorder forwards its calls straight to one stage (whose
// framebuffer access writes a pending clear whole).
// Bands lie at multiples of kBandRows rows, so each 32x32 tile of depth bounds
// (fast/depth_tiles.hpp) is drawn by one band's thread.
// Deliberately absent: square tiles for binning (bands are simpler to bin and balance as well on
// 2-8 threads).
#pragma once

#include <softraster/detail/exact/interpolation.hpp>
#include <softraster/detail/exact/scratch.hpp>
#include <softraster/detail/exact/triangle_setup.hpp>
#include <softraster/detail/fast/deferred_draws.hpp>
#include <softraster/detail/fast/depth_tiles.hpp>
#include <softraster/detail/fast/pool.hpp>
#include <softraster/detail/fragment/shade.hpp>
#include <softraster/detail/geometry/viewport.hpp>
#include <softraster/framebuffer.hpp>
#include <softraster/options.hpp>
#include <softraster/state.hpp>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <type_traits>
#include <vector>

namespace softraster::detail {

// Asks for the cache lines of [p, p + bytes) with the intent to write them (PREFETCHW: only where
// ThreadPool::prefetchesForWrite says the CPU has it).
inline void prefetchForWrite([[maybe_unused]] const void* p, [[maybe_unused]] std::size_t bytes) {
#if defined(__x86_64__) && defined(__GNUC__)
  const char* bytesAt = static_cast<const char*>(p);
  for (std::size_t at = 0; at < bytes; at += 64) asm volatile("prefetchw %0" : : "m"(bytesAt[at]));
#endif
}

// Asks for the cache lines of [p, p + bytes), to read them.
inline void prefetchForRead(const void* p, std::size_t bytes) {
  const char* bytesAt = static_cast<const char*>(p);
  for (std::size_t at = 0; at < bytes; at += 64) __builtin_prefetch(bytesAt + at, 0);
}

template <class Stage, class Uniforms, int N>
class BandQueue {
  enum class Kind : std::uint8_t { Triangle, Quad, SampledTriangle, SampledQuad, BroadcastQuad };
  // On whole cache lines: with four varyings a record is three lines, where packed at 200 bytes it
  // touched four or five (the kind and planes sit in the interpolants' tail padding), and a
  // million small triangles' records are written on one core and read on the other.
  struct alignas(64) Record {
    // Built in place from the set-up primitive, each field written once (no zeroing first); a
    // triangle leaves edges[3] unset, and nothing reads it.
    template <int E>
    Record(Kind k, const EdgeFunction (&e)[E], const PixelRect& b, const TriangleInterpolants<N>& t, unsigned planes)
        : bounds(b), interpolants(t), kind(k), regionPlanes(static_cast<std::uint8_t>(planes)) {
      std::copy(e, e + E, edges);
    }
    EdgeFunction edges[4];
    PixelRect bounds;
    [[no_unique_address]] TriangleInterpolants<N> interpolants;
    Kind kind;
    std::uint8_t regionPlanes;  // sampled kinds: MsaaRegionEdges::allowedSamples' planes
  };
  static_assert(N != 4 || sizeof(Record) == 192, "four varyings' record: three cache lines");
  // One front-end worker's records and their bins (per band: indices into records), on cache
  // lines of its own: the vectors' end pointers move with every record, and two workers
  // recording at once must not write the same line (false sharing cost more than the second
  // thread gained on a million small triangles).
  struct alignas(64) List {
    std::vector<Record> records;
    std::vector<std::vector<std::uint32_t>> bins;
  };

 public:
  static constexpr int kBandRows = detail::kBandRows;
  static_assert(kBandRows % kDepthTileSize == 0, "a depth tile (fast/depth_tiles.hpp) lies in one band");
  // Front-end workers per thread: more lists than threads, so a round's work is shared out
  // evenly when some parts of the draw cost more than others (clipping, culled runs).
  static constexpr unsigned kListsPerThread = 4;
  // A draw is deferred into a pass with a copy of its uniforms.
  static constexpr bool kDeferrable = std::is_copy_constructible_v<Uniforms>;
  static constexpr bool kStageKeepsDepthTiles = [] {
    if constexpr (requires { Stage::kKeepsDepthTiles; }) return Stage::kKeepsDepthTiles;
    return false;
  }();

  // One draw's records and what its bands need to draw them: the caller's state and uniforms
  // (drawn before the draw returns), or in a pass (deferred) copies of them, kept until the pass
  // draws it; its lists are the Context's scratch, or the pass's draw slot's own.
  class Draw final : public RecordedDraw {
   public:
    Draw() = default;
    Draw(const Draw&) = delete;
    Draw& operator=(const Draw&) = delete;

    void set(std::vector<List>& lists, unsigned workers, bool deferred, const PipelineState& state,
             const Uniforms& uniforms, Framebuffer& framebuffer, const Viewport& viewport, const PixelRect& region,
             bool inverseZ, const ContextOptions& options, bool prefetchesForWrite) {
      lists_ = &lists;
      deferred_ = deferred;
      if constexpr (kDeferrable) {
        if (deferred) {
          ownState_ = state;
          ownUniforms_.emplace(uniforms);
          state_ = &*ownState_;
          uniforms_ = &*ownUniforms_;
        }
      }
      if (!deferred) {
        state_ = &state;
        uniforms_ = &uniforms;
      }
      framebuffer_ = &framebuffer;
      viewport_ = viewport;
      region_ = region;
      inverseZ_ = inverseZ;
      options_ = options;
      firstBand_ = region.empty() ? 0 : floorDiv(region.y0, kBandRows);
      bands_ = region.empty() ? 0 : floorDiv(region.y1, kBandRows) - firstBand_ + 1;
      prefetchesForWrite_ = prefetchesForWrite;
      lists.resize(workers);
      for (List& list : lists) {
        list.records.clear();
        list.bins.resize(static_cast<std::size_t>(bands_));
        for (auto& bin : list.bins) bin.clear();
      }
    }

    int bands() const { return bands_; }
    const PixelRect& region() const { return region_; }
    std::size_t records() const {
      std::size_t records = 0;
      for (const List& list : *lists_) records += list.records.size();
      return records;
    }

    template <int E>
    void record(unsigned list, Kind kind, const EdgeFunction (&edges)[E], const PixelRect& bounds,
                const TriangleInterpolants<N>& t, unsigned regionPlanes) {
      const PixelRect box = intersect(bounds, region_);
      if (box.empty()) return;  // no band would draw it
      List& l = (*lists_)[list];
      std::vector<Record>& records = l.records;
      const auto index = static_cast<std::uint32_t>(records.size());
      // The lines a record a few ahead will take were last read by the thread that drew its band,
      // maybe on the other core: ask for them now, for writing (without, a million small triangles
      // spent four tenths of the front end's time waiting on the first store to a new record).
      if (prefetchesForWrite_ && index + kRecordsAhead < records.capacity()) {
        prefetchForWrite(records.data() + index + kRecordsAhead, sizeof(Record));
      }
      records.emplace_back(kind, edges, bounds, t, regionPlanes);
      const int first = floorDiv(box.y0, kBandRows) - firstBand_, last = floorDiv(box.y1, kBandRows) - firstBand_;
      for (int b = first; b <= last; ++b) l.bins[static_cast<std::size_t>(b)].push_back(index);
    }

    // The draw region's rows of one of its bands.
    PixelRect bandRows(std::size_t band) const {
      PixelRect rows = region_;
      const int y0 = (firstBand_ + static_cast<int>(band)) * kBandRows;
      rows.y0 = std::max(region_.y0, y0);
      rows.y1 = std::min(region_.y1, y0 + kBandRows - 1);
      return rows;
    }

    // One of this draw's bands (counted from its first), drawn by the calling thread. The band
    // task is reached through std::function, outside the Context's flattened entry point, so it
    // is compiled for the stage's instruction set and flattened here again.
    void drawBand(std::size_t band) const { callCompiledFor<Stage::kInstructionSet, &Draw::replay>(*this, band); }

    // RecordedDraw, for a pass: `band` counts from the framebuffer's first row. Before the
    // draw's first record there, the band's depth tiles are opened for it (fast/depth_tiles.hpp),
    // as a draw on its own opens them all when it starts.
    void replayBand(int band) const override {
      const int local = band - firstBand_;
      if (local < 0 || local >= bands_) return;
      bool any = false;
      for (const List& list : *lists_) any = any || !list.bins[static_cast<std::size_t>(local)].empty();
      if (!any) return;
      if (deferred_ && kStageKeepsDepthTiles && !inverseZ_) {
        const PixelRect rows = bandRows(static_cast<std::size_t>(local));
        fast::prepareDepthTileRows(*framebuffer_, state_->depth, rows.y0, rows.y1);
      }
      drawBand(static_cast<std::size_t>(local));
    }
    std::size_t recordBytes() const override { return records() * sizeof(Record); }
    void clearRecords() override {
      for (List& list : *lists_) {
        list.records.clear();
        for (auto& bin : list.bins) bin.clear();
      }
    }

   private:
    static constexpr std::size_t kRecordsAhead = 8;  // how far ahead a recorder asks for a record's lines

    void replay(std::size_t band) const {
      std::optional<Stage> stage;  // made when the band has something to draw
      const Pixels pixels = pixelsToPrefetch(*framebuffer_);  // any pending clear is taken by now
      const PixelRect rows = bandRows(band);
      for (const List& list : *lists_) {
        const std::vector<std::uint32_t>& bin = list.bins[band];
        if (bin.empty()) continue;
        if (!stage) stage.emplace(*state_, *uniforms_, *framebuffer_, viewport_, rows, inverseZ_, options_);
        const std::vector<Record>& records = list.records;
        for (std::size_t k = 0; k < bin.size(); ++k) {
          // A record was written by a front-end worker, often on the other core: ask for the one
          // two ahead, so that its lines have arrived when the next record's pixels are asked for
          // (20k small triangles spent half the replay's own time on the first read of a record).
          if (k + 2 < bin.size()) prefetchForRead(&records[bin[k + 2]], sizeof(Record));
          if (k + 1 < bin.size()) prefetchPixels(pixels, framebuffer_->width(), records[bin[k + 1]].bounds, rows);
          const Record& r = records[bin[k]];
          const EdgeFunction triangle[3] = {r.edges[0], r.edges[1], r.edges[2]};
          switch (r.kind) {
            case Kind::Triangle: stage->shadePixels(triangle, r.bounds, r.interpolants); break;
            case Kind::Quad: stage->shadePixels(r.edges, r.bounds, r.interpolants); break;
            case Kind::SampledTriangle: stage->shadeSamples(triangle, r.bounds, r.interpolants); break;
            case Kind::SampledQuad: stage->shadeSamples(r.edges, r.bounds, r.interpolants, r.regionPlanes); break;
            case Kind::BroadcastQuad: stage->shadeBroadcast(r.edges, r.bounds, r.interpolants); break;
          }
        }
      }
    }

    std::vector<List>* lists_ = nullptr;
    bool deferred_ = false;
    std::optional<PipelineState> ownState_;
    std::optional<Uniforms> ownUniforms_;
    const PipelineState* state_ = nullptr;
    const Uniforms* uniforms_ = nullptr;
    Framebuffer* framebuffer_ = nullptr;
    Viewport viewport_{};
    PixelRect region_{};
    bool inverseZ_ = false;
    ContextOptions options_{};  // the Context's (deviations, allowAvx512), for the bands' stages
    int firstBand_ = 0;  // bands lie at multiples of kBandRows rows (as the depth tiles do): this one holds the region's first row
    int bands_ = 0;
    bool prefetchesForWrite_ = false;
    std::vector<List> ownLists_;  // a deferred draw's own (a pass's slot keeps it, and its capacity, between passes)
    friend class BandQueue;
  };

  // pass: a pass that may defer this draw (nullptr: drawn before the draw returns). A deferred
  // draw's state and uniforms are copied; its records wait for the pass's flush.
  BandQueue(ThreadPool* pool, DrawScratch& scratch, const PipelineState& state, const Uniforms& uniforms,
            Framebuffer& framebuffer, const Viewport& viewport, const PixelRect& region, bool inverseZ,
            const ContextOptions& options = {}, PassRecording* pass = nullptr)
      : pool_(pool != nullptr && pool->threads() > 1 ? pool : nullptr),
        framebuffer_(framebuffer),
        scratch_(scratch) {
    if (pool_ == nullptr) {
      direct_.emplace(state, uniforms, framebuffer, viewport, region, inverseZ, options);
      pixels_ = pixelsToPrefetch(framebuffer);
      region_ = region;
      return;
    }
    if (pass != nullptr && pass->drawsInto(framebuffer) && !kDeferrable) pass->flush();  // drawn now, so after them
    if (kDeferrable && pass != nullptr && pass->drawsInto(framebuffer)) {
      pass_ = pass;
      draw_ = &pass->beginDraw<Draw>();
      draw_->set(draw_->ownLists_, workers(), true, state, uniforms, framebuffer, viewport, region, inverseZ, options,
                 pool_->prefetchesForWrite());
    } else {
      draw_ = &own_;
      own_.set(scratch.vector<List>(ScratchSlot::BandLists), workers(), false, state, uniforms, framebuffer, viewport,
               region, inverseZ, options, pool_->prefetchesForWrite());
    }
  }
  BandQueue(const BandQueue&) = delete;
  BandQueue& operator=(const BandQueue&) = delete;
  ~BandQueue() {
    if (pass_ != nullptr) pass_->endDraw();
  }

  // Whether the draw is deferred into a pass (its depth tiles are then opened band by band).
  bool deferred() const { return pass_ != nullptr; }

  // Where one front-end worker's set-up primitives go: the same calls as a fragment stage.
  class Recorder {
   public:
    Recorder(BandQueue& queue, unsigned list) : queue_(queue), list_(list) {}

    template <int E>
    void shadePixels(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t) {
      if (queue_.direct_) {
        queue_.direct_->shadePixels(edges, bounds, t);
      } else {
        queue_.draw_->record(list_, E == 3 ? Kind::Triangle : Kind::Quad, edges, bounds, t, 0);
      }
    }

    template <int E>
    void shadeSamples(const EdgeFunction (&edges)[E], const PixelRect& bounds, const TriangleInterpolants<N>& t,
                      unsigned regionPlanes = MsaaRegionEdges::kBothPlanes) {
      if (queue_.direct_) {
        queue_.direct_->shadeSamples(edges, bounds, t, regionPlanes);
      } else {
        queue_.draw_->record(list_, E == 3 ? Kind::SampledTriangle : Kind::SampledQuad, edges, bounds, t, regionPlanes);
      }
    }

    void shadeBroadcast(const EdgeFunction (&edges)[4], const PixelRect& bounds, const TriangleInterpolants<N>& t) {
      if (queue_.direct_) {
        queue_.direct_->shadeBroadcast(edges, bounds, t);
      } else {
        queue_.draw_->record(list_, Kind::BroadcastQuad, edges, bounds, t, 0);
      }
    }

   private:
    BandQueue& queue_;
    unsigned list_;
  };

  // The threads (nullptr: everything on the calling thread, straight to one stage).
  ThreadPool* pool() const { return pool_; }
  // How many recorders a round may use (list k is recorder k's).
  unsigned workers() const { return pool_ != nullptr ? pool_->threads() * kListsPerThread : 1; }
  Recorder recorder(unsigned list) { return Recorder(*this, list); }

  // With no pool: asks for the cache lines of a small primitive about to be drawn (the front end
  // calls it before the primitive's setup, which then hides part of the wait). The bands do
  // this themselves, one primitive ahead.
  void prefetch(const PixelRect& bounds) const {
    if (direct_) prefetchPixels(pixels_, framebuffer_.width(), bounds, region_);
  }

  // The front end calls it between rounds and once at the end of the draw: draws what the
  // recorders recorded in this round, or, deferred, the pass's draws once their records pass
  // the pass's budget. Returns the bytes of records the round kept (the draw loop sizes its
  // next round by them).
  std::size_t endRound() {
    if (direct_) return 0;
    const std::size_t records = draw_->records(), round = records - recordsBefore_;
    recordsBefore_ = records;
    if (pass_ != nullptr) {
      if (pass_->recordBytes() >= PassRecording::kFlushBytes) {
        pass_->flush();
        recordsBefore_ = 0;
      }
    } else if (records != 0 || framebuffer_.clearPending()) {
      flush();
      recordsBefore_ = 0;
    }
    return round * sizeof(Record);
  }

 private:
  void flush() {
    const std::optional<Framebuffer::PendingClear> clear = framebuffer_.takePendingClear();
    const PixelRect& region = own_.region();
    if (clear) {  // the rows no band covers
      if (region.y0 > 0) framebuffer_.clearRows(*clear, 0, static_cast<std::uint32_t>(region.y0 - 1));
      framebuffer_.clearRows(*clear, static_cast<std::uint32_t>(region.y1 + 1), framebuffer_.height() - 1);
    }
    // The pool's task k owns the k-th of `threads` equal runs of bands and draws them first, in
    // order; then it takes what is left of the other runs, band by band, from each run's own
    // counter. The calling thread mostly takes task 0, so the same thread tends to draw the same
    // rows draw after draw, and they stay in its cache
    // (drawn by whichever thread came first, 20k small triangles in 10 draws took twice the CPU
    // time at 2 threads as at 1); taking from the others keeps the threads busy when the runs
    // cost unequal amounts. Which thread draws a band never changes the band's pixels.
    std::vector<BandCursor>& cursors = scratch_.vector<BandCursor>(ScratchSlot::BandCursors);
    cursors.resize(pool_->threads());
    drawBandsInParallel(*pool_, static_cast<std::size_t>(own_.bands()), cursors, [this, &clear](std::size_t band) {
      if (clear) {
        const PixelRect rows = own_.bandRows(band);
        framebuffer_.clearRows(*clear, static_cast<std::uint32_t>(rows.y0), static_cast<std::uint32_t>(rows.y1));
      }
      own_.drawBand(band);
    });
    own_.clearRecords();
  }

  // The framebuffer's pixels for prefetchPixels, single-sample only (else null), taken where
  // reading them cannot write a pending clear: after the direct stage's construction has written
  // it, or in a band once the bands have taken it over.
  struct Pixels {
    const std::uint8_t* colour = nullptr;
    const std::uint32_t* depth = nullptr;
  };
  static Pixels pixelsToPrefetch(Framebuffer& framebuffer) {
    if (framebuffer.samples() != 1) return {};
    return {framebuffer.colour().data(), FramebufferAccess::depthWords(framebuffer)};
  }

  // Asks for the cache lines of colour and depth a small primitive's box covers inside `rows`
  // (single-sample only), so that they arrive while the primitive before it is drawn: a box of a
  // few pixels anywhere in a large frame otherwise waits on memory for every row it touches.
  static void prefetchPixels(const Pixels& pixels, std::size_t width, const PixelRect& bounds, const PixelRect& rows) {
    const PixelRect box = intersect(bounds, rows);
    if (box.empty() || box.y1 - box.y0 >= kPrefetchRows || box.x1 - box.x0 >= kPrefetchColumns || pixels.colour == nullptr) return;
    for (int y = box.y0; y <= box.y1; ++y) {
      const std::size_t first = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(box.x0);
      const std::size_t last = static_cast<std::size_t>(y) * width + static_cast<std::size_t>(box.x1);
      __builtin_prefetch(pixels.depth + first, 1);
      __builtin_prefetch(pixels.depth + last, 1);
      __builtin_prefetch(pixels.colour + 4 * first, 1);
      __builtin_prefetch(pixels.colour + 4 * last, 1);
    }
  }
  static constexpr int kPrefetchRows = 16, kPrefetchColumns = 16;  // "small": a box under both

  static int floorDiv(int a, int b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }

  ThreadPool* pool_;
  Framebuffer& framebuffer_;
  std::optional<Stage> direct_;
  Pixels pixels_;     // direct_'s
  PixelRect region_;  // direct_'s
  Draw own_;          // a draw not deferred: its records, drawn round by round
  Draw* draw_ = nullptr;  // &own_, or the pass's slot
  PassRecording* pass_ = nullptr;
  std::size_t recordsBefore_ = 0;  // the draw's records at the end of the last round
  DrawScratch& scratch_;
};

}  // namespace softraster::detail
