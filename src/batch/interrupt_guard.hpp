// Ctrl-C and SIGTERM while a batch's runs are prepared (the scenarios loaded, a sweep expanded) and
// under way (child_supervisor, the Slurm wait): while an InterruptGuard lives, SIGINT and SIGTERM only
// set a flag (no SA_RESTART, so a blocking poll or read returns at once) and SIGPIPE is ignored (a
// worker that died must not take the batch with it when it is written to) and SIGCHLD is at its
// default (so waitpid sees how each worker ended); the previous handlers come back when it ends.
// Guards nest: the flag is cleared only by the outermost, so a signal while the runs were prepared
// still stops them.
#pragma once

#include <csignal>
#include <stdexcept>

namespace signalsim {

/// A batch stopped by SIGINT or SIGTERM before its runs started (InterruptGuard::throw_if_interrupted):
/// the command exits 130 (kExitInterrupted) and nothing ran.
class BatchInterrupted : public std::runtime_error {
 public:
  BatchInterrupted() : std::runtime_error("interrupted before any run started; nothing ran") {}
};

class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Whether SIGINT or SIGTERM arrived since the outermost guard was made.
  static bool interrupted();
  /// Throws BatchInterrupted when one did (the long loops that prepare a batch's runs call it).
  static void throw_if_interrupted();

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
  struct sigaction old_pipe_ {};
  struct sigaction old_chld_ {};
};

}  // namespace signalsim
