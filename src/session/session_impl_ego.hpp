// SessionImpl<Api>, part 3 of 3: the ego's life in SUMO (session_impl.hpp has the class).
// Inserting the ego (with its vType and the standing obstacles) or waiting for the vehicle to take
// over, taking control of it once it departed (deterministic driving, speed and lane-change modes,
// the lateral depart offset, the subscription over TraCI), and handing it back at the end. What the
// session kept of an earlier run is forgotten when the ego is inserted. Included by
// session_impl.hpp only.
#pragma once

namespace signalsim::sumo {

template <class Api>
void SessionImpl<Api>::insert_ego() {
  forget_run_answers();
  if (config_.no_ego) return;  // SUMO's traffic alone (an egoless fleet run)
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

template <class Api>
void SessionImpl<Api>::forget_run_answers() {
  answers_.forget();
  lanes_ = LaneData<Api>();
  vclass_.clear();
  subscribed_ = false;  // take_control subscribes again
}

template <class Api>
void SessionImpl<Api>::release_ego() noexcept {
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

template <class Api>
void SessionImpl<Api>::add_ego() {
  const std::string route = "signalsim_ego_route", type = "signalsim_ego_type";
  Api::Route::add(route, config_.route);
  Api::VehicleType::copy("DEFAULT_VEHTYPE", type);
  Api::VehicleType::setLength(type, config_.length);
  Api::VehicleType::setWidth(type, config_.width);
  Api::VehicleType::setMaxSpeed(type, config_.max_speed);
  Api::VehicleType::setAccel(type, config_.accel);
  Api::VehicleType::setDecel(type, config_.decel);
  Api::VehicleType::setEmergencyDecel(type, config_.emergency_decel);
  // Deterministic driving (docs/behaviour.md §S4): no dawdling, and speed factor exactly 1, so that SUMO's
  // per-vehicle speed draw never caps the ego below the speeds signalsim plans.
  Api::VehicleType::setImperfection(type, 0.0);
  Api::VehicleType::setSpeedFactor(type, 1.0);
  Api::VehicleType::setSpeedDeviation(type, 0.0);
  // Sublane model: lateral speed and acceleration high enough that one changeSublane per step
  // lands exactly on the commanded offset (docs/behaviour.md §S4); the plan itself keeps them realistic.
  if (sublane_) Api::VehicleType::setMaxSpeedLat(type, 10.0);
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
template <class Api>
bool SessionImpl<Api>::wait_for_departure() {
  for (int i = 0;; ++i) {
    throw_if_interrupted();
    if (config_.take_over.empty() ? i >= 600 : Api::Simulation::getTime() > config_.take_over_until + 1e-9)
      return false;
    Api::Simulation::step();
    if (contains_id(Api::Simulation::getDepartedIDList(), ego_)) return true;
  }
}

template <class Api>
void SessionImpl<Api>::take_control() {
  ego_present_ = true;
  vehicle_.type = Api::Vehicle::getTypeID(ego_);  // before the setters below give it a type of its own
  if (!config_.take_over.empty()) {
    // The taken-over vehicle keeps its vType, but drives deterministically like an added ego.
    Api::Vehicle::setSpeedFactor(ego_, 1.0);
    Api::Vehicle::setImperfection(ego_, 0.0);
    if (sublane_) Api::Vehicle::setMaxSpeedLat(ego_, 10.0);
  }
  if (!config_.sumo_drives) {  // SUMO driving keeps its default speed and lane-change modes
    apply_speed_mode();
    if (config_.keep_planned_lanes) Api::Vehicle::setLaneChangeMode(ego_, 0);
    if (sublane_) Api::Vehicle::setParameter(ego_, "laneChangeModel.lcAccelLat", "20");
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
  if constexpr (Api::kSubscribes) {  // over TraCI (session_impl.hpp)
    Api::Vehicle::subscribe(ego_, std::vector<int>(kEgoVariables.begin(), kEgoVariables.end()));
    Api::Simulation::subscribe(std::vector<int>{libsumo::VAR_TIME, libsumo::VAR_ARRIVED_VEHICLES_IDS,
                                                libsumo::VAR_COLLIDING_VEHICLES_NUMBER});
    subscribed_ = true;
  }
  answers_.forget();  // the run's first step is answered afresh
}

template <class Api>
void SessionImpl<Api>::move_to_depart_offset() {
  // libsumo 1.15's Vehicle::add has no departPosLat: the ego stands still (speed 0) while SUMO's
  // sublane model moves it sideways, a few steps (lcAccelLat 20 m/s^2), before the run starts.
  if (!sublane_) throw SumoError("a lateral depart offset needs lateral_resolution > 0");
  Api::Vehicle::setSpeed(ego_, 0.0);
  for (int i = 0; i < 100; ++i) {
    const double delta = config_.depart_pos_lat - Api::Vehicle::getLateralLanePosition(ego_);
    if (std::abs(delta) < 1e-3) break;
    Api::Vehicle::changeSublane(ego_, delta);
    Api::Simulation::step();
  }
}

}  // namespace signalsim::sumo
