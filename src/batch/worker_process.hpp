// One persistent worker of a batch: `signalsim worker` (app/worker_command.cpp) started with three
// pipes - its stdin for requests, its stderr, and file descriptor 3 for replies (worker_protocol.hpp) -
// in its own process group, dying with the batch (PR_SET_PDEATHSIG), stdout on /dev/null.
// Where the program registered its worker loop (set_worker_entry) and the batch has one thread, the
// worker is a fork of the batch that runs that loop, not a new process image: exec and the dynamic
// linking of libsumo's ~220 libraries cost about 0.1 s of CPU a worker, more than five small runs.
// Reading never blocks: the pool polls fds() and calls read_available().
#pragma once

#include <sys/types.h>

#include <deque>
#include <string>
#include <vector>

#include "batch/worker_protocol.hpp"

struct pollfd;

namespace signalsim {

/// The worker's loop (`signalsim worker`'s own function), run in a fork of the batch instead of
/// exec'ing `program worker`. Without one, every worker is exec'd.
void set_worker_entry(int (*entry)());

class WorkerProcess {
 public:
  /// Starts `program worker` (or forks into the registered worker loop). Throws std::runtime_error
  /// when no pipe or process can be made.
  explicit WorkerProcess(const std::string& program);
  /// Kills the whole process group (SIGKILL) unless the worker has ended, and reaps it.
  ~WorkerProcess();
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  pid_t pid() const { return pid_; }

  /// Writes one request; false when the worker no longer reads (it has ended).
  bool send(const std::vector<std::string>& args);
  /// No more requests: an idle worker then exits 0.
  void close_requests();

  /// Adds the pipes still open to `fds` (POLLIN).
  void add_poll_fds(std::vector<pollfd>& fds) const;
  /// Reads what the pipes hold now: replies first, then stderr, so that a run's reply comes with
  /// everything the run wrote before it.
  void read_available();
  /// The next reply, if one arrived; `reply_error` is set for a line that is no reply.
  bool take_reply(WorkerReply& reply);
  /// What the worker wrote on stderr since the last call (at most 64 KiB are kept).
  std::string take_stderr();
  /// A line on the reply pipe that was not a reply (the worker is then not to be trusted).
  const std::string& reply_error() const { return reply_error_; }

  /// Both pipes reached their end: the worker has ended or is ending.
  bool pipes_closed() const { return reply_fd_ < 0 && err_fd_ < 0; }
  /// Sends `signal` to the worker's process group (not once it is reaped).
  void signal_group(int signal);
  /// Reaps the worker (waitpid); true once it has ended. `wait_status()` is then valid.
  bool reap(bool block);
  int wait_status() const { return status_; }

 private:
  pid_t pid_ = -1;
  int request_fd_ = -1;  // write end of its stdin
  int reply_fd_ = -1;    // read end of its fd 3
  int err_fd_ = -1;      // read end of its stderr
  bool reaped_ = false;
  int status_ = 0;
  std::string reply_buffer_;
  std::deque<WorkerReply> replies_;
  std::string reply_error_;
  std::string err_;
};

}  // namespace signalsim
