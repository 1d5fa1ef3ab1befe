// Worker processes (see worker_processes.hpp).
//
// The socket protocol, one AF_UNIX stream socket per worker:
//   parent -> worker  8 bytes: the task number; the parent shuts its side down when no task is
//                     left, and the worker exits when it reads the end.
//   worker -> parent  messages of 1 type byte, a 4-byte length and that many bytes:
//                     'R' ready (start() returned; the first task's clock restarts),
//                     'D' a task's reply, 'E' a task's reply after which the worker ends,
//                     'F' a fatal error line, sent just before the worker dies (an uncaught
//                     exception, an out-of-memory error where nothing catches it).
#include "run/worker_processes.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <new>
#include <optional>

#if defined(__SANITIZE_ADDRESS__)
#define CROSSCHECK_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define CROSSCHECK_ADDRESS_SANITIZER 1
#endif
#endif
#ifdef CROSSCHECK_ADDRESS_SANITIZER
#include <sanitizer/lsan_interface.h>
#endif

namespace crosscheck {
namespace {

using Clock = std::chrono::steady_clock;

// How long a worker may take to exit once it has no task left (closing renderers, a sanitizer's
// leak check) before it is killed.
constexpr std::chrono::seconds kExitGrace{60};

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// ---- the worker's side ----

int g_replySocket = -1;          // the worker's end of its socket
char g_fatalLine[512];           // formatted before it is needed: memory may be gone by then
std::size_t g_memoryLimitMegabytes = 0;

bool writeAll(int fd, const void* data, std::size_t size) {
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = send(fd, p, size, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool sendMessage(char type, const char* data, std::size_t size) {
  const auto length = static_cast<std::uint32_t>(size);
  char header[5] = {type};
  std::memcpy(header + 1, &length, 4);
  return writeAll(g_replySocket, header, sizeof header) && writeAll(g_replySocket, data, size);
}

// std::terminate in a worker (an exception nothing caught, on any of its threads): one line to
// the parent, then the abort the parent will also see.
[[noreturn]] void terminateWorker() {
  const char* what = "std::terminate called";
  if (const std::exception_ptr current = std::current_exception()) {
    try {
      std::rethrow_exception(current);
    } catch (const std::bad_alloc&) {
      if (g_memoryLimitMegabytes) {
        std::snprintf(g_fatalLine, sizeof g_fatalLine,
                      "out of memory: over the worker's memory limit of %zu MB (uncaught std::bad_alloc)",
                      g_memoryLimitMegabytes);
      } else {
        std::snprintf(g_fatalLine, sizeof g_fatalLine, "out of memory (uncaught std::bad_alloc)");
      }
      what = nullptr;
    } catch (const std::exception& e) {
      std::snprintf(g_fatalLine, sizeof g_fatalLine, "uncaught exception: %s", e.what());
      what = nullptr;
    } catch (...) {
      what = "uncaught exception of unknown type";
    }
  }
  if (what) std::snprintf(g_fatalLine, sizeof g_fatalLine, "%s", what);
  sendMessage('F', g_fatalLine, std::strlen(g_fatalLine));
  std::abort();
}

// Reads exactly `size` bytes; false at the end of the stream (or an error).
bool readAll(int fd, void* data, std::size_t size) {
  char* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

// The worker process's whole life; never returns into the caller's code.
[[noreturn]] void workerMain(int socket, pid_t parent, const WorkerLimits& limits, const WorkerProgram& program) {
  g_replySocket = socket;
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // a worker never outlives the run
  if (getppid() != parent) _exit(1);
  g_memoryLimitMegabytes = workerMemoryLimitWorks() ? limits.memoryLimitMegabytes : 0;
  if (g_memoryLimitMegabytes) {
    const rlim_t bytes = static_cast<rlim_t>(g_memoryLimitMegabytes) << 20;
    const rlimit limit{bytes, bytes};
    setrlimit(RLIMIT_AS, &limit);
  }
  std::set_terminate(terminateWorker);
  try {
    if (program.start) program.start();
    if (!sendMessage('R', nullptr, 0)) _exit(1);
    std::uint64_t task = 0;
    while (readAll(socket, &task, sizeof task)) {
      bool endWorker = false;
      const std::string reply = program.run(static_cast<std::size_t>(task), &endWorker);
      if (!sendMessage(endWorker ? 'E' : 'D', reply.data(), reply.size())) _exit(1);
      if (endWorker) break;
    }
    if (program.finish) program.finish();
  } catch (...) {
    terminateWorker();
  }
#ifdef CROSSCHECK_ADDRESS_SANITIZER
  // Static destructors do not run after _exit, so check for leaks here: a leak exits with
  // LeakSanitizer's status and the parent reports it.
  __lsan_do_leak_check();
#endif
  _exit(0);
}

// ---- the parent's side ----

struct Worker {
  pid_t pid = -1;
  int socket = -1;
  std::optional<std::size_t> task;   // the task it is running
  Clock::time_point handedOver;      // when the task was sent
  Clock::time_point deadline;        // the task's (or, once shut down, the exit's) deadline
  bool shutDown = false;             // no more tasks: waiting for it to exit
  bool ending = false;               // it said it ends after its reply ('E')
  std::string buffer;                // bytes read, not yet a whole message
  std::string fatal;                 // its 'F' line, if it sent one
};

std::string signalName(int signal) {
  const char* abbreviation = sigabbrev_np(signal);
  return abbreviation ? std::string("SIG") + abbreviation : "unknown signal";
}

// What a worker's wait status says, as the end of "worker ...".
std::string describeExit(int status) {
  if (WIFSIGNALED(status)) {
    const int signal = WTERMSIG(status);
    std::string text = "worker killed by signal " + std::to_string(signal) + " (" + signalName(signal) + ")";
    if (signal == SIGKILL) text += "; the system may have run out of memory";
    return text;
  }
  if (WIFEXITED(status)) return "worker exited with status " + std::to_string(WEXITSTATUS(status));
  return "worker ended with wait status " + std::to_string(status);
}

int waitFor(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

class Pool {
 public:
  Pool(const std::vector<std::size_t>& tasks, unsigned workers, const WorkerLimits& limits, const WorkerProgram& program,
       const std::function<void(std::size_t, TaskEnd)>& onEnd, const std::function<void(const std::string&)>& onWorkerError)
      : tasks_(tasks), maxWorkers_(std::max(1u, workers)), limits_(limits), program_(program), onEnd_(onEnd),
        onWorkerError_(onWorkerError) {}

  void run() {
    while (true) {
      handOutTasks();
      if (workers_.empty()) break;
      waitForEvents();
      enforceDeadlines();
    }
  }

 private:
  std::optional<Clock::time_point> taskDeadline(Clock::time_point from) const {
    if (limits_.timeoutSeconds <= 0) return std::nullopt;
    return from + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(limits_.timeoutSeconds));
  }

  void give(Worker& worker, std::size_t task) {
    const auto number = static_cast<std::uint64_t>(task);
    worker.task = task;
    worker.handedOver = Clock::now();
    worker.deadline = taskDeadline(worker.handedOver).value_or(Clock::time_point::max());
    // A failure means the worker is gone; the end of its socket (waitForEvents) says how.
    writeAll(worker.socket, &number, sizeof number);
  }

  void shutDown(Worker& worker) {
    shutdown(worker.socket, SHUT_WR);
    worker.shutDown = true;
    worker.deadline = Clock::now() + kExitGrace;
  }

  // Gives idle workers the next tasks, forks workers while there are tasks and room, and tells
  // idle workers with nothing left to do to exit.
  void handOutTasks() {
    for (Worker& worker : workers_) {
      if (worker.task || worker.shutDown) continue;
      if (worker.ending || next_ >= tasks_.size()) {
        shutDown(worker);
      } else {
        give(worker, tasks_[next_++]);
      }
    }
    while (next_ < tasks_.size() && busyOrStarting() < maxWorkers_) {
      const std::size_t task = tasks_[next_];
      const std::string error = fork(task);
      if (error.empty()) {
        ++next_;
        continue;
      }
      if (busyOrStarting() > 0) break;  // carry on with the workers there are
      ++next_;
      onEnd_(task, TaskEnd{TaskEnd::Kind::Crashed, "", error, 0});
    }
  }

  std::size_t busyOrStarting() const {
    return static_cast<std::size_t>(std::count_if(workers_.begin(), workers_.end(), [](const Worker& w) { return !w.shutDown; }));
  }

  // Forks a worker and gives it `task`; the error line when it cannot.
  std::string fork(std::size_t task) {
    int sockets[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0) {
      return std::string("cannot start a worker process: socketpair: ") + std::strerror(errno);
    }
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t parent = getpid();
    const pid_t pid = ::fork();
    if (pid < 0) {
      const int error = errno;
      close(sockets[0]);
      close(sockets[1]);
      return std::string("cannot start a worker process: fork: ") + std::strerror(error);
    }
    if (pid == 0) {
      close(sockets[0]);
      for (const Worker& other : workers_) close(other.socket);
      workerMain(sockets[1], parent, limits_, program_);
    }
    close(sockets[1]);
    fcntl(sockets[0], F_SETFL, fcntl(sockets[0], F_GETFL) | O_NONBLOCK);
    Worker& worker = workers_.emplace_back();
    worker.pid = pid;
    worker.socket = sockets[0];
    give(worker, task);
    return {};
  }

  void waitForEvents() {
    Clock::time_point earliest = Clock::time_point::max();
    for (const Worker& worker : workers_) earliest = std::min(earliest, worker.deadline);
    int timeout = -1;
    if (earliest != Clock::time_point::max()) {
      const double ms = std::chrono::duration<double, std::milli>(earliest - Clock::now()).count();
      timeout = static_cast<int>(std::clamp(std::ceil(ms), 0.0, 3600000.0));
    }
    std::vector<pollfd> fds;
    for (const Worker& worker : workers_) fds.push_back({worker.socket, POLLIN, 0});
    if (poll(fds.data(), fds.size(), timeout) < 0) return;  // EINTR: look again
    std::vector<std::size_t> ended;
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].revents == 0) continue;
      if (!readFrom(workers_[i])) ended.push_back(i);
    }
    for (auto it = ended.rbegin(); it != ended.rend(); ++it) reap(*it);
  }

  // Reads what the worker sent and acts on whole messages; false once its socket has ended.
  bool readFrom(Worker& worker) {
    char chunk[65536];
    while (true) {
      const ssize_t n = read(worker.socket, chunk, sizeof chunk);
      if (n > 0) {
        worker.buffer.append(chunk, static_cast<std::size_t>(n));
        continue;
      }
      if (n < 0 && errno == EINTR) continue;
      const bool open = n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
      handleMessages(worker);
      return open;
    }
  }

  void handleMessages(Worker& worker) {
    while (worker.buffer.size() >= 5) {
      std::uint32_t length = 0;
      std::memcpy(&length, worker.buffer.data() + 1, 4);
      if (worker.buffer.size() < 5 + std::size_t{length}) return;
      const char type = worker.buffer[0];
      std::string body = worker.buffer.substr(5, length);
      worker.buffer.erase(0, 5 + std::size_t{length});
      if (type == 'R' && worker.task) {
        worker.handedOver = Clock::now();
        worker.deadline = taskDeadline(worker.handedOver).value_or(Clock::time_point::max());
      } else if ((type == 'D' || type == 'E') && worker.task) {
        const std::size_t task = *worker.task;
        const double ms = millisecondsSince(worker.handedOver);
        worker.task.reset();
        worker.deadline = Clock::time_point::max();
        worker.ending = type == 'E';
        onEnd_(task, TaskEnd{TaskEnd::Kind::Replied, std::move(body), "", ms});
      } else if (type == 'F') {
        worker.fatal = std::move(body);
      }
    }
  }

  // The worker's socket ended: it exited or died. Waits for it and reports its task, if any.
  void reap(std::size_t index) {
    Worker worker = std::move(workers_[index]);
    workers_.erase(workers_.begin() + static_cast<std::ptrdiff_t>(index));
    close(worker.socket);
    const int status = waitFor(worker.pid);
    const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (worker.task) {
      std::string error = worker.fatal.empty() ? describeExit(status) : worker.fatal;
      onEnd_(*worker.task, TaskEnd{TaskEnd::Kind::Crashed, "", std::move(error), millisecondsSince(worker.handedOver)});
    } else if (!clean && onWorkerError_) {
      onWorkerError_((worker.fatal.empty() ? "" : worker.fatal + "; ") + describeExit(status) +
                     " after its last task (a report from it may be above)");
    }
  }

  void enforceDeadlines() {
    const Clock::time_point now = Clock::now();
    for (std::size_t i = workers_.size(); i-- > 0;) {
      Worker& worker = workers_[i];
      if (worker.deadline > now) continue;
      kill(worker.pid, SIGKILL);
      if (worker.task) {
        const std::size_t task = *worker.task;
        const double ms = millisecondsSince(worker.handedOver);
        worker.task.reset();
        char seconds[32];
        std::snprintf(seconds, sizeof seconds, "%g", limits_.timeoutSeconds);
        onEnd_(task, TaskEnd{TaskEnd::Kind::TimedOut, "",
                             std::string("no result within ") + seconds + " s; worker killed", ms});
      } else if (onWorkerError_) {
        onWorkerError_("worker did not exit within " + std::to_string(kExitGrace.count()) +
                       " s after its last task; killed");
      }
      close(worker.socket);
      waitFor(worker.pid);
      workers_.erase(workers_.begin() + static_cast<std::ptrdiff_t>(i));
    }
  }

  const std::vector<std::size_t>& tasks_;
  const unsigned maxWorkers_;
  const WorkerLimits limits_;
  const WorkerProgram& program_;
  const std::function<void(std::size_t, TaskEnd)>& onEnd_;
  const std::function<void(const std::string&)>& onWorkerError_;
  std::vector<Worker> workers_;
  std::size_t next_ = 0;
};

}  // namespace

bool workerMemoryLimitWorks() {
#ifdef CROSSCHECK_ADDRESS_SANITIZER
  return false;
#else
  return true;
#endif
}

void runInWorkerProcesses(const std::vector<std::size_t>& tasks, unsigned workers, const WorkerLimits& limits,
                          const WorkerProgram& program, const std::function<void(std::size_t task, TaskEnd end)>& onEnd,
                          const std::function<void(const std::string& error)>& onWorkerError) {
  Pool(tasks, workers, limits, program, onEnd, onWorkerError).run();
}

}  // namespace crosscheck
