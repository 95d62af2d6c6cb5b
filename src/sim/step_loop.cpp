#include "sim/step_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "planning/speed_limit_planner.hpp"
#include "planning/stop/jerk_limited_stop.hpp"
#include "planning/stop/stop_speed_planner.hpp"
#include "sim/behavior_stage.hpp"
#include "sim/light_stage.hpp"
#include "sim/plan_watch.hpp"
#include "sim/route_planning.hpp"
#include "sim/session_setup.hpp"
#include "sim/stuck_watch.hpp"
#include "sumo/approach_lights.hpp"
#include "sumo/sumo_session.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim {
namespace {

constexpr double kRestSpeed = 0.01;  // [m/s] below this the ego is at rest (stop errors; a commanded speed: held)

Blinker blinker_of(const TurnSignalDecision& d) {
  if (d.hazard == HazardLights::Enable) return Blinker::Hazard;
  if (d.turn == TurnIndicator::EnableLeft) return Blinker::Left;
  if (d.turn == TurnIndicator::EnableRight) return Blinker::Right;
  return Blinker::None;
}

bool is_red(char state) { return state == 'r' || state == 'u'; }

// Records stops (rest position against the stop point) and red-light crossings as they happen.
class LightOutcomes {
 public:
  explicit LightOutcomes(double stop_margin) : stop_margin_(stop_margin) {}

  /// `stopping`: the light whose stop the ego is braking for this step, if any.
  /// `leader`: SUMO's vehicle ahead, to tell a rest in the queue before a light from the ego's own stop.
  void observe(const TimelineRow& row, const std::vector<LightStep>& lights, const LightStep* stopping,
               const LeaderQuery& leader, const RouteMap& route, RunRecord& record) {
    // A stop: the first step at rest while a stop is requested; a new one only after moving again.
    // The error is measured against the stop line minus stop_margin, not the judge's stop point,
    // which restart suppression moves to wherever the ego stands (spec TLJ §1.6).
    const bool at_rest = row.speed < kRestSpeed;
    if (at_rest && stopping && !resting_) {
      const double stop_s = stopping->light->s_stop_line - stop_margin_;
      LightStop stop{stopping->light->tls_id, row.time, stop_s, row.s_front, row.s_front - stop_s,
                     stopping->result.decision, worst_level_};
      const double to_go = stop_s - row.s_front;
      if (to_go > kQueueGap) {
        if (const auto ahead = leader(to_go); ahead && ahead->gap < to_go) stop.queued_behind = ahead->id;
        const std::size_t here = route.index_at(row.s_front);
        if (stop.queued_behind.empty() && here != stopping->light->route_index)
          for (std::size_t i = here; i < stopping->light->route_index; ++i)
            if (route.at(i).is_internal) {  // the junction the ego is in, or the next one ahead
              stop.waiting_at = route.at(i).junction_id;
              break;
            }
      }
      record.stops.push_back(stop);
      resting_ = true;
    }
    if (!at_rest) resting_ = false;
    if (row.stop_level) worst_level_ = std::max(worst_level_, *row.stop_level);
    if (!stopping) worst_level_ = StopLevel::Normal;
    // A red crossing: the front passes a stop line (beyond a 5 cm stopping tolerance) during a step
    // that began with the ego's link red. Every light in the window is checked, not only the nearest.
    for (const LightStep& light : lights) {
      const double line = light.light->s_stop_line + kCrossingTolerance;
      auto previous = previous_.find(light.light->route_index);
      if (previous != previous_.end() && previous->second.front <= line && row.s_front > line &&
          is_red(previous->second.state))
        record.red_violations.push_back({light.light->tls_id, row.time, row.s_front});
      previous_[light.light->route_index] = {row.s_front, light.own_state};
    }
  }

