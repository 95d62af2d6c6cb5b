#include "sumo/sumo_session.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <libsumo/libsumo.h>

namespace signalsim::sumo {
namespace {

constexpr const char* kEgo = "ego";
constexpr const char* kEgoRoute = "signalsim_ego_route";
constexpr const char* kEgoType = "signalsim_ego_type";

std::string number(double v) {
  std::ostringstream out;
  out << std::setprecision(17) << v;
  return out.str();
}

// SUMO prints its load errors to stderr and throws a bare "Process Error": capture stderr while
// it starts so the message we report is SUMO's own first error line.
class StderrCapture {
 public:
  StderrCapture() {
    std::fflush(stderr);
    char name[] = "/tmp/signalsim-sumo-XXXXXX";
    fd_ = mkstemp(name);
    if (fd_ < 0) return;
    path_ = name;
    saved_ = dup(STDERR_FILENO);
    dup2(fd_, STDERR_FILENO);
  }
  ~StderrCapture() { restore(); if (!path_.empty()) std::remove(path_.c_str()); }
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, STDERR_FILENO);
    close(saved_);
    close(fd_);
    saved_ = -1;
  }
  std::string first_error() const {
    std::ifstream in(path_);
    std::string line, first_line;
    while (std::getline(in, line)) {
      if (line.rfind("Error: ", 0) == 0) return line.substr(7);
      if (first_line.empty() && !line.empty()) first_line = line;
    }
    return first_line;
  }

 private:
  std::string path_;
  int fd_ = -1;
  int saved_ = -1;
};

bool contains(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

}  // namespace

SumoSession::SumoSession(const SessionConfig& config) {
  std::vector<std::string> args = {"sumo", "-n", config.net, "--step-length", number(config.step_length),
                                   "--seed", std::to_string(config.seed), "--time-to-teleport", "-1",
                                   "--collision.action", "warn", "--no-step-log", "true",
                                   "--no-warnings", "true", "--duration-log.disable", "true"};
  if (!config.additional.empty()) {
    std::string joined;
    for (const auto& a : config.additional) joined += (joined.empty() ? "" : ",") + a;
    args.insert(args.end(), {"-a", joined});
  }
  {
    StderrCapture capture;
    try {
      libsumo::Simulation::start(args);
    } catch (const std::exception& e) {
      capture.restore();
      const std::string reason = capture.first_error();
      throw SumoError("SUMO could not load the simulation: " + (reason.empty() ? std::string(e.what()) : reason));
    }
  }
  try {
    libsumo::Route::add(kEgoRoute, config.route);
    libsumo::VehicleType::copy("DEFAULT_VEHTYPE", kEgoType);
    libsumo::VehicleType::setLength(kEgoType, config.length);
    libsumo::VehicleType::setMaxSpeed(kEgoType, config.max_speed);
    libsumo::VehicleType::setAccel(kEgoType, config.accel);
    libsumo::VehicleType::setDecel(kEgoType, config.decel);
    libsumo::VehicleType::setEmergencyDecel(kEgoType, config.emergency_decel);
    libsumo::VehicleType::setImperfection(kEgoType, 0.0);  // deterministic driving: no dawdling
    libsumo::Vehicle::add(kEgo, kEgoRoute, kEgoType, "0", std::to_string(config.depart_lane),
                          number(config.depart_pos), number(config.depart_speed));
    // Wait for the insertion (the lane may be blocked for a while).
    for (int i = 0; i < 600; ++i) {
      libsumo::Simulation::step();
      if (contains(libsumo::Simulation::getDepartedIDList(), kEgo)) {
        // spec SUMO §4: speed mode 15 = safe speed, max accel/decel, right of way, but no red-light
        // braking: the traffic-light judge alone decides at lights.
        libsumo::Vehicle::setSpeedMode(kEgo, 15);
        if (config.keep_planned_lanes) libsumo::Vehicle::setLaneChangeMode(kEgo, 0);
        return;
      }
    }
  } catch (const libsumo::TraCIException& e) {
    libsumo::Simulation::close();
    throw SumoError(std::string("SUMO rejected the ego: ") + e.what());
  }
  libsumo::Simulation::close();
  throw SumoError("the ego could not be inserted within 600 steps (its departure lane stays blocked)");
}

SumoSession::~SumoSession() {
  try {
    libsumo::Simulation::close();
  } catch (...) {  // closing must never throw out of a destructor
  }
}

