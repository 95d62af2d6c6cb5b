// The TraCI back-ends, through libtraci (the libsumo API over a socket, docs/behaviour.md §S1):
//   gui      signalsim starts sumo-gui on a free 127.0.0.1 port (--start --quit-on-end), connects
//            (through the relay of traci_relay.hpp, without a time limit unless --traci-timeout
//            gives one: a user may pause sumo-gui), colours the ego and tracks it in the view (at
//            its blinker on and the junction ahead near, the view is zoomed out to it for the screenshot,
//            gui_framing.hpp), and stops the program by its PID at the end;
//   connect  signalsim attaches to a SUMO someone else started with --remote-port and --num-clients,
//            through a relay that checks every answer and bounds every wait (traci_relay.hpp), takes
//            its place in the stepping order (setOrder), checks the step length, and at the end
//            closes only its own connection: the simulation goes on for the other clients.
#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <unistd.h>

#include <libsumo/libtraci.h>

#include "session/gui_framing.hpp"
#include "session/session_factory.hpp"
#include "session/interruption.hpp"
#include "session/session_impl.hpp"
#include "session/sumo_command_line.hpp"
#include "session/sumo_process.hpp"
#include "session/traci_relay.hpp"

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
  // One subscribed answer a step instead of a round trip a variable (session_impl.hpp).
  static constexpr bool kSubscribes = true;
};

constexpr const char* kView = "View #0";
constexpr double kGuiStartTimeout = 30.0;  // [s] for sumo-gui to load the net and listen
constexpr double kGuiZoom = 1500.0;        // [%] about 60 m across the view: the ego and its blinkers

// Whether the user's options already give `name` (SUMO refuses an option given twice).
bool gives_option(const std::vector<std::string>& args, const std::string& name) {
  return std::find(args.begin(), args.end(), "--" + name) != args.end();
}

