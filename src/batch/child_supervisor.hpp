// The one supervisor of a batch's child processes, for both ways of running runs
// (worker_pool.hpp): persistent workers (worker_process.hpp) that reply once per run, and one
// process per run (`--isolate`) whose run ends with the process.
//
//   while jobs remain or runs are under way:
//     each idle slot (at most `parallel`) hands the next job to its child, making one when it has
//       none (or its child ended while idle); the run's wall time starts
//     poll the children's pipes (at most 200 ms, 20 ms while a child is ending, never past the
//       nearest timeout); a reply ends a worker's run, with everything it wrote on stderr since
//       its previous reply
//     a child that ends (reaped: for a worker once its pipes closed) ends its run as its own
//       process: exit code, or the signal, or timed out when the supervisor killed it (SIGKILL to
//       its group) past the job's wall-clock timeout; a worker that writes no reply is killed too;
//       the next job gets a new child
//     finished runs go to `on_done` in the calling thread, those of one round by job id
//   on SIGINT/SIGTERM (interrupt_guard.hpp): start nothing more; runs that already ended are
//     reported; every child's group gets SIGTERM (SIGKILL after 2 s); a run that still finishes by
//     itself in that time (a reply, or a one-run process's exit, with an exit code neither 130 nor
//     143) is reported, the others not; returns false
//   a SIGINT/SIGTERM that reaches a child itself (a `kill` of it or its group; Slurm's scancel
//     signals every process of a task, often the child before the batch) stops its run as it stops
//     `signalsim run`: 130 or 143 (or its end by that signal) is no finished run, no row; the
//     supervisor then stops as above, as if the signal had reached it (docs/batch.md "Ctrl-C")
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "batch/child_process.hpp"
#include "batch/worker_protocol.hpp"

struct pollfd;

namespace signalsim {

struct ProcessJob {
  std::size_t id = 0;              ///< the caller's key (the run index)
  std::vector<std::string> argv;   ///< a `signalsim run` command line; argv[0] is the program path
  double timeout = 0.0;            ///< [s] wall clock; <= 0: none
};

struct ProcessResult {
  bool exited = false;             ///< ended through exit(); exit_code is valid
  int exit_code = -1;
  int signal = 0;                  ///< the signal that ended it, 0 if none
  bool timed_out = false;          ///< killed by the supervisor after the timeout
  std::string stderr_text;         ///< what it wrote on stderr (at most 64 KiB)
  double wall = 0.0;               ///< [s]
};

/// Whether a run ended because a SIGINT or SIGTERM reached it rather than by finishing: it exited
/// 130 or 143 (what `signalsim run` exits with when one stops it), or one killed it before its
/// handlers were installed. Not for a run the supervisor killed after its timeout.
bool stopped_by_signal(const ProcessResult& result);

/// A child as the supervisor sees it: its process and, for a persistent worker, the pipes that
/// carry runs to it and replies back.
class SupervisedChild {
 public:
  virtual ~SupervisedChild() = default;
  virtual ChildProcess& process() = 0;
  virtual const ChildProcess& process() const = 0;
  /// Whether a run ends with a reply (a persistent worker) rather than with the process.
  virtual bool replies() const { return false; }
  /// Hands it a run; false when it no longer takes one (it ended while idle).
  virtual bool take_run(const ProcessJob& job) = 0;
  /// No more runs: an idle worker then exits 0.
  virtual void close_requests() {}
  /// Adds the pipes still open to `fds` (POLLIN).
  virtual void add_poll_fds(std::vector<pollfd>& fds) const { process().add_poll_fd(fds); }
  /// Reads what its pipes hold now (a worker: replies first, then stderr, so that a run's reply
  /// comes with everything the run wrote before it).
  virtual void read_available() { process().read_stderr(); }
  /// The next reply, if one arrived.
  virtual bool take_reply(WorkerReply&) { return false; }
  /// A line on the reply pipe that was not a reply (the child is then not to be trusted).
  virtual std::string protocol_error() const { return {}; }
  /// Every pipe reached its end: it has ended or is ending.
  virtual bool pipes_closed() const { return process().stderr_closed(); }
};

/// Makes the child for a slot that has none, `job` being its first run. Throws std::runtime_error
/// with the reason when none can be made.
using ChildMaker = std::function<std::unique_ptr<SupervisedChild>(const ProcessJob& job)>;

struct Supervision {
  ChildMaker make_child;
  std::string child_noun;  ///< in "a run was stopped by a signal sent to its NOUN"
  std::function<void(const ProcessJob&, const ProcessResult&)> on_done;
  std::function<void()> on_tick;  ///< about every 200 ms; may be empty
};

/// Runs `jobs` in at most `parallel` children; see the file comment. Returns false when interrupted
/// by SIGINT or SIGTERM (handled only while it runs) or when a run was stopped by one sent to it
/// directly; the children still running are then stopped, and their runs not reported.
bool supervise(const std::vector<ProcessJob>& jobs, int parallel, const Supervision& how);

}  // namespace signalsim
