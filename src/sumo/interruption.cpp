#include "sumo/interruption.hpp"

#include <csignal>

namespace signalsim::sumo {
namespace {

volatile std::sig_atomic_t requested = 0;

void on_signal(int) { requested = 1; }

}  // namespace

void install_interruption_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = 0;  // no SA_RESTART: a blocked recv() returns EINTR and libtraci throws
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interruption_requested() { return requested != 0; }

void throw_if_interrupted() {
  if (requested) throw Interrupted();
}

}  // namespace signalsim::sumo
