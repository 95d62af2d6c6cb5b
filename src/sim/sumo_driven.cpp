// The observation loop of a SUMO-driven run; see sumo_driven.hpp for the rules.
#include "sim/sumo_driven.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "scenario/parameters.hpp"
#include "route/approach_lights.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {
namespace {

constexpr double kRestSpeed = 0.01;          // [m/s] at rest, as drive() measures stops
constexpr double kCrossingTolerance = 0.05;  // [m] a red crossing is 5 cm beyond the line, as drive()
constexpr double kLeftBehind = 2.0;          // [m] past its stop line a light is left behind (docs/behaviour.md §L1.2)
constexpr double kLightWindow = 300.0;       // [m] lights ahead whose states are followed

bool is_red(char state) { return state == 'r' || state == 'u'; }
// SUMO stops for these on its own; a rest at a green link (yielding) is no stop at the light.
bool asks_to_stop(char state) { return is_red(state) || state == 'y' || state == 'Y'; }

char link_state(const std::string& state, int link_index) {
  if (link_index < 0 || static_cast<std::size_t>(link_index) >= state.size()) return 0;
  return state[static_cast<std::size_t>(link_index)];
}

// Records stops and red crossings at every light of the route (in route order) as they happen.
class LightWatch {
 public:
  LightWatch(std::vector<sumo::ApproachLight> lights, const RouteMap& route, double stop_margin)
      : lights_(std::move(lights)), route_(route), stop_margin_(stop_margin), states_(lights_.size(), 0) {}

  /// The nearest light not left behind, or nullptr.
  const sumo::ApproachLight* nearest() const { return nearest_ < lights_.size() ? &lights_[nearest_] : nullptr; }
  char nearest_state() const { return nearest_ < lights_.size() ? states_[nearest_] : 0; }

  /// One step: `row` is observed (s_front, speed, time); `state_of(tls)` the live state string.
  template <class StateOf>
  void observe(const TimelineRow& row, StateOf state_of, RunRecord& record) {
    // Red crossings: the state each light had at the previous row is the one the step began with.
    for (std::size_t k = nearest_; k < lights_.size(); ++k) {
      const sumo::ApproachLight& light = lights_[k];
      const double line = light.s_stop_line + kCrossingTolerance;
      if (line > row.s_front + kLightWindow) break;
      if (have_previous_ && previous_front_ <= line && row.s_front > line && is_red(states_[k]))
        record.red_violations.push_back({light.tls_id, row.time, row.s_front});
      states_[k] = link_state(state_of(light.tls_id), light.link_index);
    }
    while (nearest_ < lights_.size() && row.s_front > lights_[nearest_].s_stop_line + kLeftBehind) ++nearest_;
    if (nearest_ < lights_.size() && lights_[nearest_].s_stop_line + kCrossingTolerance > row.s_front + kLightWindow)
      states_[nearest_] = link_state(state_of(lights_[nearest_].tls_id), lights_[nearest_].link_index);
    // A stop: at rest on the nearest light's approach lanelet while its link asks to stop.
    const bool at_rest = row.speed < kRestSpeed;
    if (at_rest && !resting_ && nearest_ < lights_.size()) {
      const sumo::ApproachLight& light = lights_[nearest_];
      if (row.s_front >= route_.at(light.route_index).s_start && asks_to_stop(states_[nearest_])) {
        const double stop_s = light.s_stop_line - stop_margin_;
        LightStop stop;
        stop.tl_id = light.tls_id;
        stop.time = row.time;
        stop.stop_s = stop_s;
        stop.rest_s = row.s_front;
        stop.error = row.s_front - stop_s;
        stop.by_judge = false;
        record.stops.push_back(stop);
        resting_ = true;
      }
    }
    if (!at_rest) resting_ = false;
    previous_front_ = row.s_front;
    have_previous_ = true;
  }

