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

}  // namespace

// SUMO prints its errors to stderr and throws a bare "Process Error": stderr is captured while the
// session lives, so the message we report is SUMO's own first error line, and nothing else is printed.
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
    restore();
    if (fd_ >= 0) close(fd_);
  }
  void restore() {
    if (saved_ < 0) return;
    std::fflush(stderr);
    dup2(saved_, STDERR_FILENO);
    close(saved_);
    saved_ = -1;
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
    std::istringstream in(text);
    std::string line, first_line;
    while (std::getline(in, line)) {
      if (line.rfind("Error: ", 0) == 0) return line.substr(7);
      if (first_line.empty() && !line.empty()) first_line = line;
    }
    return first_line;
  }

 private:
  int fd_ = -1;
  int saved_ = -1;
};

namespace {

bool contains(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// The index of `lane_id` among the lanes of `edge_id` (SUMO names them <edge>_<index>), or -1.
int lane_index_on(const std::string& edge_id, const std::string& lane_id) {
  const int lanes = libsumo::Edge::getLaneNumber(edge_id);
  for (int k = 0; k < lanes; ++k)
    if (edge_id + "_" + std::to_string(k) == lane_id) return k;
  return -1;
}

// Signed lateral distance [m, left positive] from the centre of lane `from` to the centre of lane
// `to` on one edge (index 0 is the rightmost lane): half of both widths plus the lanes between.
double centre_distance(const std::string& edge_id, int from, int to) {
  if (from == to) return 0.0;
  const int lo = std::min(from, to), hi = std::max(from, to);
  const auto width = [&](int k) { return libsumo::Lane::getWidth(edge_id + "_" + std::to_string(k)); };
  double d = 0.5 * (width(lo) + width(hi));
  for (int k = lo + 1; k < hi; ++k) d += width(k);
  return to > from ? d : -d;
}

// Whether vehicles of class `vclass` may use `lane_id` (SUMO keeps a vehicle off lanes it may not use,
// also sideways in the sublane model: a sidewalk is a road border).
bool permits(const std::string& lane_id, const std::string& vclass) {
  if (contains(libsumo::Lane::getDisallowed(lane_id), vclass)) return false;
  const auto allowed = libsumo::Lane::getAllowed(lane_id);  // empty: every class
  return allowed.empty() || contains(allowed, vclass);
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
  lateral_resolution_ = config.lateral_resolution;
  if (lateral_resolution_ > 0.0) args.insert(args.end(), {"--lateral-resolution", number(lateral_resolution_)});
  capture_ = std::make_unique<StderrCapture>();
  try {
    libsumo::Simulation::start(args);
  } catch (const std::exception& e) {
    throw SumoError("SUMO could not load the simulation: " + sumo_reason(e));
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
    // Sublane model: lateral speed and acceleration high enough that one changeSublane per step
    // lands exactly on the commanded offset (spec SUMO §4); the plan itself keeps them realistic.
    if (lateral_resolution_ > 0.0) libsumo::VehicleType::setMaxSpeedLat(kEgoType, 10.0);
    for (const StandingVehicle& v : config.standing) {
      const std::string route = "standing_route_" + v.id, type = "standing_type_" + v.id;
      libsumo::Route::add(route, {v.edge});
      libsumo::VehicleType::copy("DEFAULT_VEHTYPE", type);
      libsumo::VehicleType::setLength(type, v.length);
      libsumo::Vehicle::add(v.id, route, type, "0", std::to_string(v.lane), number(v.pos), "0");
      libsumo::Vehicle::setStop(v.id, v.edge, v.pos, v.lane, 1e7);
    }
    libsumo::Vehicle::add(kEgo, kEgoRoute, kEgoType, "0", std::to_string(config.depart_lane),
                          number(config.depart_pos), number(config.depart_speed));
    if (lateral_resolution_ > 0.0) libsumo::Vehicle::setParameter(kEgo, "laneChangeModel.lcAccelLat", "20");
    // Wait for the insertion (the lane may be blocked for a while).
    for (int i = 0; i < 600; ++i) {
      libsumo::Simulation::step();
      if (contains(libsumo::Simulation::getDepartedIDList(), kEgo)) {
        // spec SUMO §4: speed mode 15 = safe speed, max accel/decel, right of way, but no red-light
        // braking: the traffic-light judge alone decides at lights.
        libsumo::Vehicle::setSpeedMode(kEgo, 15);
        if (config.keep_planned_lanes) libsumo::Vehicle::setLaneChangeMode(kEgo, 0);
        if (config.depart_pos_lat != 0.0) move_to_depart_offset(config);
        return;
      }
    }
  } catch (const std::exception& e) {
    libsumo::Simulation::close();
    throw SumoError("SUMO rejected the ego: " + sumo_reason(e));
  }
  libsumo::Simulation::close();
  throw SumoError("the ego could not be inserted within 600 steps (its departure lane stays blocked)");
}

void SumoSession::move_to_depart_offset(const SessionConfig& config) {
  // libsumo 1.15's Vehicle::add has no departPosLat: the ego stands still (speed 0) while SUMO's
  // sublane model moves it sideways, a few steps (lcAccelLat 20 m/s^2), before the run starts.
  if (lateral_resolution_ <= 0.0) throw SumoError("a lateral depart offset needs lateral_resolution > 0");
  libsumo::Vehicle::setSpeed(kEgo, 0.0);
  for (int i = 0; i < 100; ++i) {
    const double delta = config.depart_pos_lat - libsumo::Vehicle::getLateralLanePosition(kEgo);
    if (std::abs(delta) < 1e-3) break;
    libsumo::Vehicle::changeSublane(kEgo, delta);
    libsumo::Simulation::step();
  }
}

SumoSession::~SumoSession() {
  try {
    libsumo::Simulation::close();
  } catch (...) {  // closing must never throw out of a destructor
  }
}

std::string SumoSession::sumo_reason(const std::exception& e) const {
  // SUMO prints its real error to stderr and throws a bare "Process Error" or the like.
  std::string reason = capture_ ? capture_->first_error() : std::string();
  return reason.empty() ? std::string(e.what()) : reason;
}

bool SumoSession::step() {
  try {
    libsumo::Simulation::step();
    for (const auto& c : libsumo::Simulation::getCollisions())
      if (c.collider == kEgo || c.victim == kEgo) ++ego_collisions_;
    return !contains(libsumo::Simulation::getArrivedIDList(), kEgo);
  } catch (const std::exception& e) {
    throw SumoError("SUMO failed during a step: " + sumo_reason(e));
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
  } catch (const std::exception& e) {
    throw SumoError(std::string("SUMO could not report the ego: ") + e.what());
  }
}

int SumoSession::ego_signals() const {
  try {
    return libsumo::Vehicle::getSignals(kEgo);
  } catch (const std::exception& e) {
    throw SumoError(std::string("SUMO could not report the ego's signals: ") + e.what());
  }
}

void SumoSession::command(int signal_mask, double speed) {
  try {
    libsumo::Vehicle::setSignals(kEgo, signal_mask);
    libsumo::Vehicle::setSpeed(kEgo, speed);
  } catch (const std::exception& e) {
    throw SumoError(std::string("SUMO refused a command for the ego: ") + e.what());
  }
}

void SumoSession::move_back(double distance) {
  try {
    const std::string lane = libsumo::Vehicle::getLaneID(kEgo);
    const double pos = libsumo::Vehicle::getLanePosition(kEgo);
    const double lat = libsumo::Vehicle::getLateralLanePosition(kEgo);
    if (pos - distance < libsumo::Vehicle::getLength(kEgo))
      throw SumoError("the ego cannot back up beyond the start of lane " + lane);
    libsumo::Vehicle::moveTo(kEgo, lane, pos - distance);
    const double drift = lat - libsumo::Vehicle::getLateralLanePosition(kEgo);
    if (lateral_resolution_ > 0.0 && std::abs(drift) > 1e-6) libsumo::Vehicle::changeSublane(kEgo, drift);
  } catch (const SumoError&) {
    throw;
  } catch (const std::exception& e) {
    throw SumoError(std::string("SUMO refused to move the ego back: ") + e.what());
  }
}

double SumoSession::lateral_offset_from(const std::string& reference_lane_id) const {
  try {
    const std::string reference_edge = libsumo::Lane::getEdgeID(reference_lane_id);
    const double in_lane = libsumo::Vehicle::getLateralLanePosition(kEgo);
    if (libsumo::Vehicle::getRoadID(kEgo) != reference_edge) return in_lane;  // documented fallback
    const int reference_index = lane_index_on(reference_edge, reference_lane_id);
    const int ego_index = libsumo::Vehicle::getLaneIndex(kEgo);
    if (reference_index < 0 || ego_index < 0) return in_lane;
    return in_lane + centre_distance(reference_edge, reference_index, ego_index);
  } catch (const std::exception& e) {
    throw SumoError("cannot measure the ego's offset from lane '" + reference_lane_id + "': " + e.what());
  }
}

void SumoSession::command_lateral_offset(double target_offset_next_step, const std::string& reference_lane_id) {
  if (lateral_resolution_ <= 0.0)
    throw SumoError("lateral offsets can only be commanded with SUMO's sublane model: set the session's "
                    "lateral_resolution > 0 (--lateral-resolution)");
  try {
    const std::string reference_edge = libsumo::Lane::getEdgeID(reference_lane_id);
    const std::string ego_edge = libsumo::Vehicle::getRoadID(kEgo);
    if (ego_edge != reference_edge)
      throw SumoError("cannot command a lateral offset from lane '" + reference_lane_id + "': the ego is on '" +
                      ego_edge + "', not on that lane's edge '" + reference_edge + "'");
    // Keep the target on the lanes the ego may use around its own (the road border): SUMO refuses a
    // move past it and leaves the ego where it was, short of the border, instead of clamping.
    const int reference_index = lane_index_on(reference_edge, reference_lane_id);
    const int ego_index = libsumo::Vehicle::getLaneIndex(kEgo);
    const int lanes = libsumo::Edge::getLaneNumber(reference_edge);
    const std::string vclass = libsumo::Vehicle::getVehicleClass(kEgo);
    const auto lane = [&](int k) { return reference_edge + "_" + std::to_string(k); };
    int lo = ego_index, hi = ego_index;
    while (lo > 0 && permits(lane(lo - 1), vclass)) --lo;
    while (hi + 1 < lanes && permits(lane(hi + 1), vclass)) ++hi;
    const double half_width = 0.5 * libsumo::Vehicle::getWidth(kEgo);
    const double lowest =
        centre_distance(reference_edge, reference_index, lo) - 0.5 * libsumo::Lane::getWidth(lane(lo)) + half_width;
    const double highest =
        centre_distance(reference_edge, reference_index, hi) + 0.5 * libsumo::Lane::getWidth(lane(hi)) - half_width;
    double target = target_offset_next_step;
    if (lowest <= highest) target = std::clamp(target, lowest, highest);
    libsumo::Vehicle::changeSublane(kEgo, target - lateral_offset_from(reference_lane_id));
  } catch (const std::exception& e) {
    throw SumoError("SUMO refused a lateral offset from lane '" + reference_lane_id + "': " + e.what());
  }
}

std::vector<SumoSession::LaneVehicle> SumoSession::vehicles_on_lane(const std::string& lane_id) const {
  try {
    std::vector<LaneVehicle> out;
    for (const std::string& id : libsumo::Lane::getLastStepVehicleIDs(lane_id)) {
      if (id == kEgo) continue;
      out.push_back({id, libsumo::Vehicle::getLanePosition(id), libsumo::Vehicle::getLength(id)});
    }
    return out;
  } catch (const std::exception& e) {
    throw SumoError("SUMO cannot list the vehicles on lane '" + lane_id + "': " + e.what());
  }
}

std::string SumoSession::light_state(const std::string& tls_id) const {
  try {
    return libsumo::TrafficLight::getRedYellowGreenState(tls_id);
  } catch (const std::exception& e) {
    throw SumoError("SUMO does not know traffic light '" + tls_id + "': " + e.what());
  }
}

std::vector<std::string> SumoSession::program_states(const std::string& tls_id) const {
  try {
    std::vector<std::string> states;
    for (const auto& logic : libsumo::TrafficLight::getAllProgramLogics(tls_id))
      for (const auto& phase : logic.phases) states.push_back(phase->state);
    return states;
  } catch (const std::exception& e) {
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
  } catch (const std::exception& e) {
    throw SumoError("cannot shift the program of traffic light '" + tls_id + "': " + e.what());
  }
}

void SumoSession::set_emergency_braking(bool on) {
  if (on == emergency_braking_) return;
  try {
    libsumo::Vehicle::setSpeedMode(kEgo, on ? 11 : 15);  // 11 = 15 without bit 2 (max decel)
    emergency_braking_ = on;
  } catch (const std::exception& e) {
    throw SumoError(std::string("SUMO refused the ego's speed mode: ") + e.what());
  }
}

}  // namespace signalsim::sumo