 private:
  struct Previous {
    double front = 0.0;
    char state = 0;
  };
  static constexpr double kCrossingTolerance = 0.05;  // [m]
  static constexpr double kQueueGap = 0.5;            // [m] closer to its stop point, the ego stopped itself
  double stop_margin_;
  bool resting_ = false;
  StopLevel worst_level_ = StopLevel::Normal;
  std::map<std::size_t, Previous> previous_;  // by approach route index
};

// The nearest stop line ahead of a light the judge passes on a stop signal (spec TLJ §2.3 "can pass
// through during yellow lamp"), or +infinity.
double passed_on_stop_signal(const std::vector<LightStep>& lights) {
  double line = std::numeric_limits<double>::infinity();
  for (const LightStep& l : lights)
    if (l.judged && l.front_to_stop_line > 0.0 && l.result.decision == JudgeDecision::Pass &&
        l.result.zone == JudgeZone::PassThroughYellow)
      line = std::min(line, l.light->s_stop_line);
  return line;
}

void record_event(RunRecord& record, const TimelineRow& row, std::string kind, std::string from, std::string to,
                  std::string source) {
  record.events.push_back({row.time, row.s_front, std::move(kind), std::move(from), std::move(to), std::move(source)});
}

}  // namespace

RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context) {
  const StartedRun run = start_run(plan_run(scenario, plan), net, context);
  return drive(run, net);
}

