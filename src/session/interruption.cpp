#include "session/interruption.hpp"

#include <csignal>

namespace signalsim::sumo {
namespace {

volatile std::sig_atomic_t requested = 0;  // the first signal's number

void on_signal(int signal) {
  if (requested == 0) requested = signal;
}

}  // namespace

Interrupted::Interrupted(int signal)
    : SumoError(std::string("interrupted by ") + (signal == SIGTERM ? "SIGTERM" : "SIGINT")), signal_(signal) {}

void install_interruption_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a blocked recv() returns EINTR and libtraci throws
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interruption_requested() { return requested != 0; }

int interruption_signal() { return requested; }

void throw_if_interrupted() {
  if (requested) throw Interrupted(requested);
}

}  // namespace signalsim::sumo
