// Ctrl-C and SIGTERM while a batch's runs are under way (child_supervisor, the Slurm wait): while an
// InterruptGuard lives, SIGINT and SIGTERM only set a flag (no SA_RESTART, so a blocking poll or
// read returns at once) and SIGPIPE is ignored (a worker that died must not take the batch with it
// when it is written to) and SIGCHLD is at its default (so waitpid sees how each worker ended); the
// previous handlers come back when it ends.
#pragma once

#include <csignal>

namespace signalsim {

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Whether SIGINT or SIGTERM arrived since the guard was made.
  static bool interrupted();

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
  struct sigaction old_pipe_ {};
  struct sigaction old_chld_ {};
};

}  // namespace signalsim
