// A persistent worker process and its request and reply pipes (worker_process.hpp).
#include "batch/worker_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

namespace signalsim {
namespace {

int (*worker_entry)() = nullptr;
void (*worker_before_first_fork)() = nullptr;

// A fork may run more than async-signal-safe code only when no other thread could have held a lock.
bool single_threaded() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("Threads:", 0) == 0) return std::stoi(line.substr(8)) == 1;
  return false;
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

void set_worker_entry(int (*entry)(), void (*before_first_fork)()) {
  worker_entry = entry;
  worker_before_first_fork = before_first_fork;
}

WorkerProcess::WorkerProcess(const std::string& program) {
  // Only where the workers will be forks: a library that started a thread while loading turns the
  // forks into exec'd workers (single_threaded below), which then pay the load themselves.
  if (worker_entry && worker_before_first_fork && single_threaded())
    std::exchange(worker_before_first_fork, nullptr)();
  int requests[2] = {-1, -1}, replies[2] = {-1, -1};
  if (pipe2(requests, O_CLOEXEC) != 0 || pipe2(replies, O_CLOEXEC) != 0) {
    const std::string reason = std::strerror(errno);
    for (int* p : {requests, replies}) {
      close_fd(p[0]);
      close_fd(p[1]);
    }
    throw std::runtime_error("cannot create a pipe: " + reason);
  }
  ChildStart how;
  how.argv = {program, "worker"};
  how.fds = {{0, requests[0]}, {kWorkerReplyFd, replies[1]}};
  how.entry = worker_entry && single_threaded() ? worker_entry : nullptr;
  try {
    process_ = ChildProcess::start(how);
  } catch (...) {
    for (int* p : {requests, replies}) {
      close_fd(p[0]);
      close_fd(p[1]);
    }
    throw;
  }
  close(requests[0]);
  close(replies[1]);
  request_fd_ = requests[1];
  reply_fd_ = replies[0];
  fcntl(reply_fd_, F_SETFL, fcntl(reply_fd_, F_GETFL) | O_NONBLOCK);
}

WorkerProcess::~WorkerProcess() {
  close_fd(request_fd_);
  close_fd(reply_fd_);
}

bool WorkerProcess::take_run(const ProcessJob& job) {
  if (request_fd_ < 0) return false;
  const std::string line = encode_worker_request(std::vector<std::string>(job.argv.begin() + 1, job.argv.end()));
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
  if (reply_fd_ >= 0) fds.push_back({reply_fd_, POLLIN, 0});
  process_.add_poll_fd(fds);
}

void WorkerProcess::read_available() {
  read_now(reply_fd_, reply_buffer_, 1 << 20);
  for (std::size_t end; (end = reply_buffer_.find('\n')) != std::string::npos;) {
    const std::string line = reply_buffer_.substr(0, end);
    reply_buffer_.erase(0, end + 1);
    if (const auto reply = decode_worker_reply(line)) replies_.push_back(*reply);
    else if (reply_error_.empty()) reply_error_ = "the worker wrote '" + line.substr(0, 80) + "' instead of a reply";
  }
  process_.read_stderr();
}

bool WorkerProcess::take_reply(WorkerReply& reply) {
  if (replies_.empty()) return false;
  reply = replies_.front();
  replies_.pop_front();
  return true;
}

}  // namespace signalsim
