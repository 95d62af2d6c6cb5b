// A persistent worker process and its three pipes (worker_process.hpp).
#include "batch/worker_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <stdexcept>

#include "batch/child_start.hpp"

namespace signalsim {
namespace {

constexpr std::size_t kMaxStderr = 64 * 1024;  // per run, as for one process per run

int (*worker_entry)() = nullptr;

// A fork may run more than async-signal-safe code only when no other thread could have held a lock.
bool single_threaded() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8)) == 1;
  return false;
}

// In the forked child, its descriptors set: what exec would have done, then the worker's loop.
[[noreturn]] void serve_in_fork(int (*entry)()) {
  // The batch's own descriptors (other workers' pipes, results.csv, the output lock) all close on
  // exec; without one they are closed here, or a worker would hold another's pipe open.
  close_range(kWorkerReplyFd + 1, ~0U, 0);
  // The handlers signalsim installs go back to the default, as exec puts them (ignored ones stay
  // ignored, as through exec); the worker installs its own.
  for (const int signal : {SIGINT, SIGTERM, SIGALRM}) std::signal(signal, SIG_DFL);
  std::exit(entry());  // the exit of `signalsim worker`'s main: its streams flushed, static objects ended
}

void close_fd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

// Reads everything `fd` holds now into `out` (at most `limit` bytes kept; the rest is read and
// dropped). Closes `fd` (sets it to -1) at its end.
void read_now(int& fd, std::string& out, std::size_t limit) {
  char buf[4096];
  while (fd >= 0) {
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n > 0) {
      if (out.size() < limit) out.append(buf, std::min<std::size_t>(static_cast<std::size_t>(n), limit - out.size()));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && errno == EAGAIN) return;
    close_fd(fd);  // end of file, or an error: nothing more will come
  }
}

}  // namespace

void set_worker_entry(int (*entry)()) { worker_entry = entry; }

WorkerProcess::WorkerProcess(const std::string& program) {
  int requests[2] = {-1, -1}, replies[2] = {-1, -1}, errors[2] = {-1, -1};
  if (pipe2(requests, O_CLOEXEC) != 0 || pipe2(replies, O_CLOEXEC) != 0 || pipe2(errors, O_CLOEXEC) != 0) {
    const std::string reason = std::strerror(errno);
    for (int* p : {requests, replies, errors}) {
      close_fd(p[0]);
      close_fd(p[1]);
    }
    throw std::runtime_error("cannot create a pipe: " + reason);
  }
  const char* args[] = {program.c_str(), "worker", nullptr};
  const pid_t parent = getpid();
  int (*const entry)() = worker_entry && single_threaded() ? worker_entry : nullptr;
  if (entry) {  // what the parent has buffered must not be written twice
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
  }
  const pid_t pid = fork();
  if (pid == 0) {
    // Child: only async-signal-safe calls until exec or, with one thread, serve_in_fork. The pipes'
    // own descriptors close on exec (or in serve_in_fork); the dup2 copies stay.
    join_own_group_tied_to(parent);
    // Every source above the standard descriptors first, so no dup2 below overwrites another's
    // source (a batch started with its stdin closed has pipes on 0, 1 or 2).
    const int from_requests = fcntl(requests[0], F_DUPFD_CLOEXEC, 10);
    const int from_errors = fcntl(errors[1], F_DUPFD_CLOEXEC, 10);
    const int to_replies = fcntl(replies[1], F_DUPFD_CLOEXEC, 10);
    const int null_file = open("/dev/null", O_WRONLY | O_CLOEXEC);
    const int null_fd = null_file >= 0 ? fcntl(null_file, F_DUPFD_CLOEXEC, 10) : -1;
    if (from_requests < 0 || from_errors < 0 || to_replies < 0) _exit(127);
    dup2(from_requests, STDIN_FILENO);
    if (null_fd >= 0) dup2(null_fd, STDOUT_FILENO);
    dup2(from_errors, STDERR_FILENO);
    dup2(to_replies, kWorkerReplyFd);
    if (entry) serve_in_fork(entry);
    exec_worker_or_exit(const_cast<char* const*>(args));
  }
  const int fork_errno = errno;
  close(requests[0]);
  close(replies[1]);
  close(errors[1]);
  if (pid < 0) {
    close(requests[1]);
    close(replies[0]);
    close(errors[0]);
    throw std::runtime_error(std::string("cannot fork: ") + std::strerror(fork_errno));
  }
  setpgid(pid, pid);  // also done in the child: no race either way
  pid_ = pid;
  request_fd_ = requests[1];
  reply_fd_ = replies[0];
  err_fd_ = errors[0];
  for (const int fd : {reply_fd_, err_fd_}) fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) | O_NONBLOCK);
}

WorkerProcess::~WorkerProcess() {
  close_fd(request_fd_);
  close_fd(reply_fd_);
  close_fd(err_fd_);
  if (!reaped_) {
    signal_group(SIGKILL);
    reap(true);
  }
}

bool WorkerProcess::send(const std::vector<std::string>& args) {
  if (request_fd_ < 0) return false;
  const std::string line = encode_worker_request(args);
  for (std::size_t at = 0; at < line.size();) {
    const ssize_t n = write(request_fd_, line.data() + at, line.size() - at);
    if (n > 0) {
      at += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    close_fd(request_fd_);  // EPIPE: it has ended
    return false;
  }
  return true;
}

void WorkerProcess::close_requests() { close_fd(request_fd_); }

void WorkerProcess::add_poll_fds(std::vector<pollfd>& fds) const {
  for (const int fd : {reply_fd_, err_fd_})
    if (fd >= 0) fds.push_back({fd, POLLIN, 0});
}

void WorkerProcess::read_available() {
  read_now(reply_fd_, reply_buffer_, 1 << 20);
  for (std::size_t end; (end = reply_buffer_.find('\n')) != std::string::npos;) {
    const std::string line = reply_buffer_.substr(0, end);
    reply_buffer_.erase(0, end + 1);
    if (const auto reply = decode_worker_reply(line)) replies_.push_back(*reply);
    else if (reply_error_.empty()) reply_error_ = "the worker wrote '" + line.substr(0, 80) + "' instead of a reply";
  }
  read_now(err_fd_, err_, kMaxStderr);
}

bool WorkerProcess::take_reply(WorkerReply& reply) {
  if (replies_.empty()) return false;
  reply = replies_.front();
  replies_.pop_front();
  return true;
}

std::string WorkerProcess::take_stderr() {
  std::string out;
  out.swap(err_);
  return out;
}

void WorkerProcess::signal_group(int signal) {
  if (!reaped_ && pid_ > 0) kill(-pid_, signal);
}

bool WorkerProcess::reap(bool block) {
  while (!reaped_) {
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
  return true;
}

}  // namespace signalsim
