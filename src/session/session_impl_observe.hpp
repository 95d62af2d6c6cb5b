// SessionImpl<Api>, part 1 of 3: what the session reads from SUMO (session_impl.hpp has the class).
// SUMO's step and the answer that comes with it (a TraCI subscription of the ego's and the
// simulation's variables: one round trip a step over a socket), the ego's state, signals and parameters, its
// leader, the vehicles on a lane, the ego's offset from a lane, and the traffic lights' states,
// programs and timing. What a step answered is asked once and kept until the next step
// (session_step_answers.hpp).
// Included by session_impl.hpp only.
#pragma once

namespace signalsim::sumo {
namespace subscription {

inline const std::string& subscribed_text(const libsumo::TraCIResults& r, int variable) {
  return static_cast<const libsumo::TraCIString&>(*r.at(variable)).value;
}
inline double subscribed_number(const libsumo::TraCIResults& r, int variable) {
  return static_cast<const libsumo::TraCIDouble&>(*r.at(variable)).value;
}
inline int subscribed_int(const libsumo::TraCIResults& r, int variable, int fallback) {
  const auto it = r.find(variable);
  return it == r.end() ? fallback : static_cast<const libsumo::TraCIInt&>(*it->second).value;
}

}  // namespace subscription

template <class Api>
bool SessionImpl<Api>::step() {
  throw_if_interrupted();
  try {
    answers_.forget();  // before the step: a failed one leaves nothing of the last
    Api::Simulation::step();
    static const libsumo::TraCIResults kNone;
    if (subscribed_) answers_.simulation_variables = Api::Simulation::getSubscriptionResults();
    const libsumo::TraCIResults& sim = subscribed_ ? *answers_.simulation_variables : kNone;
    // Collisions are rare: their details are asked for only when the step had some.
    if (!subscribed_ || subscription::subscribed_int(sim, libsumo::VAR_COLLIDING_VEHICLES_NUMBER, 1) > 0)
      for (const auto& c : Api::Simulation::getCollisions())
        if (c.collider == ego_ || c.victim == ego_) ++ego_collisions_;
    const auto arrived = sim.find(libsumo::VAR_ARRIVED_VEHICLES_IDS);
    const bool alive = arrived != sim.end()
                           ? !contains_id(static_cast<const libsumo::TraCIStringList&>(*arrived->second).value, ego_)
                           : !contains_id(Api::Simulation::getArrivedIDList(), ego_);
    if (!alive) ego_present_ = false;
    if (alive && lane_change_step_) restore_blinkers_after_lane_change();
    lane_change_step_ = false;
    on_stepped();
    return alive;
  } catch (const SumoError&) {
    throw;
  } catch (const std::exception& e) {
    throw_if_interrupted();
    throw SumoError("SUMO failed during a step: " + failure_reason(e));
  }
}

template <class Api>
const libsumo::TraCIResults* SessionImpl<Api>::simulation_variables() const {
  if (!subscribed_) return nullptr;
  if (!answers_.simulation_variables) answers_.simulation_variables = Api::Simulation::getSubscriptionResults();
  return &*answers_.simulation_variables;
}

template <class Api>
const libsumo::TraCIResults* SessionImpl<Api>::ego_variables() const {
  if (!subscribed_ || answers_.ego_moved) return nullptr;
  if (!answers_.ego_variables) answers_.ego_variables = Api::Vehicle::getSubscriptionResults(ego_);
  return answers_.ego_variables->size() == kEgoVariables.size() ? &*answers_.ego_variables : nullptr;
}

template <class Api>
double SessionImpl<Api>::time() const {
  return guarded("the time", [this] {
    if (!answers_.time) {
      const libsumo::TraCIResults* sim = simulation_variables();
      const auto it = sim ? sim->find(libsumo::VAR_TIME) : libsumo::TraCIResults::const_iterator();
      answers_.time = sim && it != sim->end() ? static_cast<const libsumo::TraCIDouble&>(*it->second).value
                                              : Api::Simulation::getTime();
    }
    return *answers_.time;
  });
}

// The ego's state: from the step's subscribed answer over TraCI (one round trip a step instead of
// nine), else from the getters; once a step either way.
template <class Api>
int SessionImpl<Api>::expected_vehicles() const {
  return guarded("the expected vehicles", [] { return Api::Simulation::getMinExpectedNumber(); });
}

template <class Api>
EgoState SessionImpl<Api>::ego() const {
  return guarded("the ego", [this] { return ego_state(); });
}

template <class Api>
const EgoState& SessionImpl<Api>::ego_state() const {
  if (!answers_.ego) answers_.ego = read_ego_state();
  return *answers_.ego;
}

template <class Api>
EgoState SessionImpl<Api>::read_ego_state() const {
  EgoState s;
  s.time = time();
  if (const libsumo::TraCIResults* v = ego_variables()) {
    s.edge = subscription::subscribed_text(*v, libsumo::VAR_ROAD_ID);
    s.lane = subscription::subscribed_text(*v, libsumo::VAR_LANE_ID);
    s.lane_pos = subscription::subscribed_number(*v, libsumo::VAR_LANEPOSITION);
    s.speed = subscription::subscribed_number(*v, libsumo::VAR_SPEED);
    s.accel = subscription::subscribed_number(*v, libsumo::VAR_ACCELERATION);
    const auto& p = static_cast<const libsumo::TraCIPosition&>(*v->at(libsumo::VAR_POSITION));
    s.x = p.x;
    s.y = p.y;
    s.lateral_offset = subscription::subscribed_number(*v, libsumo::VAR_LANEPOSITION_LAT);
  } else {
    s.lane = Api::Vehicle::getLaneID(ego_);
    // On a lane the road is that lane's edge, as libsumo's getRoadID answers (kept per lane); off the
    // lanes (parked, teleporting) SUMO is asked.
    s.edge = s.lane.empty() ? Api::Vehicle::getRoadID(ego_) : lanes_.lane_edge(s.lane);
    s.lane_pos = Api::Vehicle::getLanePosition(ego_);
    s.speed = Api::Vehicle::getSpeed(ego_);
    s.accel = Api::Vehicle::getAcceleration(ego_);
    const auto p = Api::Vehicle::getPosition(ego_);
    s.x = p.x;
    s.y = p.y;
    s.lateral_offset = Api::Vehicle::getLateralLanePosition(ego_);
  }
  return s;
}

template <class Api>
int SessionImpl<Api>::ego_signals() const {
  return guarded("the ego's signals", [this] {
    if (!answers_.ego_signals) {
      const libsumo::TraCIResults* v = ego_variables();
      answers_.ego_signals =
          v ? subscription::subscribed_int(*v, libsumo::VAR_SIGNALS, 0) : Api::Vehicle::getSignals(ego_);
    }
    return *answers_.ego_signals;
  });
}

template <class Api>
int SessionImpl<Api>::ego_signals_now() const {
  return guarded("the ego's signals", [this] { return Api::Vehicle::getSignals(ego_); });
}

template <class Api>
std::string SessionImpl<Api>::ego_parameter(const std::string& key) const {
  return guarded("a parameter of the ego", [&] { return Api::Vehicle::getParameter(ego_, key); });
}

template <class Api>
int SessionImpl<Api>::ego_lane_index() const {
  if (!answers_.ego_lane_index) {
    const libsumo::TraCIResults* v = ego_variables();
    answers_.ego_lane_index = v ? subscription::subscribed_int(*v, libsumo::VAR_LANE_INDEX, -1)
                                : Api::Vehicle::getLaneIndex(ego_);
  }
  return *answers_.ego_lane_index;
}

template <class Api>
std::optional<SumoSession::Leader> SessionImpl<Api>::ego_leader(double range) const {
  return guarded("the ego's leader", [&]() -> std::optional<Leader> {
    const auto [id, distance] = Api::Vehicle::getLeader(ego_, range);
    if (id.empty()) return std::nullopt;
    return Leader{id, distance + Api::Vehicle::getMinGap(ego_)};  // getLeader measures from front + minGap
  });
}

template <class Api>
std::vector<SumoSession::LaneVehicle> SessionImpl<Api>::vehicles_on_lane(const std::string& lane_id) const {
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

template <class Api>
double SessionImpl<Api>::lateral_offset_from(const std::string& reference_lane_id) const {
  try {
    const std::string& reference_edge = lanes_.lane_edge(reference_lane_id);
    const EgoState& here = ego_state();
    const double in_lane = here.lateral_offset;
    if (here.edge != reference_edge) return in_lane;  // documented fallback
    const int reference_index = lanes_.lane_index_on(reference_edge, reference_lane_id);
    const int ego_index = ego_lane_index();
    if (reference_index < 0 || ego_index < 0) return in_lane;
    return in_lane + lanes_.centre_distance(reference_edge, reference_index, ego_index);
  } catch (const std::exception& e) {
    throw SumoError("cannot measure the ego's offset from lane '" + reference_lane_id + "': " + failure_reason(e));
  }
}

template <class Api>
const std::string& SessionImpl<Api>::light_state(const std::string& tls_id) const {
  if (const std::string* known = answers_.light_states.find(tls_id)) return *known;
  try {
    return answers_.light_states.keep(tls_id, Api::TrafficLight::getRedYellowGreenState(tls_id));
  } catch (const std::exception& e) {
    throw SumoError("SUMO cannot report traffic light '" + tls_id + "': " + failure_reason(e));
  }
}

template <class Api>
std::vector<std::string> SessionImpl<Api>::program_states(const std::string& tls_id) const {
  try {
    std::vector<std::string> states;
    for (const auto& logic : Api::TrafficLight::getAllProgramLogics(tls_id))
      for (const auto& phase : logic.phases) states.push_back(phase->state);
    return states;
  } catch (const std::exception& e) {
    throw SumoError("SUMO cannot report traffic light '" + tls_id + "': " + failure_reason(e));
  }
}

template <class Api>
std::vector<LightProgram> SessionImpl<Api>::light_programs(const std::string& tls_id) const {
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

template <class Api>
LightTiming SessionImpl<Api>::light_timing(const std::string& tls_id) const {
  if (const LightTiming* known = answers_.light_timings.find(tls_id)) return *known;
  try {
    return answers_.light_timings.keep(tls_id,
                             LightTiming{Api::TrafficLight::getProgram(tls_id), Api::TrafficLight::getPhase(tls_id),
                                         Api::TrafficLight::getNextSwitch(tls_id)});
  } catch (const std::exception& e) {
    throw SumoError("SUMO cannot report the timing of traffic light '" + tls_id + "': " + failure_reason(e));
  }
}

}  // namespace signalsim::sumo
