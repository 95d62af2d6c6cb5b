// Starting, watching, timing out, stopping and reaping a batch's children (child_supervisor.hpp).
#include "batch/child_supervisor.hpp"

#include <poll.h>
#include <sys/wait.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <thread>

#include "batch/interrupt_guard.hpp"
#include "report/exit_codes.hpp"

namespace signalsim {
namespace {

using Clock = std::chrono::steady_clock;
constexpr double kRound = 0.2;         // [s] longest wait for the children in one round
constexpr double kEndingRound = 0.02;  // [s] while a child that has ended is still to be reaped
constexpr auto kTermGrace = std::chrono::seconds(2);  // SIGTERM, then SIGKILL

// One place for a child: the child (none until a job needs it) and the run it is doing.
struct Slot {
  std::unique_ptr<SupervisedChild> child;
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

// How a reaped process ended: exit code or signal.
void set_end(int status, ProcessResult& result) {
  if (WIFEXITED(status)) {
    result.exited = true;
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    result.signal = WTERMSIG(status);
  }
}

// A run that replied: what `signalsim run` would have exited with, and its stderr.
Finished replied(Slot& slot, int exit_code) {
  Finished f{slot.job, {}};
  f.result.exited = true;
  f.result.exit_code = exit_code;
  f.result.stderr_text = slot.child->process().take_stderr();
  f.result.wall = seconds_since(slot.start);
  slot.job = nullptr;
  return f;
}

// A run whose (reaped) child ended without replying: it ended as its own process - killed by a
// signal (ours after a timeout, or a crash) or through exit().
Finished ended(Slot& slot) {
  Finished f{slot.job, {}};
  slot.child->read_available();
  f.result.stderr_text = slot.child->process().take_stderr();
  f.result.wall = seconds_since(slot.start);
  f.result.timed_out = slot.timed_out;
  set_end(slot.child->process().wait_status(), f.result);
  slot.job = nullptr;
  return f;
}

// Hands `job` to the slot's child, making one when there is none or it has ended while idle.
// False (with the reason) when no child takes it.
bool dispatch(Slot& slot, const ProcessJob& job, const ChildMaker& make_child, std::string& error) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (!slot.child) {
      try {
        slot.child = make_child(job);
      } catch (const std::exception& e) {
        error = e.what();
        return false;
      }
    }
    slot.child->process().take_stderr();  // what it wrote while idle belongs to no run
    if (slot.child->take_run(job)) {
      slot.job = &job;
      slot.start = Clock::now();
      slot.timed_out = false;
      return true;
    }
    slot.child.reset();  // it had ended while idle
  }
  error = "the worker ended before it took the run";
  return false;
}

bool ending(const Slot& slot) { return slot.child->pipes_closed() || slot.timed_out || slot.broken; }

// Whether the slot's child may be reaped now: a one-run process whenever it has ended (what it
// wrote is read after), a worker once its pipes closed (no reply lost) or it was killed.
bool may_reap(const Slot& slot) { return !slot.child->replies() || ending(slot); }

// Waits for output of any child, at most one round or until the nearest timeout.
void wait_for_children(const std::vector<Slot>& slots) {
  double wait = kRound;
  std::vector<pollfd> fds;
  bool busy = false;
  for (const Slot& slot : slots) {
    if (!slot.child) continue;
    slot.child->add_poll_fds(fds);
    if (ending(slot)) wait = std::min(wait, kEndingRound);
    if (!slot.job) continue;
    busy = true;
    if (slot.job->timeout > 0 && !slot.timed_out)
      wait = std::min(wait, std::max(0.0, slot.job->timeout - seconds_since(slot.start)));
  }
  if (!fds.empty()) poll(fds.data(), fds.size(), static_cast<int>(wait * 1000.0) + 1);
  else if (busy) std::this_thread::sleep_for(std::chrono::duration<double>(wait));
}

// Takes the replies that arrived. A run that finished goes to `finished`; one that a SIGINT or
// SIGTERM stopped (it replied 130 or 143: the signal reached the worker itself) did not finish -
// no row - and sets `stopped`. True when the worker said it ends after its reply.
bool take_replies(Slot& slot, std::vector<Finished>& finished, bool& stopped) {
  slot.child->read_available();
  bool last = false;
  for (WorkerReply reply; slot.child->take_reply(reply);) {
    last = last || reply.last;
    if (!slot.job) continue;
    Finished f = replied(slot, reply.exit_code);
    if (stopped_by_signal(f.result)) stopped = true;
    else finished.push_back(std::move(f));
  }
  return last;
}

// The slot's reaped child: its run (if any) ended with it. One that a SIGINT/SIGTERM of its own
// ended (before its handlers were installed, or a worker between two runs) sets `stopped`.
void child_ended(Slot& slot, std::vector<Finished>& finished, bool& stopped) {
  Finished f{slot.job, {}};
  if (slot.job) {
    f = ended(slot);
    const std::string problem = slot.child->protocol_error();
    if (slot.broken) f.result.stderr_text += (f.result.stderr_text.empty() ? "" : "\n") + problem;
  } else {
    set_end(slot.child->process().wait_status(), f.result);  // an idle worker
  }
  if (!slot.broken && stopped_by_signal(f.result)) stopped = true;
  else if (f.job) finished.push_back(std::move(f));
  slot.broken = false;
  slot.child.reset();  // the next job gets a new child
}

// Reads a child's replies and notices its end and its run's timeout; finished runs go to
// `finished`. `stopped`: a signal sent to the child itself stopped it.
void collect(Slot& slot, std::vector<Finished>& finished, bool& stopped) {
  if (!slot.child) return;
  if (take_replies(slot, finished, stopped)) {
    slot.child.reset();  // it ends by itself after this reply: the next job gets a new worker
    slot.broken = false;
    return;
  }
  if (may_reap(slot) && slot.child->process().reap(false)) {
    child_ended(slot, finished, stopped);
    return;
  }
  if (!slot.child->protocol_error().empty() && !slot.broken) {
    slot.broken = true;  // not the protocol: the worker is not trusted with more (its run fails)
    slot.child->process().signal_group(SIGKILL);
  }
  if (slot.job && !slot.timed_out && slot.job->timeout > 0 && seconds_since(slot.start) >= slot.job->timeout) {
    slot.timed_out = true;
    slot.child->process().signal_group(SIGKILL);
  }
}

void report(std::vector<Finished>& finished, const Supervision& how) {
  std::sort(finished.begin(), finished.end(), [](const Finished& a, const Finished& b) { return a.job->id < b.job->id; });
  for (const Finished& f : finished) how.on_done(*f.job, f.result);
  finished.clear();
}

// While stopping: takes the child's replies and, once it has ended, drops it. A one-run process
// that exited by itself (neither 130 nor 143) finished its run: reported. A worker's run ends only
// with a reply. True once the slot is empty.
bool settle(Slot& slot, std::vector<Finished>& finished) {
  if (!slot.child) return true;
  bool stopped = false;  // known already
  take_replies(slot, finished, stopped);
  if (!may_reap(slot) || !slot.child->process().reap(false)) return false;
  if (slot.job && !slot.child->replies()) {
    Finished f = ended(slot);
    if (f.result.exited && !stopped_by_signal(f.result)) finished.push_back(std::move(f));
  }
  slot.job = nullptr;
  slot.child.reset();
  return true;
}

// Interrupted: the runs that ended are reported, every child is stopped (SIGTERM, SIGKILL after
// the grace time); see settle for the runs that end meanwhile.
void stop_children(std::vector<Slot>& slots, const Supervision& how) {
  std::vector<Finished> finished;
  for (Slot& slot : slots) {
    if (settle(slot, finished)) continue;
    slot.child->close_requests();
    slot.child->process().signal_group(SIGTERM);
  }
  const auto deadline = Clock::now() + kTermGrace;
  while (Clock::now() < deadline) {
    std::vector<pollfd> fds;
    bool waiting = false;
    for (Slot& slot : slots) {
      if (settle(slot, finished)) continue;
      waiting = true;
      slot.child->add_poll_fds(fds);
    }
    if (!waiting) break;
    if (!fds.empty()) poll(fds.data(), fds.size(), static_cast<int>(kEndingRound * 1000.0));
    else std::this_thread::sleep_for(std::chrono::duration<double>(kEndingRound));
  }
  for (Slot& slot : slots) {  // SIGKILL to what is left, reaped
    if (!slot.child) continue;
    slot.child->process().signal_group(SIGKILL);
    slot.child->process().reap(true);
    settle(slot, finished);
    slot.child.reset();
  }
  report(finished, how);
}

}  // namespace

