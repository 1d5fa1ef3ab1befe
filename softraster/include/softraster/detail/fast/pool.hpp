// ThreadPool: the worker threads a Context owns (ContextOptions::threads). run(n, task) calls
// task(0..n-1), each index exactly once, spread over the workers and the calling thread, and
// returns when all are done. Tasks claim indices in order from one counter, so which thread runs
// which index varies from run to run: a task must depend on nothing but its index (the band
// queue gives each index its own pixels, so the output never depends on the thread count).
// Between batches a worker spins for a short while (kSpinNanoseconds) before it sleeps, and so
// does the caller waiting for the last workers: a draw runs its batches back to back (a round's
// front end, then its bands, then the next round's front end), and waking a sleeping thread cost
// more than a round of a million-triangle draw gained from it (a futex wake and a reschedule,
// tens of microseconds on a virtual machine); a wait longer than the spin sleeps as before.
// The pool also says whether the CPU has PREFETCHW (CPUID, read once when the pool is made), for
// the band queue's records.
// Deliberately no futures, no priorities, no work stealing: one batch of tasks at a time.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace softraster::detail {

class ThreadPool {
 public:
  // threads: how many threads run tasks, the caller's included (so 1 starts no worker).
  explicit ThreadPool(unsigned threads);
  ~ThreadPool();
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  unsigned threads() const { return static_cast<unsigned>(workers_.size()) + 1; }
  // Whether the CPU has PREFETCHW (fast/bands.hpp asks for its records' lines with it), asked
  // once, when the pool is made.
  bool prefetchesForWrite() const { return prefetchesForWrite_; }

  // Runs task(i) for i in [0, count); returns when every call has returned. Calls from several
  // threads take turns; a task must not call run() itself.
  void run(std::size_t count, const std::function<void(std::size_t)>& task);

 private:
  void work();
  void drain(const std::function<void(std::size_t)>& task, std::size_t count);

  // Spins until done() is true or the spin's time is up; returns done().
  template <class Done>
  static bool spinUntil(Done&& done);

  static constexpr long kSpinNanoseconds = 50'000;

  bool prefetchesForWrite_;
  std::vector<std::thread> workers_;
  std::mutex runMutex_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(std::size_t)>* task_ = nullptr;
  std::size_t count_ = 0;
  std::atomic<std::size_t> next_{0};
  // Written under mutex_; atomic so that a spinning thread may read them without it.
  std::atomic<unsigned> busy_{0};             // workers inside the current batch
  std::atomic<std::size_t> generation_{0};    // bumped per batch, so a worker joins each batch once
  std::atomic<bool> stopping_{false};
};

}  // namespace softraster::detail
