// The SIGINT/SIGTERM flag and its handlers (interruption.hpp).
#include "session/interruption.hpp"

#include <atomic>
#include <csignal>

namespace signalsim::sumo {
namespace {

// The first signal's number. Atomic: the handler writes it, and TraCI's relay thread
// (traci_relay.hpp) reads it too.
std::atomic<int> requested{0};
static_assert(std::atomic<int>::is_always_lock_free, "written by a signal handler");

void on_signal(int signal) {
  int none = 0;
  requested.compare_exchange_strong(none, signal);
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
  if (const int signal = requested) throw Interrupted(signal);
}

}  // namespace signalsim::sumo
