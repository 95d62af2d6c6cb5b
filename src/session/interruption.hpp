// Ctrl-C and SIGTERM during a run: the handlers only set a flag (and make blocking socket calls return
// with EINTR); the step loop and the session's waits check it and unwind, so sumo-gui is stopped by its
// PID, temporary files are removed and the run directory says "interrupted" rather than keeping old
// files. The signal is remembered: `run` exits 128 + its number (130 SIGINT, 143 SIGTERM).
#pragma once

#include "session/sumo_session.hpp"

namespace signalsim::sumo {

/// A run stopped by SIGINT or SIGTERM.
class Interrupted : public SumoError {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

/// Installs the SIGINT and SIGTERM handlers (without SA_RESTART). Idempotent.
void install_interruption_handlers();
/// Whether a handled signal arrived.
bool interruption_requested();
/// The first handled signal (SIGINT or SIGTERM), 0 when none arrived.
int interruption_signal();
/// Throws Interrupted when one did.
void throw_if_interrupted();

}  // namespace signalsim::sumo
