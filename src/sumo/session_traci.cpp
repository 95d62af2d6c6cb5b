// The TraCI back-ends, through libtraci (the libsumo API over a socket, spec SUMO §1):
//   gui      signalsim starts sumo-gui on a free 127.0.0.1 port (--start --quit-on-end), connects,
//            colours the ego and tracks it in the view, and stops the program by its PID at the end;
//   connect  signalsim attaches to a SUMO someone else started with --remote-port and --num-clients,
//            takes its place in the stepping order (setOrder), checks the step length, and at the end
//            closes only its own connection: the simulation goes on for the other clients.
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <libsumo/libtraci.h>

#include "sumo/session_factory.hpp"
#include "sumo/session_impl.hpp"
#include "sumo/sumo_command_line.hpp"
#include "sumo/sumo_process.hpp"

namespace signalsim::sumo {
namespace {

struct LibtraciApi {
  using Simulation = libtraci::Simulation;
  using Vehicle = libtraci::Vehicle;
  using VehicleType = libtraci::VehicleType;
  using Route = libtraci::Route;
  using Lane = libtraci::Lane;
  using Edge = libtraci::Edge;
  using TrafficLight = libtraci::TrafficLight;
};

constexpr const char* kView = "View #0";
constexpr double kGuiStartTimeout = 30.0;  // [s] for sumo-gui to load the net and listen
constexpr double kGuiZoom = 1500.0;        // [%] about 60 m across the view: the ego and its blinkers

std::string short_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

std::string endpoint(const BackendOptions& b) { return b.host + ":" + std::to_string(b.port); }

// One connection attempt (libtraci's own retries print to stdout and wait 1 s each).
bool try_connect(int port, const std::string& host) {
  try {
    libtraci::Simulation::init(port, 0, host);
    return true;
  } catch (const std::exception&) {
    return false;
  }
}

class TraciSession final : public SessionImpl<LibtraciApi> {
 public:
  explicit TraciSession(const SessionConfig& config) : SessionImpl<LibtraciApi>(config) {
    // A server that goes away must be an error of the call that noticed it, not a SIGPIPE death.
    std::signal(SIGPIPE, SIG_IGN);
    if (config.backend.kind == BackendKind::Gui) start_gui();
    else attach();
    connected_ = true;
  }

  ~TraciSession() override {
    if (connected_) {
      try {
        libtraci::Simulation::close();  // connect: only this client leaves; gui: sumo-gui quits
      } catch (...) {  // a lost connection: nothing left to close
      }
    }
    if (gui_) gui_->wait_for_exit(5.0);  // then ~SumoProcess stops it by its PID
  }

  BackendKind backend() const override { return config_.backend.kind; }
  using SessionImpl<LibtraciApi>::insert_ego;

 protected:
  std::string failure_reason(const std::exception& e) const override {
    std::string reason = e.what();
    if (config_.backend.kind == BackendKind::Connect)
      reason = "the connection to SUMO at " + endpoint(config_.backend) + " failed or was lost: " + reason;
    if (gui_ && !gui_->running()) {
      const std::string said = first_error_line(gui_->output());
      reason = "sumo-gui ended" + (said.empty() ? std::string() : ": " + said);
    }
    return reason;
  }

  void on_ego_departed() override {
    if (config_.backend.kind != BackendKind::Gui) return;
    libtraci::Vehicle::setColor(ego_, libsumo::TraCIColor(255, 0, 255, 255));  // magenta: easy to find
    libtraci::GUI::trackVehicle(kView, ego_);
    libtraci::GUI::setZoom(kView, kGuiZoom);
    take_screenshot();  // replaced by the one at the first blinker, if any
  }

  void on_command(int signal_mask) override {
    if (config_.backend.kind != BackendKind::Gui || blinker_shot_ || (signal_mask & kBlinkerMask) == 0) return;
    blinker_shot_ = true;
    take_screenshot();
  }

