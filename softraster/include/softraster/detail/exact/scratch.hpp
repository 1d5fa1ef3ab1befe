// DrawScratch: the vectors a draw fills and empties (shaded vertices, assembled lines, the
// band queue's records and bins, a non-indexed draw's index sequence), kept between draws so that
// a steady-state draw allocates nothing: each vector keeps its capacity for the next draw that
// asks for the same slot and element type. ScratchPool is the Context's store of them: a draw
// leases one for its duration, so draws from several threads on one Context never share one.
// Deliberately no size limit or trimming: a scratch holds what the largest draw of its kind
// needed, as a framebuffer holds its samples.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <typeindex>
#include <typeinfo>
#include <vector>

namespace softraster::detail {

// CourseRows: the course's scanline method's per-row left/right arrays (course/scanline.hpp);
// SnappedVertices: each shaded vertex's window position in fixed point (exact/draw.hpp).
enum class ScratchSlot : std::uint8_t {
  IndexSequence,
  ShadedVertices,
  SnappedVertices,
  Lines,
  BandLists,
  BandCursors,
  CourseRows
};

class DrawScratch {
 public:
  // The vector of `slot` with elements T, as the last draw that used it left it (its user
  // clears or resizes it; a vector of vectors keeps the inner vectors' capacity too).
  template <class T>
  std::vector<T>& vector(ScratchSlot slot) {
    for (Entry& e : entries_) {
      if (e.slot == slot && e.type == std::type_index(typeid(T))) return static_cast<Typed<T>&>(*e.holder).values;
    }
    auto holder = std::make_unique<Typed<T>>();
    std::vector<T>& v = holder->values;
    entries_.push_back({slot, std::type_index(typeid(T)), std::move(holder)});
    return v;
  }

 private:
  struct Holder {
    virtual ~Holder() = default;
  };
  template <class T>
  struct Typed final : Holder {
    std::vector<T> values;
  };
  struct Entry {
    ScratchSlot slot;
    std::type_index type;
    std::unique_ptr<Holder> holder;
  };
  std::vector<Entry> entries_;
};

class ScratchPool {
 public:
  // A scratch for one draw, given back when the lease ends.
  class Lease {
   public:
    Lease(ScratchPool& pool, std::unique_ptr<DrawScratch> scratch) : pool_(pool), scratch_(std::move(scratch)) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() { pool_.giveBack(std::move(scratch_)); }
    DrawScratch& operator*() const { return *scratch_; }

   private:
    ScratchPool& pool_;
    std::unique_ptr<DrawScratch> scratch_;
  };

  Lease lease() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (free_.empty()) return Lease(*this, std::make_unique<DrawScratch>());
    std::unique_ptr<DrawScratch> scratch = std::move(free_.back());
    free_.pop_back();
    return Lease(*this, std::move(scratch));
  }

 private:
  void giveBack(std::unique_ptr<DrawScratch> scratch) {
    std::lock_guard<std::mutex> lock(mutex_);
    free_.push_back(std::move(scratch));
  }

  std::mutex mutex_;
  std::vector<std::unique_ptr<DrawScratch>> free_;
};

}  // namespace softraster::detail
