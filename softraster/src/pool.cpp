// ThreadPool (detail/fast/pool.hpp): workers spin briefly, then sleep on a condition variable
// between batches; the CPUID read behind prefetchesForWrite().
#include <softraster/detail/fast/pool.hpp>

#include <chrono>
#if defined(__x86_64__)
#include <cpuid.h>
#include <immintrin.h>
#endif

namespace softraster::detail {

namespace {

// CPUID 0x80000001, ECX bit 8: PREFETCHW (PRFCHW, 3DNowPrefetch).
bool cpuHasPrefetchW() {
#if defined(__x86_64__) && defined(__GNUC__)
  unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
  return __get_cpuid(0x80000001u, &eax, &ebx, &ecx, &edx) != 0 && ((ecx >> 8) & 1u) != 0;
#else
  return false;
#endif
}

}  // namespace

ThreadPool::ThreadPool(unsigned threads) : prefetchesForWrite_(cpuHasPrefetchW()) {
  for (unsigned i = 1; i < threads; ++i) workers_.emplace_back([this] { work(); });
}

ThreadPool::~ThreadPool() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  for (std::thread& t : workers_) t.join();
}

void ThreadPool::drain(const std::function<void(std::size_t)>& task, std::size_t count) {
  for (std::size_t i = next_.fetch_add(1); i < count; i = next_.fetch_add(1)) task(i);
}

template <class Done>
bool ThreadPool::spinUntil(Done&& done) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point end = Clock::now() + std::chrono::nanoseconds(kSpinNanoseconds);
  for (;;) {
    for (int i = 0; i < 64; ++i) {  // the clock is read once per 64 polls
      if (done()) return true;
#if defined(__x86_64__)
      _mm_pause();
#endif
    }
    if (Clock::now() >= end) return done();
  }
}

void ThreadPool::work() {
  std::size_t seen = 0;
  for (;;) {
    const std::function<void(std::size_t)>* task;
    std::size_t count;
    spinUntil([&] { return stopping_.load(std::memory_order_relaxed) || generation_.load(std::memory_order_relaxed) != seen; });
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      task = task_;  // read with the generation, under the lock: this batch's task and size
      count = count_;
      ++busy_;
    }
    if (task != nullptr) drain(*task, count);
    {
      std::lock_guard lock(mutex_);
      --busy_;
    }
    done_.notify_one();
  }
}

void ThreadPool::run(std::size_t count, const std::function<void(std::size_t)>& task) {
  if (workers_.empty() || count <= 1) {
    for (std::size_t i = 0; i < count; ++i) task(i);
    return;
  }
  std::lock_guard serial(runMutex_);  // two draws on one Context from two threads take turns here
  {
    std::lock_guard lock(mutex_);
    task_ = &task;
    count_ = count;
    next_.store(0);
    ++generation_;
  }
  wake_.notify_all();
  drain(task, count);
  spinUntil([&] { return busy_.load(std::memory_order_relaxed) == 0; });
  std::unique_lock lock(mutex_);
  // Every index has been claimed once the caller's drain() returns; wait for the workers still
  // running theirs. A worker that wakes after this finds the task cleared and goes back to sleep.
  done_.wait(lock, [&] { return busy_ == 0; });
  task_ = nullptr;
}

}  // namespace softraster::detail