  // sumo-gui draws in its own thread, after the step: the simulation waits until the picture of
  // this step is written, so that it shows the ego where it is (a fast run would be far ahead).
  void on_stepped() override {
    if (!screenshot_pending_) return;
    screenshot_pending_ = false;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    std::uintmax_t previous = 0;
    while (std::chrono::steady_clock::now() < until) {
      std::error_code missing;
      const std::uintmax_t size = std::filesystem::file_size(config_.backend.screenshot, missing);
      if (!missing && size > 0 && size == previous) return;  // written, and no longer growing
      previous = missing ? 0 : size;
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    throw SumoError("sumo-gui did not write the screenshot " + config_.backend.screenshot + " within 5 s");
  }

 private:
  void take_screenshot() {
    if (config_.backend.screenshot.empty()) return;
    std::error_code ignored;
    std::filesystem::remove(config_.backend.screenshot, ignored);  // on_stepped waits for the new one
    try {
      libtraci::GUI::screenshot(kView, config_.backend.screenshot);  // written when the step is drawn
    } catch (const std::exception& e) {
      throw SumoError("sumo-gui refused a screenshot: " + failure_reason(e));
    }
    screenshot_pending_ = true;
  }

  void start_gui() {
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0')
      throw SumoError("--gui needs a display, and DISPLAY is not set (run it on a desktop, or under xvfb-run)");
    const int port = free_local_port();
    std::vector<std::string> argv = sumo_command_line(config_, config_.backend.sumo_gui_binary);
    argv.insert(argv.end(), {"--remote-port", std::to_string(port), "--start", "true", "--quit-on-end", "true",
                             "--delay", std::to_string(config_.backend.gui_delay_ms), "--window-size", "1024,768"});
    gui_output_.path = (std::filesystem::temp_directory_path() /
                        ("signalsim-gui-" + std::to_string(getpid()) + "-" + std::to_string(port) + ".txt")).string();
    try {
      gui_ = std::make_unique<SumoProcess>(argv, gui_output_.path);
    } catch (const std::exception& e) {
      throw SumoError(std::string("--gui: ") + e.what());
    }
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kGuiStartTimeout);
    while (!try_connect(port, "127.0.0.1")) {
      if (!gui_->running()) {
        const std::string said = first_error_line(gui_->output());
        throw SumoError("sumo-gui could not start" + (said.empty() ? std::string() : ": " + said));
      }
      if (std::chrono::steady_clock::now() >= until)
        throw SumoError("sumo-gui did not accept a TraCI connection on port " + std::to_string(port) + " within " +
                        std::to_string(static_cast<int>(kGuiStartTimeout)) + " s");
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  }

  void attach() {
    const BackendOptions& b = config_.backend;
    // A few quick attempts: a server that was just started may not listen yet.
    bool connected = false;
    for (int attempt = 0; attempt < 5 && !connected; ++attempt) {
      if (attempt > 0) std::this_thread::sleep_for(std::chrono::milliseconds(200));
      connected = try_connect(b.port, b.host);
    }
    if (!connected)
      throw SumoError("cannot connect to SUMO at " + endpoint(b) +
                      ": connection refused (start it with: sumo -c FILE.sumocfg --remote-port " +
                      std::to_string(b.port) + " --num-clients N)");
    try {
      try {
        libtraci::Simulation::setOrder(b.client_order);
      } catch (const std::exception& e) {
        throw SumoError("SUMO at " + endpoint(b) + " refused client order " + std::to_string(b.client_order) + ": " +
                        e.what());
      }
      const double server_step = delta_t();
      if (std::abs(server_step - config_.step_length) > 1e-9)
        throw SumoError("the scenario's step_length " + short_number(config_.step_length) +
                        " s differs from the step length of SUMO at " + endpoint(b) + ", " +
                        short_number(server_step) + " s (Simulation::getDeltaT)");
    } catch (...) {
      try {
        libtraci::Simulation::close();  // leave politely: the other clients go on
      } catch (...) {
      }
      throw;
    }
  }

  // sumo-gui's own output (read for its first error line), removed after the process is stopped.
  struct TempFile {
    std::string path;
    ~TempFile() {
      std::error_code ignored;
      if (!path.empty()) std::filesystem::remove(path, ignored);
    }
  };
  TempFile gui_output_;             // destroyed after gui_ (declared before it)
  std::unique_ptr<SumoProcess> gui_;
  bool connected_ = false;
  bool blinker_shot_ = false;
  bool screenshot_pending_ = false;
};

}  // namespace

std::unique_ptr<SumoSession> open_traci_session(const SessionConfig& config) {
  auto session = std::make_unique<TraciSession>(config);
  session->insert_ego();
  return session;
}

}  // namespace signalsim::sumo
