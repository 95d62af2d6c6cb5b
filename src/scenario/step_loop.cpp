#include "scenario/step_loop.hpp"

#include <algorithm>
#include <cmath>

#include "planning/speed_limit_planner.hpp"
#include "planning/stop/jerk_limited_stop.hpp"
#include "scenario/light_stage.hpp"
#include "sumo/approach_lights.hpp"
#include "sumo/sumo_session.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim {
namespace {

constexpr double kRestSpeed = 0.01;  // [m/s] below this the ego counts as at rest for stop errors

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

bool is_stop(JudgeDecision d) { return d == JudgeDecision::Stop || d == JudgeDecision::EmergencyStop; }
bool is_red(char state) { return state == 'r' || state == 'u'; }

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
  config.emergency_decel = scenario.ego.emergency_decel;
  config.keep_planned_lanes = plan.lane_changes == 0;
  return config;
}

// Records stops (rest position against the stop point) and red-light crossings as they happen.
class LightOutcomes {
 public:
  void observe(const TimelineRow& row, const LightStep& light, double s_stop_line, RunRecord& record) {
    // A stop: the first step at rest while a stop is requested; a new one only after moving again.
    const bool at_rest = row.speed < kRestSpeed;
    if (at_rest && is_stop(row.tl_decision) && row.stop_s && !resting_) {
      record.stops.push_back({row.tl_id, row.time, *row.stop_s, row.s_front, row.s_front - *row.stop_s,
                              row.tl_decision, worst_level_});
      resting_ = true;
    }
    if (!at_rest) resting_ = false;
    if (row.stop_level) worst_level_ = std::max(worst_level_, *row.stop_level);
    if (!is_stop(row.tl_decision)) worst_level_ = StopLevel::Normal;
    // A red crossing: the front passes the stop line during a step that began on red.
    if (light.light && previous_tl_ == row.tl_id && previous_front_ < s_stop_line && row.s_front >= s_stop_line &&
        is_red(previous_state_))
      record.red_violations.push_back({row.tl_id, row.time, row.s_front});
    previous_tl_ = row.tl_id;
    previous_front_ = row.s_front;
    previous_state_ = row.tl_state;
  }

 private:
  bool resting_ = false;
  StopLevel worst_level_ = StopLevel::Normal;
  std::string previous_tl_;
  double previous_front_ = 0.0;
  char previous_state_ = 0;
};

void record_event(RunRecord& record, const TimelineRow& row, std::string kind, std::string from, std::string to,
                  std::string source) {
  record.events.push_back({row.time, row.s_front, std::move(kind), std::move(from), std::move(to), std::move(source)});
}

}  // namespace

RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net) {
  const RouteMap& route = plan.map;
  const double b2f = scenario.ego.base_link_to_front;
  const double dt = scenario.step_length;
  const SpeedLimits limits{scenario.ego.max_speed, scenario.ego.accel, scenario.ego.decel};
  StopPlannerParameters stop_params;
  stop_params.emergency.min_acc = -scenario.ego.emergency_decel;
  TurnSignalDecider decider(turn_signal_parameters(scenario.params, b2f));
  RunRecord record;
  record.base_link_to_front = b2f;
  sumo::SumoSession session(session_config(scenario, plan));
  // Arrow bulbs from every program SUMO loaded (additional files may replace the net's program).
  std::vector<sumo::ApproachLight> approaches = sumo::approach_lights(net, route);
  for (sumo::ApproachLight& a : approaches) a.has_arrow = sumo::shows_arrow(session.program_states(a.tls_id), a);
  TrafficLightStage lights(std::move(approaches), traffic_light_parameters(scenario.params), scenario.perception,
                           scenario.params.number("forward_path_length"));
  LightOutcomes outcomes;

  for (const auto& [tls, offset] : scenario.light_offsets) session.shift_light_program(tls, offset);
  const double end_time = session.time() + scenario.duration;
  std::size_t hint = 0;
  double last_s = scenario.ego.depart_pos;
  Blinker previous_blinker = Blinker::None;
  JudgeDecision previous_decision = JudgeDecision::None;

  sumo::EgoState observed = session.ego();
  while (true) {
    // observe: the ego's route position (monotonic: search from the lanelet it was on).
    const double s_front = route.s_of(observed.lane, observed.edge, observed.lane_pos, hint).value_or(last_s);
    hint = route.index_at(std::max(0.0, s_front - 1e-6));
    last_s = s_front;
    const EgoOnRoute ego{s_front, s_front - b2f, observed.speed};

    // decide: blinker (spec TSD) and light (spec TLJ).
    const TurnSignalDecision decision = decider.decide(route, ego);
    const Blinker blinker = blinker_of(decision);
    const sumo::ApproachLight* approached = lights.current();
    const std::string state = approached ? session.light_state(approached->tls_id) : std::string();
    const double s_stop_line = approached ? approached->s_stop_line : 0.0;
    const LightStep light = lights.step(observed.time, s_front, observed.speed, observed.accel, state);

    // plan: lane limits, and a jerk-limited stop when the judge asks for one.
    double speed = plan_speed_under_limits(route, s_front, observed.speed, dt, limits);
    std::optional<StopLevel> stop_level;
    if (light.result.stop_point_distance) {
      const StopCommand stop = plan_stop({observed.speed, observed.accel, *light.result.stop_point_distance, dt}, stop_params);
      if (stop.braking || stop.commanded_velocity < speed) {
        speed = std::min(speed, stop.commanded_velocity);
        stop_level = stop.level;
      }
    }
    session.set_emergency_braking(stop_level == StopLevel::Emergency);

    // apply, step.
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
    if (light.light) {
      row.tl_id = light.light->tls_id;
      row.tl_state = light.own_state;
    }
    if (light.judged) {
      row.tl_observed = light.observed;
      row.tl_decision = light.result.decision;
      row.zone = light.result.zone;
      row.stop_distance = light.result.distance;
      row.judge_distance = light.result.judge_dist;
      row.yellow_lamp_line = light.result.yellow_lamp_line;
      if (light.result.stop_point_distance) row.stop_s = s_front + *light.result.stop_point_distance;
      row.stop_level = stop_level;
    }
    if (blinker != previous_blinker) {
      record_event(record, row, "blinker", std::string(to_string(previous_blinker)), std::string(to_string(blinker)),
                   std::string(to_string(row.blinker_source)));
      previous_blinker = blinker;
    }
    if (row.tl_decision != previous_decision) {
      record_event(record, row, "light", std::string(to_string(previous_decision)),
                   std::string(to_string(row.tl_decision)), row.tl_id);
      previous_decision = row.tl_decision;
    }
    outcomes.observe(row, light, s_stop_line, record);
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
