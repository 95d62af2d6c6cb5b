// A batch's runs in persistent workers (worker_pool.hpp).
#include "batch/worker_pool.hpp"

#include <poll.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <thread>

#include "batch/interrupt_guard.hpp"
#include "batch/worker_process.hpp"

namespace signalsim {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kRound = 0.2;        // [s] longest wait for the workers in one round
constexpr double kEndingRound = 0.02; // [s] while a worker that has ended is still to be reaped
constexpr auto kTermGrace = std::chrono::seconds(2);  // SIGTERM, then SIGKILL

// One place for a worker: the process (none until a job needs it) and the run it is doing.
struct Slot {
  std::unique_ptr<WorkerProcess> worker;
  const ProcessJob* job = nullptr;
  Clock::time_point start;
  bool timed_out = false;
  bool broken = false;  // it wrote something that is not a reply
};

struct Finished {
  const ProcessJob* job = nullptr;
  ProcessResult result;
};

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// A run that replied: what `signalsim run` would have exited with, and its stderr.
Finished replied(Slot& slot, int exit_code) {
  Finished f{slot.job, {}};
  f.result.exited = true;
  f.result.exit_code = exit_code;
  f.result.stderr_text = slot.worker->take_stderr();
  f.result.wall = seconds_since(slot.start);
  slot.job = nullptr;
  return f;
}

// A run whose (reaped) worker ended without replying: it ended as its own process would have -
// killed by a signal (ours after a timeout, or a crash) or through exit().
Finished ended(Slot& slot) {
  Finished f{slot.job, {}};
  slot.worker->read_available();
  f.result.stderr_text = slot.worker->take_stderr();
  f.result.wall = seconds_since(slot.start);
  f.result.timed_out = slot.timed_out;
  const int status = slot.worker->wait_status();
  if (WIFEXITED(status)) {
    f.result.exited = true;
    f.result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    f.result.signal = WTERMSIG(status);
  }
  slot.job = nullptr;
  return f;
}

// Hands `job` to the slot's worker, starting one when there is none or it has ended while idle.
// False (with the reason) when no worker takes it.
bool dispatch(Slot& slot, const ProcessJob& job, std::string& error) {
  const std::vector<std::string> args(job.argv.begin() + 1, job.argv.end());
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (!slot.worker) {
      try {
        slot.worker = std::make_unique<WorkerProcess>(job.argv.front());
      } catch (const std::exception& e) {
        error = e.what();
        return false;
      }
    }
    slot.worker->take_stderr();  // what it wrote while idle belongs to no run
    if (slot.worker->send(args)) {
      slot.job = &job;
      slot.start = Clock::now();
      slot.timed_out = false;
      return true;
    }
    slot.worker.reset();  // it had ended while idle
  }
  error = "the worker ended before it took the run";
  return false;
}

// Waits for output of any worker, at most one round or until the nearest timeout.
void wait_for_workers(const std::vector<Slot>& slots) {
  double wait = kRound;
  std::vector<pollfd> fds;
  bool busy = false;
  for (const Slot& slot : slots) {
    if (!slot.worker) continue;
    slot.worker->add_poll_fds(fds);
    if (slot.worker->pipes_closed() || slot.timed_out || slot.broken) wait = std::min(wait, kEndingRound);
    if (!slot.job) continue;
    busy = true;
    if (slot.job->timeout > 0 && !slot.timed_out)
      wait = std::min(wait, std::max(0.0, slot.job->timeout - seconds_since(slot.start)));
  }
  if (!fds.empty()) poll(fds.data(), fds.size(), static_cast<int>(wait * 1000.0) + 1);
  else if (busy) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
}

// Takes the replies that arrived. A run that finished goes to `finished`; one that a SIGINT or
// SIGTERM stopped (it replied 130 or 143: the signal reached the worker itself, as Slurm's scancel
// signals every process of a task) did not finish - no row - and sets `stopped`. True when the
// worker said it ends after its reply.
bool take_replies(Slot& slot, std::vector<Finished>& finished, bool& stopped) {
  slot.worker->read_available();
  bool last = false;
  for (WorkerReply reply; slot.worker->take_reply(reply);) {
    last = last || reply.last;
    if (!slot.job) continue;
    Finished f = replied(slot, reply.exit_code);
    if (stopped_by_signal(f.result)) stopped = true;
    else finished.push_back(std::move(f));
  }
  return last;
}