bool stopped_by_signal(const ProcessResult& result) {
  if (result.timed_out) return false;  // our SIGKILL: the run's own end, an error row
  if (result.exited) return result.exit_code == kExitInterrupted || result.exit_code == kExitTerminated;
  return result.signal == SIGINT || result.signal == SIGTERM;
}

bool supervise(const std::vector<ProcessJob>& jobs, int parallel, const Supervision& how) {
  InterruptGuard guard;
  std::vector<Slot> slots(std::min<std::size_t>(static_cast<std::size_t>(std::max(1, parallel)), jobs.size()));
  std::size_t next = 0;
  const auto busy = [&] { return std::any_of(slots.begin(), slots.end(), [](const Slot& s) { return s.job; }); };
  std::vector<Finished> finished;
  bool stopped = false;  // a signal sent to a child itself stopped its run: the batch stops too
  const auto stopping = [&] { return stopped || InterruptGuard::interrupted(); };
  while ((next < jobs.size() || busy()) && !stopping()) {
    for (Slot& slot : slots) {
      if (slot.job || next >= jobs.size() || stopping()) continue;
      const ProcessJob& job = jobs[next++];
      std::string error;
      if (!dispatch(slot, job, how.make_child, error)) {
        Finished f{&job, {}};
        f.result.stderr_text = error;
        finished.push_back(std::move(f));
      }
    }
    wait_for_children(slots);
    for (Slot& slot : slots) collect(slot, finished, stopped);
    report(finished, how);
    if (how.on_tick) how.on_tick();
  }
  if (!stopping()) return true;  // the idle workers are killed and reaped with `slots`
  if (stopped && !InterruptGuard::interrupted())
    std::fprintf(stderr, "signalsim: a run was stopped by a signal sent to its %s: the batch stops\n",
                 how.child_noun.c_str());
  stop_children(slots, how);
  return false;
}

}  // namespace signalsim