bool SumoSession::step() {
  try {
    libsumo::Simulation::step();
    for (const auto& c : libsumo::Simulation::getCollisions())
      if (c.collider == kEgo || c.victim == kEgo) ++ego_collisions_;
    return !contains(libsumo::Simulation::getArrivedIDList(), kEgo);
  } catch (const libsumo::TraCIException& e) {
    throw SumoError(std::string("SUMO failed during a step: ") + e.what());
  }
}

double SumoSession::time() const { return libsumo::Simulation::getTime(); }

EgoState SumoSession::ego() const {
  try {
    EgoState s;
    s.time = libsumo::Simulation::getTime();
    s.edge = libsumo::Vehicle::getRoadID(kEgo);
    s.lane = libsumo::Vehicle::getLaneID(kEgo);
    s.lane_pos = libsumo::Vehicle::getLanePosition(kEgo);
    s.speed = libsumo::Vehicle::getSpeed(kEgo);
    s.accel = libsumo::Vehicle::getAcceleration(kEgo);
    const auto p = libsumo::Vehicle::getPosition(kEgo);
    s.x = p.x;
    s.y = p.y;
    s.lateral_offset = libsumo::Vehicle::getLateralLanePosition(kEgo);
    return s;
  } catch (const libsumo::TraCIException& e) {
    throw SumoError(std::string("SUMO could not report the ego: ") + e.what());
  }
}

int SumoSession::ego_signals() const {
  try {
    return libsumo::Vehicle::getSignals(kEgo);
  } catch (const libsumo::TraCIException& e) {
    throw SumoError(std::string("SUMO could not report the ego's signals: ") + e.what());
  }
}

void SumoSession::command(int signal_mask, double speed) {
  try {
    libsumo::Vehicle::setSignals(kEgo, signal_mask);
    libsumo::Vehicle::setSpeed(kEgo, speed);
  } catch (const libsumo::TraCIException& e) {
    throw SumoError(std::string("SUMO refused a command for the ego: ") + e.what());
  }
}

std::string SumoSession::light_state(const std::string& tls_id) const {
  try {
    return libsumo::TrafficLight::getRedYellowGreenState(tls_id);
  } catch (const libsumo::TraCIException& e) {
    throw SumoError("SUMO does not know traffic light '" + tls_id + "': " + e.what());
  }
}

std::vector<std::string> SumoSession::program_states(const std::string& tls_id) const {
  try {
    std::vector<std::string> states;
    for (const auto& logic : libsumo::TrafficLight::getAllProgramLogics(tls_id))
      for (const auto& phase : logic.phases) states.push_back(phase->state);
    return states;
  } catch (const libsumo::TraCIException& e) {
    throw SumoError("SUMO does not know traffic light '" + tls_id + "': " + e.what());
  }
}

void SumoSession::shift_light_program(const std::string& tls_id, double offset) {
  try {
    const std::string program = libsumo::TrafficLight::getProgram(tls_id);
    for (const auto& logic : libsumo::TrafficLight::getAllProgramLogics(tls_id)) {
      if (logic.programID != program) continue;
      double cycle = 0.0;
      for (const auto& phase : logic.phases) cycle += phase->duration;
      if (cycle <= 0.0) return;
      // Where the cycle stands now, plus the offset: that phase, with the rest of its duration.
      const double now = libsumo::Simulation::getTime();
      double into = std::fmod(now + offset, cycle);
      if (into < 0) into += cycle;
      for (std::size_t i = 0; i < logic.phases.size(); ++i) {
        const double duration = logic.phases[i]->duration;
        if (into < duration) {
          libsumo::TrafficLight::setPhase(tls_id, static_cast<int>(i));
          libsumo::TrafficLight::setPhaseDuration(tls_id, duration - into);
          return;
        }
        into -= duration;
      }
      return;
    }
  } catch (const libsumo::TraCIException& e) {
    throw SumoError("cannot shift the program of traffic light '" + tls_id + "': " + e.what());
  }
}

void SumoSession::set_emergency_braking(bool on) {
  if (on == emergency_braking_) return;
  try {
    libsumo::Vehicle::setSpeedMode(kEgo, on ? 11 : 15);  // 11 = 15 without bit 2 (max decel)
    emergency_braking_ = on;
  } catch (const libsumo::TraCIException& e) {
    throw SumoError(std::string("SUMO refused the ego's speed mode: ") + e.what());
  }
}

}  // namespace signalsim::sumo