RunRecord drive(const StartedRun& run, const sumo::NetIndex& net) {
  const Scenario& scenario = run.scenario;
  const sumo::RoutePlan& plan = run.plan;
  const LateralPlan& lateral = run.lateral;
  sumo::SumoSession& session = *run.session;
  const RouteMap& route = plan.map;
  const double b2f = scenario.ego.base_link_to_front;
  const double dt = scenario.step_length;
  const SpeedLimits limits{scenario.ego.max_speed, scenario.ego.accel, scenario.ego.decel};
  StopPlannerParameters stop_params;
  stop_params.emergency.min_acc = -scenario.ego.emergency_decel;
  StopSpeedPlanner stop_speed(stop_params, scenario.ego.emergency_decel);
  TurnSignalDecider decider(turn_signal_parameters(scenario.params, b2f));
  RunRecord record;
  record.base_link_to_front = b2f;
  record.sumo.backend = session.backend();
  if (run.config.backend.kind == sumo::BackendKind::Connect)
    record.sumo.endpoint = run.config.backend.host + ":" + std::to_string(run.config.backend.port);
  record.sumo.ego = session.ego_vehicle();
  record.sumo.args = run.config.extra_args;
  record.sumo.out_dir = run.out_dir;
  record.sumo.log = run.config.log_file;
  record.sumo.server_options = session.server_options();
  record.sumo.notes = run.notes;
  BehaviorStageConfig behavior_config;
  behavior_config.path_forward = scenario.params.number("forward_path_length");
  behavior_config.route_length = route.length();
  behavior_config.vehicle_length = scenario.ego.length;
  behavior_config.max_speed = scenario.ego.max_speed;
  behavior_config.gaps = {scenario.params.number("lane_change_safety_rear_gap"),
                          scenario.params.number("lane_change_safety_front_gap")};
  BehaviorStage behavior_stage(
      lateral, behavior_parameters(scenario.params, decider.parameters(), scenario.ego.length, kObstacleWidth),
      behavior_config);
  // A lane change's target lane: the other vehicles on it, in route s (asked only while one waits).
  const auto target_lane_traffic = [&](const LateralSegment& seg) {
    std::vector<OccupiedSpan> spans;
    const double lane_start = route.at(seg.route_index).s_start;
    for (const sumo::SumoSession::LaneVehicle& v : session.vehicles_on_lane(seg.reference_lane))
      spans.push_back({lane_start + v.pos - v.length, lane_start + v.pos});
    return spans;
  };
  // Arrow bulbs from every program SUMO loaded (additional files may replace the net's program).
  std::vector<sumo::ApproachLight> approaches = sumo::approach_lights(net, route);
  for (sumo::ApproachLight& a : approaches) a.has_arrow = sumo::shows_arrow(session.program_states(a.tls_id), a);
  const TrafficLightJudgeParameters judge_params = traffic_light_parameters(scenario.params);
  // V2I (spec TLJ §1.7): SUMO's programs and timing through the session, only when it is on.
  V2iSource v2i;
  v2i.channel = scenario.v2i_channel;
  v2i.programs_of = [&session](const std::string& tls) { return session.light_programs(tls); };
  v2i.timing_of = [&session](const std::string& tls) { return session.light_timing(tls); };
  record.v2i = judge_params.v2i.use_remaining_time;
  TrafficLightStage lights(std::move(approaches), judge_params, scenario.perception,
                           scenario.params.number("forward_path_length"), std::move(v2i));
  LightOutcomes outcomes(judge_params.stop_margin);
  const auto light_state = [&session](const std::string& tls) { return session.light_state(tls); };

  for (const auto& [tls, offset] : scenario.light_offsets) session.shift_light_program(tls, offset);
  // `duration` from the ego's departure, and a sumocfg's `end`: whichever comes first.
  const double end_time = std::min(session.time() + scenario.duration,
                                   scenario.sumo.end.value_or(std::numeric_limits<double>::infinity()));
  std::size_t hint = 0;
  double last_s = scenario.ego.depart_pos;
  Blinker previous_blinker = Blinker::None;
  JudgeDecision previous_decision = JudgeDecision::None;
  bool previous_v2i_stop = false;

  bool departed = false;  // the ego has moved (start planner: has_departed)
  double backed_up = 0.0;  // [m] emulated backward driving done so far
  const LateralSegment* pull_over_goal = nullptr;
  for (const LateralSegment& seg : behavior_stage.plan().segments)
    if (seg.kind == LateralKind::PullOver) pull_over_goal = &seg;

  StuckWatch stuck(scenario.params.number("stuck_rest_time"));
  PlanWatch plan_watch(route, lateral);  // where SUMO leaves the lane plan
  // SUMO's leader of the ego for a not-arrived reason (Vehicle::getLeader: also on the lanes ahead).
  const LeaderQuery leader = [&session](double range) -> std::optional<LeaderInfo> {
    const auto found = session.ego_leader(range);
    if (!found) return std::nullopt;
    return LeaderInfo{found->id, found->gap};
  };
  sumo::EgoState observed = session.ego();
  while (true) {
    // observe: the ego's route position (monotonic: search from the lanelet it was on).
    const auto located = route.s_of(observed.lane, observed.edge, observed.lane_pos, hint);
    if (!located) ++record.off_route_steps;  // the lane is not on the route: s held (counted)
    const double s_front = located.value_or(last_s);
    hint = route.index_at(std::max(0.0, s_front - 1e-6));
    last_s = s_front;
    const bool off_plan = plan_watch.observe(observed.lane, observed.edge, hint, s_front, observed.time, record);
    // Backing up (pull out with `backward`, emulated): not driving forward, negative speed.
    const bool backing = backed_up < lateral.backward - 1e-9;
    const EgoOnRoute ego{s_front, s_front - b2f, backing ? -kBackwardSpeed : observed.speed};
    if (observed.speed > kRestSpeed) departed = true;

    // lateral plan: measured against the planned lane while the ego is on a segment's edge.
    const LateralSegment* segment = behavior_stage.plan().on_edge(observed.edge);
    const double lateral_offset =
        segment ? session.lateral_offset_from(segment->reference_lane) : observed.lateral_offset;

    // behaviour modules (spec TSD §8) and the lane changes' phases (scenario/behavior_stage).
    BehaviorStage::Observation behavior_observation;
    behavior_observation.now = observed.time;
    behavior_observation.ego = ego;
    behavior_observation.accel = observed.accel;
    behavior_observation.backing = backing;
    behavior_observation.departed = departed;
    behavior_observation.segment = segment;
    behavior_observation.lateral_offset = lateral_offset;
    const BehaviorStage::Result behavior_step = behavior_stage.step(behavior_observation, target_lane_traffic);
    const TurnSignalInfo& behavior = behavior_step.behavior;
    std::optional<double> planned_offset;
    if (segment) planned_offset = behavior_stage.planned_offset(*segment, ego.s_base, backing);

    // decide: blinker (spec TSD) and light (spec TLJ).
    const TurnSignalDecision decision = decider.decide(route, ego, behavior);
    const Blinker blinker = blinker_of(decision);
    const std::vector<LightStep> light_steps =
        lights.step(observed.time, s_front, observed.speed, observed.accel, light_state);
    // The light the ego brakes for: the nearest stop requested by any judge in the window.
    const LightStep* stopping = nullptr;
    for (const LightStep& l : light_steps)
      if (l.result.stop_point_distance &&
          (!stopping || *l.result.stop_point_distance < *stopping->result.stop_point_distance))
        stopping = &l;
    // The timeline describes that light, else the nearest one.
    const LightStep* shown = stopping ? stopping : (light_steps.empty() ? nullptr : &light_steps.front());

    // SUMO's right of way would hold the ego at a red line on its own (spec SUMO §4, measured): while
    // the next junction is a light showing the ego red or yellow, the judge alone decides there.
    session.set_right_of_way(!light_decides_next_junction(route, s_front, light_steps));

    // plan: lane limits, and a jerk-limited stop for each stop point (planning/stop/stop_speed_planner).
    // A light the judge passes on a stop signal (pass_through_yellow: it cannot stop, and reaches the
    // line within the yellow lamp period at its current speed) is crossed at that speed: the limits
    // beyond its stop line apply from the line on (slowing before it for a turn would reach the line
    // on red, issue 11).
    const double passed_line = passed_on_stop_signal(light_steps);
    const double limits_speed = plan_speed_under_limits(route, s_front, observed.speed, dt, limits, passed_line);
    // SUMO would brake ahead of the turn's limit on its own (its safe speed looks at the next lanes'
    // limits): while crossing such a line its lane limits are off, the planner's apply again beyond it.
    session.set_sumo_lane_limits(!std::isfinite(passed_line));
    stop_speed.begin_step(observed.speed, observed.accel, limits_speed, dt);
    std::optional<StopLevel> stop_level;
    if (stopping) stop_level = stop_speed.add_stop(*stopping->result.stop_point_distance);
    // The pull-over goal: a jerk-limited stop with base_link at the goal (its level is not recorded).
    std::optional<StopLevel> goal_level;
    if (pull_over_goal) goal_level = stop_speed.add_stop(pull_over_goal->goal_s - ego.s_base);
    // A lane change not yet approved: base_link comes to rest before its last possible start (the
    // stop constrains the speed from the step where a normal stop must begin, until approval).
    std::optional<StopLevel> hold_level;
    if (behavior_step.hold_distance) hold_level = stop_speed.add_stop(*behavior_step.hold_distance);
    double speed = stop_speed.speed();
    session.set_emergency_braking(stop_level == StopLevel::Emergency || hold_level == StopLevel::Emergency);

    // apply, step.
    if (backing) speed = 0.0;
    stop_speed.end_step(speed);
    // What of signalsim holds the ego at rest this step, if anything (the stuck rule).
    // Off the plan, signalsim's stops are for the planned lanes, not the one SUMO drives: it holds nothing.
    std::string held_by;
    if (speed < kRestSpeed && !off_plan) {
      held_by = backing       ? "backing up"
                : stop_level  ? "stopped for light " + stopping->light->tls_id
                : hold_level  ? "the hold point of a lane change waiting for approval"
                : goal_level  ? "the pull-over goal"
                              : "its speed plan";
    }
    // In the queue before a red light the ego rests behind others, short of its own stop point: the
    // stuck clock pauses while a judge asks for a stop (a red lasting longer than stuck_rest_time is
    // no deadlock), but does not restart, so a car parked before a light is still found out.
    const bool queued = stopping != nullptr && held_by.empty() && !off_plan;
    session.command(signal_mask(blinker), speed);
    // The plan's offset where base_link will be after the step (normal lanes of the plan's edge only).
    if (segment)
      session.command_lateral_offset(behavior_stage.planned_offset(*segment, ego.s_base + speed * dt, backing),
                                     segment->reference_lane);
    if (backing) {
      const double back = std::min(kBackwardSpeed * dt, lateral.backward - backed_up);
      session.move_back(back);
      backed_up += back;
    }
    const bool alive = session.step();

    // record.
    TimelineRow row;
    row.time = observed.time;
    row.s_front = s_front;
    row.x = observed.x;
    row.y = observed.y;
    row.speed = ego.speed;  // signed: negative while backing up
    row.accel = observed.accel;
    row.edge = observed.edge;
    row.lane = observed.lane;
    row.lateral_offset = lateral_offset;
    row.planned_offset = planned_offset;
    row.blinker = blinker;
    row.blinker_source = blinker == Blinker::None ? RequestSource::None : decision.source;
    row.sumo_signals = alive ? session.ego_signals() : -1;
    if (shown) {
      row.tl_id = shown->light->tls_id;
      row.tl_state = shown->own_state;
    } else if (const sumo::ApproachLight* next = lights.next_light()) {  // beyond the horizon
      row.tl_id = next->tls_id;
      const std::string state = session.light_state(next->tls_id);
      if (next->link_index >= 0 && static_cast<std::size_t>(next->link_index) < state.size())
        row.tl_state = state[static_cast<std::size_t>(next->link_index)];
    }
    if (shown && shown->judged) {
      row.tl_observed = shown->observed;
      row.tl_decision = shown->result.decision;
      row.zone = shown->result.zone;
      row.stop_distance = shown->result.distance;
      row.judge_distance = shown->result.judge_dist;
      row.yellow_lamp_line = shown->result.yellow_lamp_line;
      if (shown->result.stop_point_distance) row.stop_s = s_front + *shown->result.stop_point_distance;
      row.stop_level = stop_level;
      row.v2i_stop = shown->result.v2i_stop;
      row.v2i_time_to_red = shown->result.v2i_time_to_red;
    }
    if (blinker != previous_blinker) {
      record_event(record, row, "blinker", std::string(to_string(previous_blinker)), std::string(to_string(blinker)),
                   std::string(to_string(row.blinker_source)));
      previous_blinker = blinker;
    }
    for (const BehaviorStage::Transition& t : behavior_step.transitions)
      record_event(record, row, "lane_change", to_string(t.from), to_string(t.to), t.edge);
    if (row.tl_decision != previous_decision) {
      record_event(record, row, "light", std::string(to_string(previous_decision)),
                   std::string(to_string(row.tl_decision)), row.tl_id);
      previous_decision = row.tl_decision;
    }
    // With V2I on: when its rule starts or stops holding for the light shown (spec TLJ §1.7).
    if (record.v2i && row.v2i_stop != previous_v2i_stop) {
      record_event(record, row, "v2i", previous_v2i_stop ? "red_predicted" : "none",
                   row.v2i_stop ? "red_predicted" : "none", row.tl_id);
      previous_v2i_stop = row.v2i_stop;
    }
    outcomes.observe(row, light_steps, stopping, leader, route, record);
    for (const LightStep& l : light_steps)  // every light its own record, whichever the row shows
      record.light_log.push_back({record.rows.size(), l.light->route_index, l.own_state,
                                  l.judged ? l.result.decision : JudgeDecision::None,
                                  l.judged ? l.result.zone : JudgeZone::None});
    record.rows.push_back(std::move(row));

    if (!alive) {
      record.arrived = true;
      break;
    }
    if (stuck.observe(record.rows.back().time, record.rows.back().speed, held_by, queued)) {
      record.not_arrived = not_arrived("stuck", scenario.duration, record.rows.back(), stuck, leader, route);
      plan_watch.explain(*record.not_arrived, record);
      break;
    }
    if (session.time() >= end_time - 1e-9) {
      record.not_arrived = not_arrived("duration", scenario.duration, record.rows.back(), stuck, leader, route);
      plan_watch.explain(*record.not_arrived, record);
      break;
    }
    observed = session.ego();
  }
  record.collisions = session.ego_collisions();
  record.lane_changes = behavior_stage.lane_change_records();
  record.maneuver_lines = maneuver_lines(behavior_stage.plan(), record.lane_changes,
                                         scenario.params.number("turn_signal_shift_length_threshold"));
  return record;
}

}  // namespace signalsim
