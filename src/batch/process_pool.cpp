// Worker processes for batch runs, one process per run (process_pool.hpp).
#include "batch/process_pool.hpp"

#include "batch/child_start.hpp"
#include "batch/interrupt_guard.hpp"
#include "report/exit_codes.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <climits>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <thread>

namespace signalsim {
namespace {

using Clock = std::chrono::steady_clock;
constexpr std::size_t kMaxStderr = 64 * 1024;

struct Worker {
  const ProcessJob* job = nullptr;
  pid_t pid = -1;
  int fd = -1;                 // read end of its stderr pipe; -1 once closed
  Clock::time_point start;
  bool reaped = false;
  int status = 0;
  bool timed_out = false;
  std::string err;
};

// fork + exec with the child in its own process group. `err_fd` becomes the child's stderr (-1:
// inherit), stdin and stdout go to /dev/null when `quiet_stdout`. Returns the pid, -1 on failure.
pid_t spawn(const std::vector<std::string>& argv, int err_fd, bool own_group) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid != 0) {
    if (pid > 0 && own_group) setpgid(pid, pid);  // also done in the child: no race either way
    return pid;
  }
  // Child: only async-signal-safe calls from here on.
  if (own_group) {
    join_own_group_tied_to(parent);
    const int null_fd = open("/dev/null", O_RDWR | O_CLOEXEC);  // the dup2 copies stay open
    if (null_fd >= 0) {
      dup2(null_fd, STDIN_FILENO);
      dup2(null_fd, STDOUT_FILENO);
    }
  }
  if (err_fd >= 0) dup2(err_fd, STDERR_FILENO);
  exec_worker_or_exit(args.data());
}

void drain(Worker& w) {
  if (w.fd < 0) return;
  char buf[4096];
  while (true) {
    const ssize_t n = read(w.fd, buf, sizeof buf);
    if (n > 0) {
      if (w.err.size() < kMaxStderr) w.err.append(buf, std::min<std::size_t>(n, kMaxStderr - w.err.size()));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n == 0) {  // EOF
      close(w.fd);
      w.fd = -1;
    }
    return;  // EAGAIN or EOF or error
  }
}

void close_worker(Worker& w) {
  if (w.fd >= 0) close(w.fd);
  w.fd = -1;
}

bool reap(Worker& w, bool block) {
  if (w.reaped) return true;
  while (true) {
    const pid_t r = waitpid(w.pid, &w.status, block ? 0 : WNOHANG);
    if (r == w.pid) {
      w.reaped = true;
      return true;
    }
    if (r < 0 && errno == EINTR) {
      if (!block) return false;
      continue;
    }
    if (r < 0) {  // not our child any more (cannot happen): treat as gone
      w.reaped = true;
      w.status = 0;
      return true;
    }
    return false;
  }
}

}  // namespace

