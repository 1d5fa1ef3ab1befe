// Deferred draws: what lets a pass (softraster/pass.hpp) draw many draws in one sweep of the
// bands, as lavapipe bins a whole render pass before it rasterizes a tile.
//   - RecordedDraw: one draw's set-up primitives, binned into bands of kBandRows rows (at
//     multiples of it from row 0), replayed band by band (fast/bands.hpp's BandQueue::Draw).
//   - drawBandsInParallel: bands shared out among the pool's threads, the batch's task k first
//     drawing the k-th of equal runs of bands, then helping with the others'. The pool hands its
//     tasks out first come, first served, and the calling thread, which starts the batch, mostly
//     takes task 0, so the same rows tend to stay in the same core's cache (binding task k to
//     thread k measured no faster: docs/architecture.md).
//   - PassRecording: a pass's draws, in submission order, kept until flush() draws every band of
//     every one of them: per band, draw after draw, so every pixel still sees its primitives in
//     submission order and the output is the same bits as drawing them one by one.
// A flush runs when the pass ends, when a draw that cannot be deferred comes, and when the kept
// records pass kFlushBytes (so memory stays bounded for any pass). Draw slots are kept from one
// pass to the next and reused by a draw of the same type, so a steady-state pass allocates nothing.
// Deliberately absent: square tiles (as bands.hpp), reordering draws, dropping a draw hidden by a
// later one.
#pragma once

#include <softraster/detail/fast/pool.hpp>
#include <softraster/framebuffer.hpp>

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace softraster::detail {

inline constexpr int kBandRows = 32;

// One draw's records, as the bands replay them.
class RecordedDraw {
 public:
  virtual ~RecordedDraw() = default;
  // Draws this draw's records in band `band` (rows [band * kBandRows, band * kBandRows +
  // kBandRows - 1] of the framebuffer), on the calling thread.
  virtual void replayBand(int band) const = 0;
  virtual std::size_t recordBytes() const = 0;
  virtual void clearRecords() = 0;
};

// The next band of one thread's run, on a cache line of its own (a std::atomic_ref: cursors
// sit in vectors that are resized).
struct alignas(64) BandCursor {
  alignas(std::atomic_ref<std::size_t>::required_alignment) std::size_t next = 0;
};

// drawBand(band) for every band in [0, bands), on the pool's threads, task k taking run k first
// (see the top comment); cursors: at least pool.threads() of them.
template <class DrawBand>
void drawBandsInParallel(ThreadPool& pool, std::size_t bands, std::vector<BandCursor>& cursors, DrawBand&& drawBand) {
  const std::size_t threads = pool.threads();
  const auto runEnd = [threads, bands](std::size_t k) { return (k + 1) * bands / threads; };
  for (std::size_t k = 0; k < threads; ++k) cursors[k].next = k * bands / threads;
  pool.run(threads, [&](std::size_t k) {
    for (std::size_t j = 0; j < threads; ++j) {
      const std::size_t run = (k + j) % threads;  // its own run first
      std::atomic_ref<std::size_t> next(cursors[run].next);
      for (std::size_t band = next.fetch_add(1); band < runEnd(run); band = next.fetch_add(1)) {
        drawBand(band);
      }
    }
  });
}

class PassRecording {
 public:
  // A flush when the kept records pass this: they are written on one core and read on another,
  // best from the last-level cache (exact/draw.hpp's rounds aim at 12 MB too).
  static constexpr std::size_t kFlushBytes = std::size_t{12} << 20;

  explicit PassRecording(ThreadPool& pool) : pool_(pool), cursors_(pool.threads()) {}
  PassRecording(const PassRecording&) = delete;
  PassRecording& operator=(const PassRecording&) = delete;

  // A pass on `framebuffer` starts; finish() draws what it kept and ends it (a pass keeps no
  // pointer to a framebuffer after it: the framebuffer may go).
  void start(Framebuffer& framebuffer) {
    finish();
    framebuffer_ = &framebuffer;
  }
  void finish() {
    flush();
    framebuffer_ = nullptr;
  }
  bool drawsInto(const Framebuffer& framebuffer) const { return framebuffer_ == &framebuffer; }

  // The slot of the next draw, of type Draw: the one this position held in an earlier pass when
  // it has that type (its vectors' capacity kept), else a new one. The draw is open until
  // endDraw(); a flush meanwhile keeps it (its later records come after).
  template <class Draw>
  Draw& beginDraw() {
    if (used_ == draws_.size()) draws_.emplace_back();
    std::unique_ptr<RecordedDraw>& slot = draws_[used_++];
    Draw* draw = dynamic_cast<Draw*>(slot.get());
    if (draw == nullptr) {
      slot = std::make_unique<Draw>();
      draw = static_cast<Draw*>(slot.get());
    }
    drawing_ = true;
    return *draw;
  }
  void endDraw() { drawing_ = false; }

  std::size_t recordBytes() const {
    std::size_t bytes = 0;
    for (std::size_t d = 0; d < used_; ++d) bytes += draws_[d]->recordBytes();
    return bytes;
  }

  // Draws every recorded draw (and writes a pending clear), then forgets them but the open one.
  void flush() {
    if (framebuffer_ == nullptr) return;
    Framebuffer& framebuffer = *framebuffer_;
    if (recordBytes() != 0 || framebuffer.clearPending()) {
      const std::optional<Framebuffer::PendingClear> clear = framebuffer.takePendingClear();
      const std::uint32_t height = framebuffer.height();
      const std::size_t bands = (height + kBandRows - 1) / kBandRows;
      drawBandsInParallel(pool_, bands, cursors_, [&](std::size_t band) {
        if (clear) {
          const auto y0 = static_cast<std::uint32_t>(band) * kBandRows;
          framebuffer.clearRows(*clear, y0, std::min(height, y0 + kBandRows) - 1);
        }
        for (std::size_t d = 0; d < used_; ++d) draws_[d]->replayBand(static_cast<int>(band));
      });
    }
    for (std::size_t d = 0; d < used_; ++d) draws_[d]->clearRecords();
    if (drawing_ && used_ > 1) std::swap(draws_[0], draws_[used_ - 1]);  // the open draw goes on first
    used_ = drawing_ ? 1 : 0;
  }

 private:
  ThreadPool& pool_;
  Framebuffer* framebuffer_ = nullptr;
  std::vector<BandCursor> cursors_;
  std::vector<std::unique_ptr<RecordedDraw>> draws_;  // [0, used_): this pass's, in order; the rest kept for reuse
  std::size_t used_ = 0;
  bool drawing_ = false;  // draws_[used_ - 1] is still recording
};

}  // namespace softraster::detail
