// SessionImpl<Api>: the per-step SUMO logic of SumoSession, written once for both client libraries.
// `Api` names the library's domain classes (Api::Vehicle, Api::Simulation, ...): libsumo (in-process)
// or libtraci (over a socket) have the same API in two namespaces whose headers cannot be included in
// one translation unit (spec SUMO §1), so this header includes neither. session_embedded.cpp and
// session_traci.cpp include their library, define Api and instantiate this template; they own only
// how SUMO is started and closed. Include it after <libsumo/libsumo.h> or <libsumo/libtraci.h>
// (it uses their shared types and constants, libsumo::TraCIResults, libsumo::VAR_*).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include "sumo/interruption.hpp"
#include "sumo/number_parsing.hpp"
#include "sumo/sumo_session.hpp"

namespace signalsim::sumo {

inline bool contains_id(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// Speed-mode bits (spec SUMO §4): 0 safe speed, 1 max accel, 2 max decel, 3 right of way; bit 4
// (hard braking for red lights) is never set: the traffic-light judge decides at lights.
inline constexpr int kSpeedModeSafeSpeed = 1, kSpeedModeMaxAccel = 2, kSpeedModeMaxDecel = 4, kSpeedModeRightOfWay = 8;
// SUMO's defaults, for a vehicle signalsim hands back (TraCI docs: speed mode 31, lane-change mode 1621).
inline constexpr int kSumoDefaultSpeedMode = 31, kSumoDefaultLaneChangeMode = 0b011001010101;

template <class Api>
class SessionImpl : public SumoSession {
 public:
  explicit SessionImpl(const SessionConfig& config)
      : config_(config), ego_(config.take_over.empty() ? kDefaultEgoId : config.take_over) {}

  const EgoVehicle& ego_vehicle() const override { return vehicle_; }
  double delta_t() const override { return guarded("the step length", [] { return Api::Simulation::getDeltaT(); }); }

  bool step() override {
    throw_if_interrupted();
    try {
      Api::Simulation::step();
      const libsumo::TraCIResults sim = subscribed_ ? Api::Simulation::getSubscriptionResults() : libsumo::TraCIResults();
      // Collisions are rare: their details are asked for only when the step had some.
      if (!subscribed_ || subscribed_int(sim, libsumo::VAR_COLLIDING_VEHICLES_NUMBER, 1) > 0)
        for (const auto& c : Api::Simulation::getCollisions())
          if (c.collider == ego_ || c.victim == ego_) ++ego_collisions_;
      const auto arrived = sim.find(libsumo::VAR_ARRIVED_VEHICLES_IDS);
      const bool alive = arrived != sim.end()
                             ? !contains_id(static_cast<const libsumo::TraCIStringList&>(*arrived->second).value, ego_)
                             : !contains_id(Api::Simulation::getArrivedIDList(), ego_);
      if (!alive) ego_present_ = false;
      on_stepped();
      return alive;
    } catch (const SumoError&) {
      throw;
    } catch (const std::exception& e) {
      throw_if_interrupted();
      throw SumoError("SUMO failed during a step: " + failure_reason(e));
    }
  }

  double time() const override {
    return guarded("the time", [this] {
      if (subscribed_) {
        const libsumo::TraCIResults sim = Api::Simulation::getSubscriptionResults();
        if (const auto it = sim.find(libsumo::VAR_TIME); it != sim.end())
          return static_cast<const libsumo::TraCIDouble&>(*it->second).value;
      }
      return Api::Simulation::getTime();
    });
  }

  // The ego's state comes with the step's answer (a TraCI subscription: one round trip a step
  // instead of nine over a socket); before the first subscribed step it is asked for directly.
  EgoState ego() const override {
    return guarded("the ego", [this] {
      const libsumo::TraCIResults v = subscribed_ ? Api::Vehicle::getSubscriptionResults(ego_) : libsumo::TraCIResults();
      EgoState s;
      s.time = time();
      if (v.size() == kEgoVariables.size()) {
        s.edge = text(v, libsumo::VAR_ROAD_ID);
        s.lane = text(v, libsumo::VAR_LANE_ID);
        s.lane_pos = number(v, libsumo::VAR_LANEPOSITION);
        s.speed = number(v, libsumo::VAR_SPEED);
        s.accel = number(v, libsumo::VAR_ACCELERATION);
        const auto& p = static_cast<const libsumo::TraCIPosition&>(*v.at(libsumo::VAR_POSITION));
        s.x = p.x;
        s.y = p.y;
        s.lateral_offset = number(v, libsumo::VAR_LANEPOSITION_LAT);
        return s;
      }
      s.edge = Api::Vehicle::getRoadID(ego_);
      s.lane = Api::Vehicle::getLaneID(ego_);
      s.lane_pos = Api::Vehicle::getLanePosition(ego_);
      s.speed = Api::Vehicle::getSpeed(ego_);
      s.accel = Api::Vehicle::getAcceleration(ego_);
      const auto p = Api::Vehicle::getPosition(ego_);
      s.x = p.x;
      s.y = p.y;
      s.lateral_offset = Api::Vehicle::getLateralLanePosition(ego_);
      return s;
    });
  }

  int ego_signals() const override {
    return guarded("the ego's signals", [this] {
      if (subscribed_) {
        const libsumo::TraCIResults v = Api::Vehicle::getSubscriptionResults(ego_);
        if (const auto it = v.find(libsumo::VAR_SIGNALS); it != v.end())
          return static_cast<const libsumo::TraCIInt&>(*it->second).value;
      }
      return Api::Vehicle::getSignals(ego_);
    });
  }

  void command(int signal_mask, double speed) override {
    try {
      Api::Vehicle::setSignals(ego_, signal_mask);
      Api::Vehicle::setSpeed(ego_, speed);
    } catch (const std::exception& e) {
      throw SumoError("SUMO refused a command for the ego: " + failure_reason(e));
    }
    on_command(signal_mask);
  }

  void move_back(double distance) override {
    try {
      const std::string lane = Api::Vehicle::getLaneID(ego_);
      const double pos = Api::Vehicle::getLanePosition(ego_);
      const double lat = Api::Vehicle::getLateralLanePosition(ego_);
      if (pos - distance < Api::Vehicle::getLength(ego_))
        throw SumoError("the ego cannot back up beyond the start of lane " + lane);
      Api::Vehicle::moveTo(ego_, lane, pos - distance);
      const double drift = lat - Api::Vehicle::getLateralLanePosition(ego_);
      if (config_.lateral_resolution > 0.0 && std::abs(drift) > 1e-6) Api::Vehicle::changeSublane(ego_, drift);
    } catch (const SumoError&) {
      throw;
    } catch (const std::exception& e) {
      throw SumoError("SUMO refused to move the ego back: " + failure_reason(e));
    }
  }

  double lateral_offset_from(const std::string& reference_lane_id) const override {
    try {
      const std::string& reference_edge = lane_edge(reference_lane_id);
      const double in_lane = Api::Vehicle::getLateralLanePosition(ego_);
      if (Api::Vehicle::getRoadID(ego_) != reference_edge) return in_lane;  // documented fallback
      const int reference_index = lane_index_on(reference_edge, reference_lane_id);
      const int ego_index = Api::Vehicle::getLaneIndex(ego_);
      if (reference_index < 0 || ego_index < 0) return in_lane;
      return in_lane + centre_distance(reference_edge, reference_index, ego_index);
    } catch (const std::exception& e) {
      throw SumoError("cannot measure the ego's offset from lane '" + reference_lane_id + "': " + failure_reason(e));
    }
  }

  void command_lateral_offset(double target_offset_next_step, const std::string& reference_lane_id) override {
    if (config_.lateral_resolution <= 0.0)
      throw SumoError("lateral offsets can only be commanded with SUMO's sublane model: set the session's "
                      "lateral_resolution > 0 (--lateral-resolution)");
    try {
      const std::string& reference_edge = lane_edge(reference_lane_id);
      const std::string ego_edge = Api::Vehicle::getRoadID(ego_);
      if (ego_edge != reference_edge)
        throw SumoError("cannot command a lateral offset from lane '" + reference_lane_id + "': the ego is on '" +
                        ego_edge + "', not on that lane's edge '" + reference_edge + "'");
      // Keep the target on the lanes the ego may use around its own (the road border): SUMO refuses a
      // move past it and leaves the ego where it was, short of the border, instead of clamping.
      const int reference_index = lane_index_on(reference_edge, reference_lane_id);
      const int ego_index = Api::Vehicle::getLaneIndex(ego_);
      const int lanes = lane_count(reference_edge);
      if (vclass_.empty()) vclass_ = Api::Vehicle::getVehicleClass(ego_);
      const std::string& vclass = vclass_;
      const auto lane = [&](int k) { return reference_edge + "_" + std::to_string(k); };
      int lo = ego_index, hi = ego_index;
      while (lo > 0 && permits(lane(lo - 1), vclass)) --lo;
      while (hi + 1 < lanes && permits(lane(hi + 1), vclass)) ++hi;
      const double half_width = 0.5 * vehicle_.width;
      const double lowest = centre_distance(reference_edge, reference_index, lo) - 0.5 * lane_width(lane(lo)) + half_width;
      const double highest = centre_distance(reference_edge, reference_index, hi) + 0.5 * lane_width(lane(hi)) - half_width;
      double target = target_offset_next_step;
      if (lowest <= highest) target = std::clamp(target, lowest, highest);
      Api::Vehicle::changeSublane(ego_, target - lateral_offset_from(reference_lane_id));
    } catch (const SumoError&) {
      throw;
    } catch (const std::exception& e) {
      throw SumoError("SUMO refused a lateral offset from lane '" + reference_lane_id + "': " + failure_reason(e));
    }
  }

  std::vector<LaneVehicle> vehicles_on_lane(const std::string& lane_id) const override {
    try {
      std::vector<LaneVehicle> out;
      for (const std::string& id : Api::Lane::getLastStepVehicleIDs(lane_id)) {
        if (id == ego_) continue;
        out.push_back({id, Api::Vehicle::getLanePosition(id), Api::Vehicle::getLength(id)});
      }
      return out;
    } catch (const std::exception& e) {
      throw SumoError("SUMO cannot list the vehicles on lane '" + lane_id + "': " + failure_reason(e));
    }
  }

  std::string light_state(const std::string& tls_id) const override {
    try {
      return Api::TrafficLight::getRedYellowGreenState(tls_id);
    } catch (const std::exception& e) {
      throw SumoError("SUMO cannot report traffic light '" + tls_id + "': " + failure_reason(e));
    }
  }

  std::vector<std::string> program_states(const std::string& tls_id) const override {
    try {
      std::vector<std::string> states;
      for (const auto& logic : Api::TrafficLight::getAllProgramLogics(tls_id))
        for (const auto& phase : logic.phases) states.push_back(phase->state);
      return states;
    } catch (const std::exception& e) {
      throw SumoError("SUMO cannot report traffic light '" + tls_id + "': " + failure_reason(e));
    }
  }

  std::vector<LightProgram> light_programs(const std::string& tls_id) const override {
    try {
      std::vector<LightProgram> programs;
      for (const auto& logic : Api::TrafficLight::getAllProgramLogics(tls_id)) {
        LightProgram program{logic.programID, program_kind_of(logic.type), {}};
        for (const auto& phase : logic.phases) program.phases.push_back({phase->duration, phase->state, phase->next});
        programs.push_back(std::move(program));
      }
      return programs;
    } catch (const std::exception& e) {
      throw SumoError("SUMO cannot report the programs of traffic light '" + tls_id + "': " + failure_reason(e));
    }
  }

  LightTiming light_timing(const std::string& tls_id) const override {
    try {
      return {Api::TrafficLight::getProgram(tls_id), Api::TrafficLight::getPhase(tls_id),
              Api::TrafficLight::getNextSwitch(tls_id)};
    } catch (const std::exception& e) {
      throw SumoError("SUMO cannot report the timing of traffic light '" + tls_id + "': " + failure_reason(e));
    }
  }

  void shift_light_program(const std::string& tls_id, double offset) override {
    try {
      const std::string program = Api::TrafficLight::getProgram(tls_id);
      for (const auto& logic : Api::TrafficLight::getAllProgramLogics(tls_id)) {
        if (logic.programID != program) continue;
        double cycle = 0.0;
        for (const auto& phase : logic.phases) cycle += phase->duration;
        if (cycle <= 0.0) return;
        // Where the cycle stands now, plus the offset: that phase, with the rest of its duration.
        const double now = Api::Simulation::getTime();
        double into = std::fmod(now + offset, cycle);
        if (into < 0) into += cycle;
        for (std::size_t i = 0; i < logic.phases.size(); ++i) {
          const double duration = logic.phases[i]->duration;
          if (into < duration) {
            Api::TrafficLight::setPhase(tls_id, static_cast<int>(i));
            Api::TrafficLight::setPhaseDuration(tls_id, duration - into);
            return;
          }
          into -= duration;
        }
        return;
      }
    } catch (const std::exception& e) {
      throw SumoError("cannot shift the program of traffic light '" + tls_id + "': " + failure_reason(e));
    }
  }

  void set_emergency_braking(bool on) override {
    if (on == emergency_braking_) return;
    emergency_braking_ = on;
    apply_speed_mode();
  }

  void set_sumo_lane_limits(bool on) override {
    if (on == lane_limits_) return;
    lane_limits_ = on;
    guarded("the ego's speed factor", [&] { Api::Vehicle::setSpeedFactor(ego_, on ? 1.0 : kFreeSpeedFactor); });
  }

  void set_right_of_way(bool respect) override {
    if (respect == right_of_way_) return;
    right_of_way_ = respect;
    apply_speed_mode();
  }

  std::optional<Leader> ego_leader(double range) const override {
    return guarded("the ego's leader", [&]() -> std::optional<Leader> {
      const auto [id, distance] = Api::Vehicle::getLeader(ego_, range);
      if (id.empty()) return std::nullopt;
      return Leader{id, distance + Api::Vehicle::getMinGap(ego_)};  // getLeader measures from front + minGap
    });
  }

  int ego_collisions() const override { return ego_collisions_; }

 protected:
  /// Inserts the ego (or waits for the vehicle to take over) once SUMO runs, then applies the ego's
  /// controls and reads what it departed as. The factory calls it once, after the back-end started.
  void insert_ego() {
    try {
      if (config_.take_over.empty()) add_ego();
      const bool departed = wait_for_departure();
      if (!departed) {
        if (config_.take_over.empty())
          throw SumoError("the ego could not be inserted within 600 steps (its departure lane stays blocked)");
        throw SumoError("vehicle '" + ego_ + "' (ego.id) did not depart by t=" + exact_number(config_.take_over_until) +
                        " s: it is not in the route files SUMO loaded, or departs later");
      }
      take_control();
    } catch (const SumoError&) {
      throw;
    } catch (const std::exception& e) {
      throw SumoError("SUMO rejected the ego: " + failure_reason(e));
    }
  }

  /// Hands the ego back when signalsim leaves a simulation that goes on (--connect): an ego it added
  /// (and its standing obstacles) is removed; a taken-over vehicle drives on under SUMO's own models
  /// (default speed and lane-change modes, its own speed and signals). Never throws.
  void release_ego() noexcept {
    try {
      if (ego_present_ && config_.take_over.empty()) Api::Vehicle::remove(ego_);
      if (ego_present_ && !config_.take_over.empty()) {
        Api::Vehicle::setSpeed(ego_, -1.0);
        Api::Vehicle::setSpeedMode(ego_, kSumoDefaultSpeedMode);
        Api::Vehicle::setLaneChangeMode(ego_, kSumoDefaultLaneChangeMode);
        Api::Vehicle::setSignals(ego_, -1);
      }
      ego_present_ = false;
      for (const StandingVehicle& v : config_.standing)
        if (contains_id(Api::Vehicle::getIDList(), v.id)) Api::Vehicle::remove(v.id);
    } catch (...) {  // a lost connection: nothing left to hand back
    }
  }

  /// SUMO's own reason for a failure (the embedded back-end reads it from SUMO's stderr).
  virtual std::string failure_reason(const std::exception& e) const { return e.what(); }
  /// Called once the ego is under control (gui: colour and track it).
  virtual void on_ego_departed() {}
  /// Called after each command (gui: the screenshot at the first blinker).
  virtual void on_command(int /*signal_mask*/) {}
  /// Called after each step (gui: waits for a requested screenshot to be written).
  virtual void on_stepped() {}

  const SessionConfig config_;
  const std::string ego_;

 private:
  template <class F>
  auto guarded(const char* what, F f) const {
    try {
      return f();
    } catch (const std::exception& e) {
      throw SumoError(std::string("SUMO could not report ") + what + ": " + failure_reason(e));
    }
  }

  void add_ego() {
    const std::string route = "signalsim_ego_route", type = "signalsim_ego_type";
    Api::Route::add(route, config_.route);
    Api::VehicleType::copy("DEFAULT_VEHTYPE", type);
    Api::VehicleType::setLength(type, config_.length);
    Api::VehicleType::setWidth(type, config_.width);
    Api::VehicleType::setMaxSpeed(type, config_.max_speed);
    Api::VehicleType::setAccel(type, config_.accel);
    Api::VehicleType::setDecel(type, config_.decel);
    Api::VehicleType::setEmergencyDecel(type, config_.emergency_decel);
    // Deterministic driving (spec SUMO §4): no dawdling, and speed factor exactly 1, so that SUMO's
    // per-vehicle speed draw never caps the ego below the speeds signalsim plans.
    Api::VehicleType::setImperfection(type, 0.0);
    Api::VehicleType::setSpeedFactor(type, 1.0);
    Api::VehicleType::setSpeedDeviation(type, 0.0);
    // Sublane model: lateral speed and acceleration high enough that one changeSublane per step
    // lands exactly on the commanded offset (spec SUMO §4); the plan itself keeps them realistic.
    if (config_.lateral_resolution > 0.0) Api::VehicleType::setMaxSpeedLat(type, 10.0);
    for (const StandingVehicle& v : config_.standing) {
      const std::string standing_route = "standing_route_" + v.id, standing_type = "standing_type_" + v.id;
      Api::Route::add(standing_route, {v.edge});
      Api::VehicleType::copy("DEFAULT_VEHTYPE", standing_type);
      Api::VehicleType::setLength(standing_type, v.length);
      Api::Vehicle::add(v.id, standing_route, standing_type, "now", std::to_string(v.lane), exact_number(v.pos), "0");
      Api::Vehicle::setStop(v.id, v.edge, v.pos, v.lane, 1e7);
    }
    Api::Vehicle::add(ego_, route, type, "now", std::to_string(config_.depart_lane), exact_number(config_.depart_pos),
                      exact_number(config_.depart_speed));
    ego_present_ = true;  // from now on release_ego() removes it, departed or still waiting
  }

  // Steps until the ego departs: an added ego within 600 steps (its lane may be blocked for a while),
  // a taken-over one by take_over_until.
  bool wait_for_departure() {
    for (int i = 0;; ++i) {
      throw_if_interrupted();
      if (config_.take_over.empty() ? i >= 600 : Api::Simulation::getTime() > config_.take_over_until + 1e-9)
        return false;
      Api::Simulation::step();
      if (contains_id(Api::Simulation::getDepartedIDList(), ego_)) return true;
    }
  }

  void take_control() {
    ego_present_ = true;
    vehicle_.type = Api::Vehicle::getTypeID(ego_);  // before the setters below give it a type of its own
    if (!config_.take_over.empty()) {
      // The taken-over vehicle keeps its vType, but drives deterministically like an added ego.
      Api::Vehicle::setSpeedFactor(ego_, 1.0);
      Api::Vehicle::setImperfection(ego_, 0.0);
      if (config_.lateral_resolution > 0.0) Api::Vehicle::setMaxSpeedLat(ego_, 10.0);
    }
    if (!config_.sumo_drives) {  // SUMO driving keeps its default speed and lane-change modes
      apply_speed_mode();
      if (config_.keep_planned_lanes) Api::Vehicle::setLaneChangeMode(ego_, 0);
      if (config_.lateral_resolution > 0.0) Api::Vehicle::setParameter(ego_, "laneChangeModel.lcAccelLat", "20");
    }
    vehicle_.id = ego_;
    vehicle_.length = Api::Vehicle::getLength(ego_);
    vehicle_.width = Api::Vehicle::getWidth(ego_);
    vehicle_.max_speed = Api::Vehicle::getMaxSpeed(ego_);
    vehicle_.accel = Api::Vehicle::getAccel(ego_);
    vehicle_.decel = Api::Vehicle::getDecel(ego_);
    vehicle_.emergency_decel = Api::Vehicle::getEmergencyDecel(ego_);
    vehicle_.vclass = Api::Vehicle::getVehicleClass(ego_);
    vehicle_.route = Api::Vehicle::getRoute(ego_);
    vehicle_.depart_time = Api::Simulation::getTime() - Api::Simulation::getDeltaT();  // inserted in the step just done
    vehicle_.depart_lane = Api::Vehicle::getLaneIndex(ego_);
    vehicle_.depart_pos = Api::Vehicle::getLanePosition(ego_);
    vehicle_.depart_speed = Api::Vehicle::getSpeed(ego_);
    on_ego_departed();
    if (config_.depart_pos_lat != 0.0 && !config_.sumo_drives) move_to_depart_offset();
    Api::Vehicle::subscribe(ego_, std::vector<int>(kEgoVariables.begin(), kEgoVariables.end()));
    Api::Simulation::subscribe(std::vector<int>{libsumo::VAR_TIME, libsumo::VAR_ARRIVED_VEHICLES_IDS,
                                                libsumo::VAR_COLLIDING_VEHICLES_NUMBER});
    subscribed_ = true;
  }

  void apply_speed_mode() {
    int mode = kSpeedModeSafeSpeed | kSpeedModeMaxAccel;
    if (!emergency_braking_) mode |= kSpeedModeMaxDecel;
    if (right_of_way_) mode |= kSpeedModeRightOfWay;
    try {
      Api::Vehicle::setSpeedMode(ego_, mode);
    } catch (const std::exception& e) {
      throw SumoError("SUMO refused the ego's speed mode: " + failure_reason(e));
    }
  }

  void move_to_depart_offset() {
    // libsumo 1.15's Vehicle::add has no departPosLat: the ego stands still (speed 0) while SUMO's
    // sublane model moves it sideways, a few steps (lcAccelLat 20 m/s^2), before the run starts.
    if (config_.lateral_resolution <= 0.0) throw SumoError("a lateral depart offset needs lateral_resolution > 0");
    Api::Vehicle::setSpeed(ego_, 0.0);
    for (int i = 0; i < 100; ++i) {
      const double delta = config_.depart_pos_lat - Api::Vehicle::getLateralLanePosition(ego_);
      if (std::abs(delta) < 1e-3) break;
      Api::Vehicle::changeSublane(ego_, delta);
      Api::Simulation::step();
    }
  }

  // Static net data asked over TraCI once and kept (lane widths, permissions, lane counts do not
  // change during a run): a lane change would otherwise ask for them every step.
  int lane_count(const std::string& edge_id) const {
    auto it = lane_counts_.find(edge_id);
    if (it == lane_counts_.end()) it = lane_counts_.emplace(edge_id, Api::Edge::getLaneNumber(edge_id)).first;
    return it->second;
  }
  double lane_width(const std::string& lane_id) const {
    auto it = lane_widths_.find(lane_id);
    if (it == lane_widths_.end()) it = lane_widths_.emplace(lane_id, Api::Lane::getWidth(lane_id)).first;
    return it->second;
  }
  const std::string& lane_edge(const std::string& lane_id) const {
    auto it = lane_edges_.find(lane_id);
    if (it == lane_edges_.end()) it = lane_edges_.emplace(lane_id, Api::Lane::getEdgeID(lane_id)).first;
    return it->second;
  }

  // The index of `lane_id` among the lanes of `edge_id` (SUMO names them <edge>_<index>), or -1.
  int lane_index_on(const std::string& edge_id, const std::string& lane_id) const {
    const int lanes = lane_count(edge_id);
    for (int k = 0; k < lanes; ++k)
      if (edge_id + "_" + std::to_string(k) == lane_id) return k;
    return -1;
  }

  // Signed lateral distance [m, left positive] from the centre of lane `from` to the centre of lane
  // `to` on one edge (index 0 is the rightmost lane): half of both widths plus the lanes between.
  double centre_distance(const std::string& edge_id, int from, int to) const {
    if (from == to) return 0.0;
    const int lo = std::min(from, to), hi = std::max(from, to);
    const auto width = [&](int k) { return lane_width(edge_id + "_" + std::to_string(k)); };
    double d = 0.5 * (width(lo) + width(hi));
    for (int k = lo + 1; k < hi; ++k) d += width(k);
    return to > from ? d : -d;
  }

  // Whether vehicles of class `vclass` may use `lane_id` (SUMO keeps a vehicle off lanes it may not
  // use, also sideways in the sublane model: a sidewalk is a road border).
  bool permits(const std::string& lane_id, const std::string& vclass) const {
    const std::string key = lane_id + "\n" + vclass;
    auto it = permits_.find(key);
    if (it == permits_.end()) {
      const auto allowed = Api::Lane::getAllowed(lane_id);  // empty: every class
      const bool ok = !contains_id(Api::Lane::getDisallowed(lane_id), vclass) &&
                      (allowed.empty() || contains_id(allowed, vclass));
      it = permits_.emplace(key, ok).first;
    }
    return it->second;
  }

  mutable std::unordered_map<std::string, int> lane_counts_;
  mutable std::unordered_map<std::string, double> lane_widths_;
  mutable std::unordered_map<std::string, std::string> lane_edges_;
  mutable std::unordered_map<std::string, bool> permits_;
  EgoVehicle vehicle_;
  static constexpr std::array<int, 8> kEgoVariables = {
      libsumo::VAR_ROAD_ID,      libsumo::VAR_LANE_ID,  libsumo::VAR_LANEPOSITION,     libsumo::VAR_SPEED,
      libsumo::VAR_ACCELERATION, libsumo::VAR_POSITION, libsumo::VAR_LANEPOSITION_LAT, libsumo::VAR_SIGNALS};
  static const std::string& text(const libsumo::TraCIResults& r, int variable) {
    return static_cast<const libsumo::TraCIString&>(*r.at(variable)).value;
  }
  static double number(const libsumo::TraCIResults& r, int variable) {
    return static_cast<const libsumo::TraCIDouble&>(*r.at(variable)).value;
  }
  static int subscribed_int(const libsumo::TraCIResults& r, int variable, int fallback) {
    const auto it = r.find(variable);
    return it == r.end() ? fallback : static_cast<const libsumo::TraCIInt&>(*it->second).value;
  }

  bool subscribed_ = false;     // the ego's and the simulation's variables come with each step
  mutable std::string vclass_;  // the ego's vehicle class, asked once
  bool ego_present_ = false;  // inserted (or taken over) and not arrived: release_ego() has work
  int ego_collisions_ = 0;
  bool emergency_braking_ = false;
  bool right_of_way_ = true;
  bool lane_limits_ = true;  // speed factor 1 (set_sumo_lane_limits)
};

}  // namespace signalsim::sumo
