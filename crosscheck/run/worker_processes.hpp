// Worker processes for the conformance runner, as deqp-runner and the Khronos CTS isolate their
// cases: numbered tasks run in processes forked from the calling one, so a task that segfaults,
// aborts, allocates without bound or never finishes ends its worker, not the run. The parent
// hands each worker one task at a time over a socket and reads back the bytes the task replies;
// it polls the sockets (no threads), kills a worker whose task outlives the timeout (SIGKILL),
// notices a dead worker (waitpid), reports what became of its task and forks a replacement.
// Each worker gets an address-space limit (RLIMIT_AS), so a runaway allocation fails there
// (std::bad_alloc) instead of waking the system's OOM killer.
// Fork, not exec: a worker runs the caller's functions as they are (a test's replaced renderer
// too), so the caller must have no other threads when it calls this (fork copies only the
// calling thread) and must open nothing that cannot be shared across fork (Vulkan, thread pools)
// before it: a worker opens its own in WorkerProgram::start.
// Deliberately no retry of a task that failed and no limit on CPU time: a task runs once, and the
// wall-clock timeout is the only clock.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace crosscheck {

struct WorkerLimits {
  double timeoutSeconds = 0;             // per task, from when it is handed over; 0: none
  std::size_t memoryLimitMegabytes = 0;  // each worker's address space (RLIMIT_AS); 0: none
};

// What a worker does, called in the worker process only.
struct WorkerProgram {
  // Once in each new worker, before its first task (opening renderers); may be empty. Its time
  // counts against the worker's first task's timeout.
  std::function<void()> start;
  // One task: the bytes to hand back to the parent. Setting *endWorker ends the worker after this
  // reply (a new one takes the next task), for a worker whose state may be spoiled.
  std::function<std::string(std::size_t task, bool* endWorker)> run;
  // Once before a worker exits normally (closing renderers, so a leak check sees them closed);
  // may be empty.
  std::function<void()> finish;
};

// How one task ended, as the parent saw it.
struct TaskEnd {
  enum class Kind { Replied, Crashed, TimedOut };
  Kind kind = Kind::Replied;
  std::string reply;          // Replied: what WorkerProgram::run returned
  std::string error;          // Crashed, TimedOut: one line, e.g. "worker killed by signal 11 (SIGSEGV)"
  double milliseconds = 0;    // from handing the task over to its end
};

// Runs every task of `tasks` once on up to `workers` worker processes and calls onEnd(task, end)
// in this process as each ends, in the order they end. onWorkerError gets a line for what is not
// any task's (a worker that exits abnormally after its last task: a sanitizer's leak report, or
// one that does not exit); may be empty. Returns when every task has ended and every worker
// exited.
void runInWorkerProcesses(const std::vector<std::size_t>& tasks, unsigned workers, const WorkerLimits& limits,
                          const WorkerProgram& program, const std::function<void(std::size_t task, TaskEnd end)>& onEnd,
                          const std::function<void(const std::string& error)>& onWorkerError);

// Whether this build can limit a worker's address space: not under AddressSanitizer, which
// reserves terabytes of address space for its shadow memory (the limit is then not applied).
bool workerMemoryLimitWorks();

}  // namespace crosscheck