// Reads a worker's replies and notices its end and its run's timeout; finished runs go to
// `finished`. `stopped`: a signal sent to the worker itself stopped it (take_replies).
void collect(Slot& slot, std::vector<Finished>& finished, bool& stopped) {
  if (!slot.worker) return;
  const bool last = take_replies(slot, finished, stopped);
  if (last) {
    slot.worker.reset();  // it ends by itself after this reply: the next job gets a new worker
    slot.broken = false;
    return;
  }
  if (!slot.worker->reply_error().empty() && !slot.broken) {
    slot.broken = true;  // not the protocol: the worker is not trusted with more (its run fails)
    slot.worker->signal_group(SIGKILL);
  }
  if (slot.job && !slot.timed_out && slot.job->timeout > 0 && seconds_since(slot.start) >= slot.job->timeout) {
    slot.timed_out = true;
    slot.worker->signal_group(SIGKILL);
  }
  const bool ending = slot.worker->pipes_closed() || slot.timed_out || slot.broken;
  if (!ending || !slot.worker->reap(false)) return;
  if (slot.job) {
    Finished f = ended(slot);
    if (slot.broken) f.result.stderr_text += (f.result.stderr_text.empty() ? "" : "\n") + slot.worker->reply_error();
    // Ended without a reply through a SIGINT/SIGTERM of its own (before its handlers were installed,
    // or between two runs): its run did not finish either.
    if (!slot.broken && stopped_by_signal(f.result)) stopped = true;
    else finished.push_back(std::move(f));
  } else {
    ProcessResult idle;  // an idle worker that such a signal ended: the same stop
    const int status = slot.worker->wait_status();
    idle.exited = WIFEXITED(status);
    idle.exit_code = idle.exited ? WEXITSTATUS(status) : -1;
    idle.signal = WIFSIGNALED(status) ? WTERMSIG(status) : 0;
    if (!slot.broken && stopped_by_signal(idle)) stopped = true;
  }
  slot.broken = false;
  slot.worker.reset();  // the next job gets a new worker
}

void report(std::vector<Finished>& finished,
            const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done) {
  std::sort(finished.begin(), finished.end(), [](const Finished& a, const Finished& b) { return a.job->id < b.job->id; });
  for (const Finished& f : finished) on_done(*f.job, f.result);
  finished.clear();
}

// Interrupted: the runs that ended are reported, every worker is stopped (SIGTERM, SIGKILL after the
// grace time). A run that ends by itself meanwhile is reported; one a signal stopped (130, 143: ours,
// or one that reached the worker before it) not.
void stop_workers(std::vector<Slot>& slots,
                  const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done) {
  std::vector<Finished> finished;
  bool stopped = false;  // known already
  for (Slot& slot : slots) {
    if (!slot.worker) continue;
    take_replies(slot, finished, stopped);
    slot.worker->close_requests();
    slot.worker->signal_group(SIGTERM);
  }
  const auto deadline = Clock::now() + kTermGrace;
  while (Clock::now() < deadline) {
    bool waiting = false;
    std::vector<pollfd> fds;
    for (Slot& slot : slots) {
      if (!slot.worker) continue;
      take_replies(slot, finished, stopped);
      if (slot.worker->pipes_closed() && slot.worker->reap(false)) {
        slot.job = nullptr;  // ended without a reply: stopped, no row
        slot.worker.reset();
        continue;
      }
      waiting = true;
      slot.worker->add_poll_fds(fds);
    }
    if (!waiting) break;
    if (!fds.empty()) poll(fds.data(), fds.size(), static_cast<int>(kEndingRound * 1000.0));
    else std::this_thread::sleep_for(std::chrono::duration<double>(kEndingRound));
  }
  for (Slot& slot : slots) slot.worker.reset();  // SIGKILL to what is left, reaped
  report(finished, on_done);
}

}  // namespace

bool run_in_workers(const std::vector<ProcessJob>& jobs, int parallel,
                    const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                    const std::function<void()>& on_tick) {
  InterruptGuard guard;
  std::vector<Slot> slots(std::min<std::size_t>(static_cast<std::size_t>(std::max(1, parallel)), jobs.size()));
  std::size_t next = 0;
  const auto busy = [&] { return std::any_of(slots.begin(), slots.end(), [](const Slot& s) { return s.job; }); };
  std::vector<Finished> finished;
  bool stopped = false;  // a signal sent to a worker itself stopped its run: the batch stops too
  const auto stopping = [&] { return stopped || InterruptGuard::interrupted(); };
  while ((next < jobs.size() || busy()) && !stopping()) {
    for (Slot& slot : slots) {
      if (slot.job || next >= jobs.size() || stopping()) continue;
      const ProcessJob& job = jobs[next++];
      std::string error;
      if (!dispatch(slot, job, error)) {
        Finished f{&job, {}};
        f.result.stderr_text = error;
        finished.push_back(std::move(f));
      }
    }
    wait_for_workers(slots);
    for (Slot& slot : slots) collect(slot, finished, stopped);
    report(finished, on_done);
    if (on_tick) on_tick();
  }
  if (stopping()) {
    if (stopped && !InterruptGuard::interrupted())
      std::fprintf(stderr, "signalsim: a run was stopped by a signal sent to its worker: the batch stops\n");
    stop_workers(slots, on_done);
    return false;
  }
  return true;  // the idle workers are killed and reaped with `slots`
}

bool run_jobs(const std::vector<ProcessJob>& jobs, int parallel, bool isolate,
              const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
              const std::function<void()>& on_tick) {
  if (isolate) return run_processes(jobs, parallel, on_done, on_tick);
  return run_in_workers(jobs, parallel, on_done, on_tick);
}

}  // namespace signalsim