double parse_number(const std::string& text) {
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return 0.0;
  }
}

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string endpoint(const BackendOptions& b) { return b.host + ":" + std::to_string(b.port); }

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
      // connect: the simulation goes on for the other clients, without signalsim's ego (not after
      // the relay ended the connection: nothing would reach the server)
      if (config_.backend.kind == BackendKind::Connect && relay_failure().empty()) release_ego();
      try {
        libtraci::Simulation::close();  // connect: only this client leaves; gui: sumo-gui quits
      } catch (...) {  // a lost connection: nothing left to close
      }
    }
    // then ~SumoProcess stops it by its PID (at once when the connection failed: it may be frozen)
    if (gui_ && relay_failure().empty()) gui_->wait_for_exit(5.0);
  }

  BackendKind backend() const override { return config_.backend.kind; }
  std::vector<std::pair<std::string, std::string>> server_options() const override { return server_options_; }
  using SessionImpl<LibtraciApi>::insert_ego;

 protected:
  std::string failure_reason(const std::exception& e) const override {
    if (gui_ && !gui_->running()) {
      const std::string said = gui_error();
      return "sumo-gui ended" + (said.empty() ? std::string() : ": " + said);
    }
    // The relay ended the connection: its reason, not libtraci's "peer shutdown".
    if (std::string relayed = relay_failure(); !relayed.empty()) return relayed;
    std::string reason = e.what();
    // SUMO answered with an error (TraCIException): a refusal, not a lost connection.
    const bool refused = dynamic_cast<const libsumo::TraCIException*>(&e) != nullptr;
    if (config_.backend.kind == BackendKind::Connect && !refused)
      reason = "the connection to SUMO at " + endpoint(config_.backend) + " failed or was lost: " + reason;
    return reason;
  }

  void on_ego_departed() override {
    if (config_.backend.kind != BackendKind::Gui) return;
    libtraci::Vehicle::setColor(ego_, libsumo::TraCIColor(255, 0, 255, 255));  // magenta: easy to find
    libtraci::GUI::trackVehicle(kView, ego_);
    libtraci::GUI::setZoom(kView, config_.backend.gui_zoom > 0.0 ? config_.backend.gui_zoom : kGuiZoom);
    shots_left_ = kShotsPerPicture;  // the view at departure, replaced by the one at the first blinker
  }

  // At the first blinker the view at the default zoom is taken; while the blinker is on, the first
  // step the junction ahead is near replaces it with the view zoomed out to that junction
  // (gui_framing.hpp): the picture answers where the blinker is for.
  void on_command(int signal_mask) override {
    if (config_.backend.kind != BackendKind::Gui) return;
    const bool blinking = (signal_mask & kBlinkerMask) != 0;
    if (!blinker_seen_ && blinking) {
      blinker_seen_ = true;
      shots_left_ = kShotsPerPicture;
      picture_ = GuiPicture{};
    }
    if (blinking && !framed_ && !config_.backend.screenshot.empty() && frame_view()) {
      framed_ = true;
      shots_left_ = kShotsPerPicture;
    }
    if (shots_left_ > 0) take_screenshot();
  }

  std::optional<GuiPicture> gui_picture() const override {
    if (!picture_taken_) return std::nullopt;
    return picture_;
  }

  // sumo-gui draws in its own thread, after the step: the simulation waits until the picture of
  // this step is written, so that it shows the ego where it is (a fast run would be far ahead).
  void on_stepped() override {
    if (!screenshot_pending_) return;
    screenshot_pending_ = false;
    --shots_left_;
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
    picture_taken_ = true;
    picture_.time = time();  // the row whose command this picture follows (the last one taken is kept)
  }

  bool frame_view() {
    try {
      std::optional<GuiPicture> framed = frame_junction_ahead(kView, ego_);
      if (!framed) return false;
      picture_ = *framed;
      return true;
    } catch (const libsumo::TraCIException&) {  // sumo-gui refused a view change: the view keeps the ego
      return false;
    } catch (const std::exception& e) {
      throw SumoError("sumo-gui: framing the view failed: " + failure_reason(e));
    }
  }

  void start_gui() {
    const char* display = std::getenv("DISPLAY");
    if (display == nullptr || *display == '\0')
      throw SumoError("--gui needs a display, and DISPLAY is not set (run it on a desktop, or under xvfb-run)");
    const int port = free_local_port();
    std::vector<std::string> argv = sumo_command_line(config_, config_.backend.sumo_gui_binary);
    // SUMO 1.15 waits --delay x step length between steps: --gui-delay MS is per step.
    const double delay = config_.backend.gui_delay_ms / config_.step_length;
    argv.insert(argv.end(), {"--remote-port", std::to_string(port), "--start", "true", "--quit-on-end", "true",
                             "--delay", exact_number(delay)});
    if (!gives_option(config_.extra_args, "window-size")) argv.insert(argv.end(), {"--window-size", "1024,768"});
    gui_output_.path = (std::filesystem::temp_directory_path() /
                        ("signalsim-gui-" + std::to_string(getpid()) + "-" + std::to_string(port) + ".txt")).string();
    try {
      gui_ = std::make_unique<SumoProcess>(argv, gui_output_.path);
    } catch (const std::exception& e) {
      throw SumoError(std::string("--gui: ") + e.what());
    }
    connect_gui(port);
  }

  // Connects to the sumo-gui just started, through a relay, once it listens (it has loaded the net).
  void connect_gui(int port) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(kGuiStartTimeout);
    const RelayLimits limits{config_.backend.traci_timeout, kMaxTraciMessage};
    while (!relay_) {
      throw_if_interrupted();
      if (!gui_->running()) {
        const std::string said = gui_error();
        throw SumoError("sumo-gui could not start" + (said.empty() ? std::string() : ": " + said));
      }
      try {
        relay_ = std::make_unique<TraciRelay>("127.0.0.1", port, limits);
      } catch (const Interrupted&) {
        throw;
      } catch (const SumoError&) {  // not listening yet
        if (std::chrono::steady_clock::now() >= until)
          throw SumoError("sumo-gui did not accept a TraCI connection on port " + std::to_string(port) + " within " +
                          std::to_string(static_cast<int>(kGuiStartTimeout)) + " s");
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
      }
    }
    // Another program could have taken the port between free_local_port() and sumo-gui's bind: then
    // our sumo-gui has ended and the connection is someone else's.
    if (!gui_->running()) throw SumoError("sumo-gui could not start: " + gui_error());
    try {
      libtraci::Simulation::init(relay_->client_port(), 0, "127.0.0.1");  // asks sumo-gui's version
    } catch (const std::exception& e) {
      leave();
      throw SumoError("sumo-gui did not answer TraCI: " + failure_reason(e));
    }
  }

  // sumo-gui's first error: what it printed, else (with --log) its log file.
  std::string gui_error() const {
    std::string said = first_error_line(gui_->output());
    if (said.empty() && !config_.log_file.empty()) said = first_error_line(read_text(config_.log_file));
    return said;
  }

  void attach() {
    const BackendOptions& b = config_.backend;
    relay_ = std::make_unique<TraciRelay>(b.host, b.port, RelayLimits{b.traci_timeout, kMaxTraciMessage});
    try {
      libtraci::Simulation::init(relay_->client_port(), 0, "127.0.0.1");  // asks SUMO's version
    } catch (const std::exception& e) {
      leave();
      throw SumoError(failure_reason(e));
    }
    try {
      try {
        libtraci::Simulation::setOrder(b.client_order);
      } catch (const libsumo::TraCIException& e) {
        throw SumoError("SUMO at " + endpoint(b) + " refused client order " + std::to_string(b.client_order) + ": " +
                        e.what());
      }
      const double server_step = delta_t();
      if (std::abs(server_step - config_.step_length) > 1e-9)
        throw SumoError("the scenario's step_length " + short_number(config_.step_length) +
                        " s differs from the step length of SUMO at " + endpoint(b) + ", " +
                        short_number(server_step) + " s (Simulation::getDeltaT)");
      for (const char* option : {"net-file", "route-files", "additional-files", "seed", "collision.action",
                                 "time-to-teleport", "lateral-resolution", "lanechange.duration"})
        server_options_.emplace_back(option, libtraci::Simulation::getOption(option));
      // Lateral motion needs SUMO's sublane model or its continuous lane change, which only the
      // server's start can switch on; a server's sublane model also drives a lane change.
      const bool server_sublane = parse_number(libtraci::Simulation::getOption("lateral-resolution")) > 0.0;
      const bool server_continuous =
          parse_number(libtraci::Simulation::getOption("lanechange.duration")) > server_step + 1e-9;
      if (continuous_lane_change_ && server_sublane) sublane_ = true, continuous_lane_change_ = false;
      if (config_.lateral_resolution > 0.0 && !server_sublane)
        throw SumoError("the scenario drives lateral motion (a maneuver beside a lane's centre), which needs "
                        "SUMO's sublane model: start SUMO at " + endpoint(b) + " with --lateral-resolution " +
                        short_number(config_.lateral_resolution));
      if (continuous_lane_change_ && !server_continuous)
        throw SumoError("the scenario drives a lane change, which needs SUMO's continuous lane change or its "
                        "sublane model: start SUMO at " + endpoint(b) + " with --lanechange.duration " +
                        short_number(config_.lane_change_duration) + " (or --lateral-resolution)");
    } catch (const SumoError&) {
      leave();
      throw;
    } catch (const std::exception& e) {
      leave();
      throw SumoError(failure_reason(e));
    }
  }

  // Why the relay ended the connection; "" while it relays (or before it started).
  std::string relay_failure() const { return relay_ ? relay_->failure() : std::string(); }

  static void leave() noexcept {
    try {
      libtraci::Simulation::close();  // leave politely: the other clients go on
    } catch (...) {
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
  std::unique_ptr<TraciRelay> relay_;  // between libtraci and the server; closed after libtraci
  bool connected_ = false;
  std::vector<std::pair<std::string, std::string>> server_options_;  // connect: as the server reports them
  // A busy sumo-gui may draw the first frame after a view change without the vehicles: each picture
  // is taken on two consecutive steps, the second one kept.
  static constexpr int kShotsPerPicture = 2;
  int shots_left_ = 0;
  bool blinker_seen_ = false;
  bool framed_ = false;  // the view was framed on a junction ahead
  bool screenshot_pending_ = false;
  bool picture_taken_ = false;
  GuiPicture picture_;  // what the kept screenshot shows
};

}  // namespace

std::unique_ptr<SumoSession> open_traci_session(const SessionConfig& config) {
  auto session = std::make_unique<TraciSession>(config);
  session->insert_ego();
  return session;
}

}  // namespace signalsim::sumo
