// The embedded back-end: SUMO inside this process through libsumo (one simulation at a time per process,
// docs/behaviour.md §S1; a batch's persistent worker starts one after another, each closed at the end
// of its run). Built alone as the module libsignalsim_libsumo.so (session_factory.hpp). SUMO prints its
// errors to stderr and throws a bare "Process Error", so stderr is captured while the session lives and
// the message we report is SUMO's own first error line.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <sstream>

#include <libsumo/libsumo.h>

#include "session/session_impl.hpp"
#include "session/session_factory.hpp"
#include "session/sumo_command_line.hpp"

namespace signalsim::sumo {
namespace {

struct LibsumoApi {
  using Simulation = libsumo::Simulation;
  using Vehicle = libsumo::Vehicle;
  using VehicleType = libsumo::VehicleType;
  using Route = libsumo::Route;
  using Lane = libsumo::Lane;
  using Edge = libsumo::Edge;
  using TrafficLight = libsumo::TrafficLight;
  // In process the getters cost less than libsumo's subscriptions (session_impl.hpp).
  static constexpr bool kSubscribes = false;
};

// libsumo's state in this process: whether a simulation runs now, and whether a start ever failed
// (embedded_sumo_reusable).
struct LibsumoState {
  bool running = false;
  bool failed_start = false;
};
LibsumoState g_libsumo;

// Simulation::start, refused while one runs (libsumo would close it under its session's feet).
void start_libsumo(const std::vector<std::string>& command_line) {
  if (g_libsumo.running)
    throw SumoError("SUMO is already running in this process (libsumo runs one simulation at a time)");
  try {
    libsumo::Simulation::start(command_line);
  } catch (...) {
    g_libsumo.failed_start = true;
    throw;
  }
  g_libsumo.running = true;
}

void close_libsumo() noexcept {
  try {
    libsumo::Simulation::close();
  } catch (...) {  // closing must never throw out of a destructor
  }
  g_libsumo.running = false;
}

// SUMO's stderr, redirected into a nameless temporary file while the session lives.
class StderrCapture {
 public:
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;
  StderrCapture() {
    std::fflush(stderr);
    char name[] = "/tmp/signalsim-sumo-XXXXXX";
    fd_ = mkstemp(name);
    if (fd_ < 0) return;
    unlink(name);  // nameless from the start: a killed worker leaves nothing behind
    saved_ = dup(STDERR_FILENO);
    dup2(fd_, STDERR_FILENO);
  }
  ~StderrCapture() {
    if (saved_ >= 0) {
      std::fflush(stderr);
      dup2(saved_, STDERR_FILENO);
      close(saved_);
    }
    if (fd_ >= 0) close(fd_);
  }
  /// SUMO's first "Error: " line (else the first line) written so far.
  std::string first_error() const {
    if (fd_ < 0) return {};
    std::fflush(stderr);
    std::string text;
    char buf[4096];
    for (off_t at = 0;;) {
      const ssize_t n = pread(fd_, buf, sizeof buf, at);
      if (n <= 0) break;
      text.append(buf, static_cast<std::size_t>(n));
      at += n;
      if (text.size() > (1u << 20)) break;  // SUMO's first lines are enough
    }
    return first_error_line(text);
  }

 private:
  int fd_ = -1;
  int saved_ = -1;
};

class EmbeddedSession final : public SessionImpl<LibsumoApi> {
 public:
  explicit EmbeddedSession(const SessionConfig& config) : SessionImpl<LibsumoApi>(config) {
    try {
      start_libsumo(sumo_command_line(config, "sumo"));
    } catch (const std::exception& e) {
      throw SumoError("SUMO could not load the simulation: " + failure_reason(e));
    }
    started_ = true;
  }
  ~EmbeddedSession() override {
    if (started_) close_libsumo();
  }
  BackendKind backend() const override { return BackendKind::Embedded; }
  using SessionImpl<LibsumoApi>::insert_ego;

 protected:
  std::string failure_reason(const std::exception& e) const override {
    const std::string reason = capture_.first_error();
    return reason.empty() ? std::string(e.what()) : reason;
  }

 private:
  StderrCapture capture_;  // first member initialised: it sees SUMO's start-up messages
  bool started_ = false;
};

std::string libsumo_net_load_error(const std::string& net_path) {
  StderrCapture capture;  // SUMO's messages stay out of the user's terminal
  try {
    start_libsumo({"sumo", "--net-file", net_path, "--begin", "0", "--end", "0", "--no-step-log", "true",
                   "--duration-log.disable", "true", "--no-warnings", "true"});
  } catch (const std::exception& e) {
    const std::string reason = capture.first_error();
    return reason.empty() ? std::string(e.what()) : reason;
  }
  close_libsumo();  // loaded is what was asked
  return {};
}

bool libsumo_reusable() { return !g_libsumo.failed_start; }

std::unique_ptr<SumoSession> open_libsumo_session(const SessionConfig& config) {
  auto session = std::make_unique<EmbeddedSession>(config);
  session->insert_ego();
  return session;
}

}  // namespace
}  // namespace signalsim::sumo

// The module's entry (session_factory.hpp): the program looks it up by name after dlopen.
extern "C" const signalsim::sumo::EmbeddedBackend* signalsim_embedded_backend_v4() {
  using namespace signalsim::sumo;
  static const EmbeddedBackend backend{kEmbeddedBackendBuild, &open_libsumo_session, &libsumo_net_load_error,
                                        &libsumo_reusable};
  return &backend;
}
