// One persistent worker of a batch: `signalsim worker` (app/worker_command.cpp), a child of the
// batch (child_process.hpp: its own process group, dying with the batch, stdout on /dev/null,
// stderr into a pipe) with two more pipes - its stdin for requests and file descriptor 3 for
// replies (worker_protocol.hpp). The supervisor (child_supervisor.hpp) hands it runs and reads
// its replies; reading never blocks.
// Where the program registered its worker loop (set_worker_entry) and the batch has one thread, the
// worker is a fork of the batch that runs that loop, not a new process image: exec and the dynamic
// linking of libsumo's ~220 libraries cost about 0.15 s of CPU a worker, more than five small runs;
// the batch loads libsumo's module once before its first fork (set_worker_entry), and the forks share it.
#pragma once

#include <deque>
#include <string>
#include <vector>

#include "batch/child_supervisor.hpp"
#include "batch/worker_protocol.hpp"

namespace signalsim {

/// The worker's loop (`signalsim worker`'s own function), run in a fork of the batch instead of
/// exec'ing `program worker`. Without one, every worker is exec'd. `before_first_fork`, when given,
/// runs once in the batch before it forks its first worker: the program loads libsumo's module there,
/// so that the workers share it instead of each loading it (0.15 s of CPU a worker).
void set_worker_entry(int (*entry)(), void (*before_first_fork)() = nullptr);

class WorkerProcess : public SupervisedChild {
 public:
  /// Starts `program worker` (or forks into the registered worker loop). Throws std::runtime_error
  /// when no pipe or process can be made.
  explicit WorkerProcess(const std::string& program);
  /// Closes its pipes; the process is killed (SIGKILL to its group) unless it has ended, and reaped.
  ~WorkerProcess() override;
  WorkerProcess(const WorkerProcess&) = delete;
  WorkerProcess& operator=(const WorkerProcess&) = delete;

  ChildProcess& process() override { return process_; }
  const ChildProcess& process() const override { return process_; }
  bool replies() const override { return true; }
  /// Writes the job's `signalsim run` arguments (argv without the program) as one request; false
  /// when the worker no longer reads (it has ended).
  bool take_run(const ProcessJob& job) override;
  void close_requests() override;
  void add_poll_fds(std::vector<pollfd>& fds) const override;
  void read_available() override;
  bool take_reply(WorkerReply& reply) override;
  std::string protocol_error() const override { return reply_error_; }
  bool pipes_closed() const override { return reply_fd_ < 0 && process_.stderr_closed(); }

 private:
  ChildProcess process_;
  int request_fd_ = -1;  // write end of its stdin
  int reply_fd_ = -1;    // read end of its fd 3
  std::string reply_buffer_;
  std::deque<WorkerReply> replies_;
  std::string reply_error_;
};

}  // namespace signalsim