std::string self_executable() {
  char buf[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return "/proc/self/exe";
  return std::string(buf, static_cast<std::size_t>(n));
}

bool stopped_by_signal(const ProcessResult& result) {
  if (result.timed_out) return false;  // our SIGKILL: the run's own end, an error row
  if (result.exited) return result.exit_code == kExitInterrupted || result.exit_code == kExitTerminated;
  return result.signal == SIGINT || result.signal == SIGTERM;
}

std::string signal_name(int signal) {
  switch (signal) {
    case SIGKILL: return "SIGKILL";
    case SIGTERM: return "SIGTERM";
    case SIGINT: return "SIGINT";
    case SIGSEGV: return "SIGSEGV";
    case SIGABRT: return "SIGABRT";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGHUP: return "SIGHUP";
    case SIGPIPE: return "SIGPIPE";
    default: break;
  }
  return "signal " + std::to_string(signal);
}

bool run_processes(const std::vector<ProcessJob>& jobs, int parallel,
                   const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                   const std::function<void()>& on_tick) {
  InterruptGuard guard;
  parallel = std::max(1, parallel);
  std::vector<Worker> running;
  std::size_t next = 0;

  auto start = [&](const ProcessJob& job) {
    int fds[2];
    Worker w;
    w.job = &job;
    w.start = Clock::now();
    if (pipe2(fds, O_CLOEXEC) != 0) {
      ProcessResult r;
      r.stderr_text = std::string("cannot create a pipe: ") + std::strerror(errno);
      on_done(job, r);
      return;
    }
    w.pid = spawn(job.argv, fds[1], true);
    close(fds[1]);
    if (w.pid < 0) {
      close(fds[0]);
      ProcessResult r;
      r.stderr_text = std::string("cannot fork: ") + std::strerror(errno);
      on_done(job, r);
      return;
    }
    w.fd = fds[0];
    fcntl(w.fd, F_SETFL, fcntl(w.fd, F_GETFL) | O_NONBLOCK);
    running.push_back(std::move(w));
  };

  bool stopped = false;  // a run was stopped by a signal sent to it, not to the pool
  // Reports the reaped worker's run, unless a signal stopped it (the run did not finish: no row).
  auto finish = [&](Worker& w) {
    drain(w);
    close_worker(w);
    ProcessResult r;
    r.wall = std::chrono::duration<double>(Clock::now() - w.start).count();
    r.stderr_text = std::move(w.err);
    r.timed_out = w.timed_out;
    if (WIFEXITED(w.status)) {
      r.exited = true;
      r.exit_code = WEXITSTATUS(w.status);
    } else if (WIFSIGNALED(w.status)) {
      r.signal = WTERMSIG(w.status);
    }
    if (stopped_by_signal(r)) {
      stopped = true;
      return;
    }
    on_done(*w.job, r);
  };
  const auto stopping = [&] { return stopped || InterruptGuard::interrupted(); };

  while ((next < jobs.size() || !running.empty()) && !stopping()) {
    while (running.size() < static_cast<std::size_t>(parallel) && next < jobs.size() && !stopping())
      start(jobs[next++]);

    // Wait for output, an exit (the pipe closes) or the nearest timeout, at most 200 ms.
    auto now = Clock::now();
    double wait = 0.2;
    for (const Worker& w : running)
      if (w.job->timeout > 0 && !w.timed_out)
        wait = std::min(wait, std::max(0.0, w.job->timeout - std::chrono::duration<double>(now - w.start).count()));
    std::vector<pollfd> fds;
    for (const Worker& w : running)
      if (w.fd >= 0) fds.push_back({w.fd, POLLIN, 0});
    if (!fds.empty()) {
      poll(fds.data(), fds.size(), static_cast<int>(wait * 1000.0) + 1);
    } else if (!running.empty()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    for (Worker& w : running) drain(w);

    now = Clock::now();
    for (Worker& w : running) {
      if (!reap(w, false) && w.job->timeout > 0 && !w.timed_out &&
          std::chrono::duration<double>(now - w.start).count() >= w.job->timeout) {
        w.timed_out = true;
        kill(-w.pid, SIGKILL);
      }
    }
    // Report finished workers in a fixed order (by job id) when several end in the same round.
    std::vector<Worker> still;
    std::vector<Worker> done;
    for (Worker& w : running) (w.reaped ? done : still).push_back(std::move(w));
    running = std::move(still);
    std::sort(done.begin(), done.end(), [](const Worker& a, const Worker& b) { return a.job->id < b.job->id; });
    for (Worker& w : done) finish(w);
    if (on_tick) on_tick();
  }

  if (!stopping()) return true;
  if (stopped && !InterruptGuard::interrupted())
    std::fprintf(stderr, "signalsim: a run was stopped by a signal sent to its process: the batch stops\n");
  // Interrupted: stop every worker still running. A worker that had already finished by itself
  // (it exited, it was not killed) is reported: its run is complete and must not be lost.
  for (Worker& w : running) reap(w, false);
  for (Worker& w : running)
    if (!w.reaped) kill(-w.pid, SIGTERM);
  const auto deadline = Clock::now() + std::chrono::seconds(2);
  for (Worker& w : running) {
    while (!reap(w, false) && Clock::now() < deadline) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (!w.reaped) {
      kill(-w.pid, SIGKILL);
      reap(w, true);
    }
  }
  std::sort(running.begin(), running.end(), [](const Worker& a, const Worker& b) { return a.job->id < b.job->id; });
  for (Worker& w : running) {
    // A worker stopped here - or by a signal of its own, as Slurm's scancel signals every process -
    // unwinds and exits 143 or 130 (finish drops it: that run did not finish, no row). One that
    // exited by itself in the meantime did finish; one killed by another signal did not.
    if (WIFEXITED(w.status)) finish(w);
    else close_worker(w);
  }
  return false;
}

int run_foreground(const std::vector<std::string>& argv) {
  const pid_t pid = spawn(argv, -1, false);
  if (pid < 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 127;
}

}  // namespace signalsim