 private:
  std::vector<sumo::ApproachLight> lights_;
  const RouteMap& route_;
  double stop_margin_;
  std::vector<char> states_;     // each light's link state at the last row it was followed
  std::size_t nearest_ = 0;      // lights before it are left behind
  double previous_front_ = 0.0;
  bool have_previous_ = false;
  bool resting_ = false;
};

// Extends the last off-plan stretch or starts one.
void note_off_plan(RunRecord& record, const TimelineRow& row, const std::string& planned, bool continues) {
  if (continues && !record.off_plan.empty() && record.off_plan.back().lane == row.lane) {
    record.off_plan.back().s_to = row.s_front;
    ++record.off_plan.back().steps;
    return;
  }
  record.off_plan.push_back({row.lane, planned, row.s_front, row.s_front, 1});
}

}  // namespace

RoutePosition locate_on_route(const RouteMap& route, const std::string& lane, const std::string& edge, double lane_pos,
                              std::size_t hint, double last_s) {
  RoutePosition out;
  out.on_plan = route.find_lane(lane, hint).has_value();
  out.s = route.s_of(lane, edge, lane_pos, hint);
  // Another connection of a route junction: placed on the junction's route lanelet at or after hint
  // (RouteMap::s_of, at most its end); connections differ in length, so never behind the last s.
  if (out.s && !out.on_plan && !edge.empty() && edge.front() == ':') out.s = std::max(*out.s, last_s);
  return out;
}

RunRecord observe_sumo_drive(const StartedRun& run, const sumo::NetIndex& net) {
  const Scenario& scenario = run.scenario;
  const RouteMap& route = run.plan.map;
  sumo::SumoSession& session = *run.session;
  RunRecord record;
  record.driver = Driver::Sumo;
  record.base_link_to_front = scenario.ego.base_link_to_front;
  record.sumo.backend = session.backend();
  if (run.config.backend.kind == sumo::BackendKind::Connect)
    record.sumo.endpoint = run.config.backend.host + ":" + std::to_string(run.config.backend.port);
  record.sumo.ego = session.ego_vehicle();
  record.sumo.args = run.config.extra_args;
  record.sumo.log = run.config.log_file;
  LightWatch lights(sumo::approach_lights(net, route), route, scenario.run_params.judge.stop_margin);
  const auto state_of = [&session](const std::string& tls) -> const std::string& { return session.light_state(tls); };

  for (const auto& [tls, offset] : scenario.light_offsets) session.shift_light_program(tls, offset);
  const double end_time = session.time() + scenario.duration;
  std::size_t hint = 0;
  double last_s = scenario.ego.depart_pos;
  bool previous_off_plan = false;
  Blinker previous_blinker = Blinker::None;
  while (true) {
    const sumo::EgoState observed = session.ego();
    const int signals = session.ego_signals();
    const RoutePosition located = locate_on_route(route, observed.lane, observed.edge, observed.lane_pos, hint, last_s);
    if (!located.s) ++record.off_route_steps;  // the lane is not on the route: s held (counted)
    const double s_front = located.s.value_or(last_s);
    hint = route.index_at(std::max(0.0, s_front - 1e-6));
    last_s = s_front;

    TimelineRow row;
    row.time = observed.time;
    row.s_front = s_front;
    row.x = observed.x;
    row.y = observed.y;
    row.speed = observed.speed;
    row.accel = observed.accel;
    row.edge = observed.edge;
    row.lane = observed.lane;
    row.lateral_offset = observed.lateral_offset;
    row.blinker = blinker_of_signals(signals);
    row.blinker_source = row.blinker == Blinker::None ? RequestSource::None : RequestSource::Sumo;
    row.sumo_signals = signals;
    lights.observe(row, state_of, record);
    if (const sumo::ApproachLight* light = lights.nearest()) {
      row.tl_id = light->tls_id;
      row.tl_state = lights.nearest_state();
    }
    const bool off_plan = located.s && !located.on_plan;
    if (off_plan) note_off_plan(record, row, route.at(hint).lane_id, previous_off_plan);
    previous_off_plan = off_plan;
    if (row.blinker != previous_blinker) {
      record.events.push_back({row.time, row.s_front, "blinker", std::string(to_string(previous_blinker)),
                               std::string(to_string(row.blinker)), std::string(to_string(row.blinker_source))});
      previous_blinker = row.blinker;
    }
    record.rows.push_back(std::move(row));

    if (!session.step()) {
      record.arrived = true;
      break;
    }
    if (session.time() >= end_time - 1e-9) break;
  }
  record.collisions = session.ego_collisions();
  return record;
}

}  // namespace signalsim
