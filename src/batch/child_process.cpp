// Starting, reading, signalling and reaping one child process of a batch (child_process.hpp).
#include "batch/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <utility>

#include "core/program_location.hpp"

namespace signalsim {
namespace {

constexpr std::size_t kMaxStderr = 64 * 1024;

// Child, after fork: only async-signal-safe calls until exec (the parent may hold locks another of
// its threads took). It leads a process group of its own and dies with the batch; a parent that
// is already gone (`parent` is the pid before fork) ends it at once.
void join_own_group_tied_to(pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the batch
  if (getppid() != parent) _exit(127);
}

// Child: execv(args[0], args); when that fails, "signalsim: cannot start worker: PROGRAM" on stderr
// and exit code 127.
[[noreturn]] void exec_or_exit(char* const* args) {
  execv(args[0], args);
  const char* msg = "signalsim: cannot start worker: ";
  (void)!write(STDERR_FILENO, msg, std::strlen(msg));
  (void)!write(STDERR_FILENO, args[0], std::strlen(args[0]));
  (void)!write(STDERR_FILENO, "\n", 1);
  _exit(127);
}

// Child, with one thread only: what exec would have done, then the entry. The batch's own
// descriptors (other children's pipes, results.csv, the output lock) all close on exec; here they
// are closed by hand, or a child would hold another's pipe open. The handlers signalsim installs go
// back to the default, as exec puts them (ignored ones stay ignored); the entry installs its own.
[[noreturn]] void serve_in_fork(int (*entry)(), int highest_fd) {
  close_range(static_cast<unsigned>(highest_fd) + 1, ~0U, 0);
  for (const int signal : {SIGINT, SIGTERM, SIGALRM}) std::signal(signal, SIG_DFL);
  std::exit(entry());  // as the program's main would end: streams flushed, static objects ended
}

// Child: its descriptors. Every source moves above the standard descriptors first, so that no dup2
// overwrites another's source (a batch started with stdin closed has pipes on 0, 1 or 2). `high`
// has room for one descriptor per entry of `fds` (no allocation after fork).
void set_child_fds(const std::vector<ChildFd>& fds, int err_write, std::vector<int>& high) {
  const int null_file = open("/dev/null", O_RDWR | O_CLOEXEC);
  const int null_fd = null_file >= 0 ? fcntl(null_file, F_DUPFD_CLOEXEC, 10) : -1;
  const int err_fd = fcntl(err_write, F_DUPFD_CLOEXEC, 10);
  if (err_fd < 0) _exit(127);
  for (std::size_t i = 0; i < fds.size(); ++i) {
    high[i] = fcntl(fds[i].source, F_DUPFD_CLOEXEC, 10);
    if (high[i] < 0) _exit(127);
  }
  if (null_fd >= 0) {
    dup2(null_fd, STDIN_FILENO);
    dup2(null_fd, STDOUT_FILENO);
  }
  for (std::size_t i = 0; i < fds.size(); ++i) dup2(high[i], fds[i].target);  // the dup2 copies stay open on exec
  dup2(err_fd, STDERR_FILENO);
}

}  // namespace

ChildProcess ChildProcess::start(const ChildStart& how) {
  int err_pipe[2] = {-1, -1};
  if (pipe2(err_pipe, O_CLOEXEC) != 0) throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  std::vector<char*> args;
  for (const std::string& a : how.argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<int> high(how.fds.size(), -1);
  int highest_fd = STDERR_FILENO;
  for (const ChildFd& fd : how.fds) highest_fd = std::max(highest_fd, fd.target);
  if (how.entry) {  // what the parent has buffered must not be written twice
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
  }
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid == 0) {
    join_own_group_tied_to(parent);
    set_child_fds(how.fds, err_pipe[1], high);
    if (how.entry) serve_in_fork(how.entry, highest_fd);
    exec_or_exit(args.data());
  }
  const int fork_errno = errno;
  close(err_pipe[1]);
  if (pid < 0) {
    close(err_pipe[0]);
    throw std::runtime_error(std::string("cannot fork: ") + std::strerror(fork_errno));
  }
  setpgid(pid, pid);  // also done in the child: no race either way
  ChildProcess child;
  child.pid_ = pid;
  child.err_fd_ = err_pipe[0];
  fcntl(child.err_fd_, F_SETFL, fcntl(child.err_fd_, F_GETFL) | O_NONBLOCK);
  return child;
}

ChildProcess::~ChildProcess() { release(); }

void ChildProcess::release() {
  close_fd(err_fd_);
  if (pid_ > 0 && !reaped_) {
    signal_group(SIGKILL);
    reap(true);
  }
  pid_ = -1;
}

ChildProcess::ChildProcess(ChildProcess&& other) noexcept { *this = std::move(other); }

ChildProcess& ChildProcess::operator=(ChildProcess&& other) noexcept {
  if (this == &other) return *this;
  release();
  pid_ = std::exchange(other.pid_, -1);
  err_fd_ = std::exchange(other.err_fd_, -1);
  reaped_ = std::exchange(other.reaped_, false);
  status_ = std::exchange(other.status_, 0);
  err_ = std::move(other.err_);
  return *this;
}

void ChildProcess::add_poll_fd(std::vector<pollfd>& fds) const {
  if (err_fd_ >= 0) fds.push_back({err_fd_, POLLIN, 0});
}

void ChildProcess::read_stderr() {
  char buf[4096];
  while (err_fd_ >= 0) {
    const ssize_t n = read(err_fd_, buf, sizeof buf);
    if (n > 0) {  // beyond the limit it is read and dropped
      if (err_.size() < kMaxStderr) err_.append(buf, std::min<std::size_t>(static_cast<std::size_t>(n), kMaxStderr - err_.size()));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return;
    close_fd(err_fd_);  // end of file, or an error: nothing more will come
  }
}

std::string ChildProcess::take_stderr() {
  std::string out;
  out.swap(err_);
  return out;
}

void ChildProcess::signal_group(int signal) {
  if (!reaped_ && pid_ > 0) kill(-pid_, signal);
}

bool ChildProcess::reap(bool block) {
  while (!reaped_ && pid_ > 0) {
    const pid_t r = waitpid(pid_, &status_, block ? 0 : WNOHANG);
    if (r == pid_) {
      reaped_ = true;
    } else if (r < 0 && errno == EINTR) {
      if (!block) return false;
    } else if (r < 0) {  // not our child any more (cannot happen): treat it as gone
      reaped_ = true;
      status_ = 0;
    } else {
      return false;
    }
  }
  return reaped_;
}

int run_foreground(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) exec_or_exit(args.data());
  if (pid < 0) return 127;
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 127;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 127;
}

void close_fd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

std::string self_executable() {
  const std::filesystem::path exe = running_binary();
  return exe.empty() ? "/proc/self/exe" : exe.string();
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

}  // namespace signalsim
