#include "scenario/step_loop.hpp"

#include <algorithm>
#include <cmath>

#include "planning/speed_limit_planner.hpp"
#include "sumo/sumo_session.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim {
namespace {

Blinker blinker_of(const TurnSignalDecision& d) {
  if (d.hazard == HazardLights::Enable) return Blinker::Hazard;
  if (d.turn == TurnIndicator::EnableLeft) return Blinker::Left;
  if (d.turn == TurnIndicator::EnableRight) return Blinker::Right;
  return Blinker::None;
}

int signal_mask(Blinker b) {
  switch (b) {
    case Blinker::Left: return sumo::kBlinkerLeft;
    case Blinker::Right: return sumo::kBlinkerRight;
    case Blinker::Hazard: return sumo::kBlinkerEmergency;
    case Blinker::None: break;
  }
  return 0;
}

// The next signalised approach ahead of the front bumper; advances monotonically.
class NextLight {
 public:
  explicit NextLight(const RouteMap& route) {
    for (std::size_t i = 0; i < route.size(); ++i)
      if (route.at(i).traffic_light) approaches_.push_back(i);
  }
  const Lanelet* ahead(const RouteMap& route, double s_front) {
    while (next_ < approaches_.size() && route.at(approaches_[next_]).s_end() < s_front) ++next_;
    return next_ < approaches_.size() ? &route.at(approaches_[next_]) : nullptr;
  }

 private:
  std::vector<std::size_t> approaches_;
  std::size_t next_ = 0;
};

sumo::SessionConfig session_config(const Scenario& scenario, const sumo::RoutePlan& plan) {
  sumo::SessionConfig config;
  config.net = scenario.net;
  config.additional = scenario.additional;
  config.step_length = scenario.step_length;
  config.seed = scenario.seed;
  config.route = scenario.ego.route;
  config.depart_lane = plan.lane_per_edge.empty() ? 0 : plan.lane_per_edge.front();
  config.depart_pos = scenario.ego.depart_pos;
  config.depart_speed = scenario.ego.depart_speed;
  config.max_speed = scenario.ego.max_speed;
  config.length = scenario.ego.length;
  config.accel = scenario.ego.accel;
  config.keep_planned_lanes = plan.lane_changes == 0;
  return config;
}

}  // namespace

RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan) {
  const RouteMap& route = plan.map;
  const double b2f = scenario.ego.base_link_to_front;
  const SpeedLimits limits{scenario.ego.max_speed, scenario.ego.accel, scenario.ego.decel};
  TurnSignalDecider decider(turn_signal_parameters(scenario.params, b2f));
  NextLight next_light(route);

  RunRecord record;
  record.base_link_to_front = b2f;
  sumo::SumoSession session(session_config(scenario, plan));
  const double end_time = session.time() + scenario.duration;
  std::size_t hint = 0;
  double last_s = scenario.ego.depart_pos;
  Blinker previous = Blinker::None;

  sumo::EgoState observed = session.ego();
  while (true) {
    // observe: the ego's route position (monotonic: search from the lanelet it was on).
    const double s_front = route.s_of(observed.lane, observed.edge, observed.lane_pos, hint).value_or(last_s);
    hint = route.index_at(std::max(0.0, s_front - 1e-6));
    last_s = s_front;
    const EgoOnRoute ego{s_front, s_front - b2f, observed.speed};

    // decide, plan, apply, step.
    const TurnSignalDecision decision = decider.decide(route, ego);
    const Blinker blinker = blinker_of(decision);
    const double speed = plan_speed_under_limits(route, s_front, observed.speed, scenario.step_length, limits);
    const Lanelet* light = next_light.ahead(route, s_front);
    const char tl_state = light ? session.link_state(light->traffic_light->tls_id, light->traffic_light->link_index) : 0;
    session.command(signal_mask(blinker), speed);
    const bool alive = session.step();

    // record.
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
    row.blinker = blinker;
    row.blinker_source = blinker == Blinker::None ? RequestSource::None : decision.source;
    row.sumo_signals = alive ? session.ego_signals() : -1;
    if (light) {
      row.tl_id = light->traffic_light->tls_id;
      row.tl_state = tl_state;
    }
    if (blinker != previous) {
      record.events.push_back({row.time, s_front, "blinker", std::string(to_string(previous)),
                               std::string(to_string(blinker)), std::string(to_string(row.blinker_source))});
      previous = blinker;
    }
    record.rows.push_back(std::move(row));

    if (!alive) {
      record.arrived = true;
      break;
    }
    if (session.time() >= end_time - 1e-9) break;
    observed = session.ego();
  }
  record.collisions = session.ego_collisions();
  return record;
}

}  // namespace signalsim
