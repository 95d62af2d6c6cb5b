// The stages of one step and the StepLoop that runs them; see step_stages.hpp.
#include "step/step_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "planning/stop/jerk_limited_stop.hpp"
#include "step/route_planning.hpp"
#include "route/approach_lights.hpp"

namespace signalsim {
namespace {

Blinker blinker_of(const TurnSignalDecision& d) {
  if (d.hazard == HazardLights::Enable) return Blinker::Hazard;
  if (d.turn == TurnIndicator::EnableLeft) return Blinker::Left;
  if (d.turn == TurnIndicator::EnableRight) return Blinker::Right;
  return Blinker::None;
}

// The nearest stop line ahead of a light the judge passes on a stop signal (docs/behaviour.md §L2.3 "can pass
// through during yellow lamp"), or +infinity.
double passed_on_stop_signal(const std::vector<LightStep>& lights) {
  double line = std::numeric_limits<double>::infinity();
  for (const LightStep& l : lights)
    if (l.judged && l.front_to_stop_line > 0.0 && l.result.decision == JudgeDecision::Pass &&
        l.result.zone == JudgeZone::PassThroughYellow)
      line = std::min(line, l.light->s_stop_line);
  return line;
}

StopSpeedPlanner stop_planner_for(const EgoSpec& ego) {
  StopPlannerParameters params;
  params.emergency.min_acc = -ego.emergency_decel;
  return StopSpeedPlanner(params, ego.emergency_decel);
}

BehaviorStageConfig behavior_config_for(const Scenario& scenario, const RouteMap& route) {
  BehaviorStageConfig config;
  config.path_forward = scenario.run_params.decider.forward_path_length;
  config.route_length = route.length();
  config.vehicle_length = scenario.ego.length;
  config.max_speed = scenario.ego.max_speed;
  config.gaps = {scenario.run_params.lane_change_safety_rear_gap, scenario.run_params.lane_change_safety_front_gap};
  return config;
}

// The light stage on the route's lights, with arrow bulbs from every program SUMO loaded (additional
// files may replace the net's program); V2I (docs/behaviour.md §L1.7): SUMO's programs and timing through the
// session, used only when it is on.
TrafficLightStage light_stage_for(const StartedRun& run, const sumo::NetIndex& net,
                                  const TrafficLightJudgeParameters& judge) {
  sumo::SumoSession& session = *run.session;
  std::vector<sumo::ApproachLight> approaches = sumo::approach_lights(net, run.plan.map);
  for (sumo::ApproachLight& a : approaches) a.has_arrow = sumo::shows_arrow(session.program_states(a.tls_id), a);
  V2iSource v2i;
  v2i.channel = run.scenario.v2i_channel;
  v2i.programs_of = [&session](const std::string& tls) { return session.light_programs(tls); };
  v2i.timing_of = [&session](const std::string& tls) { return session.light_timing(tls); };
  return TrafficLightStage(std::move(approaches), judge, run.scenario.perception,
                           run.scenario.run_params.decider.forward_path_length, std::move(v2i));
}

}  // namespace

StepLoop::StepLoop(const StartedRun& run, const sumo::NetIndex& net)
    : scenario_(run.scenario),
      route_(run.plan.map),
      lateral_(run.lateral),
      session_(*run.session),
      b2f_(scenario_.ego.base_link_to_front),
      dt_(scenario_.step_length),
      limits_{scenario_.ego.max_speed, scenario_.ego.accel, scenario_.ego.decel},
      judge_params_(scenario_.run_params.judge),
      decider_(turn_signal_parameters(scenario_)),
      behavior_(lateral_, behavior_parameters(scenario_), behavior_config_for(scenario_, route_)),
      lights_(light_stage_for(run, net, judge_params_)),
      stop_speed_(stop_planner_for(scenario_.ego)),
      outcomes_(judge_params_.stop_margin),
      stuck_(scenario_.run_params.stuck_rest_time),
      plan_watch_(route_, lateral_),
      leader_([this](double range) -> std::optional<LeaderInfo> {
        // Vehicle::getLeader: also on the lanes ahead.
        const auto found = session_.ego_leader(range);
        if (!found) return std::nullopt;
        return LeaderInfo{found->id, found->gap};
      }),
      last_s_(scenario_.ego.depart_pos) {
  for (const LateralSegment& seg : behavior_.plan().segments)
    if (seg.kind == LateralKind::PullOver) pull_over_goal_ = &seg;
  record_.base_link_to_front = b2f_;
  record_.sumo = run_sumo_info(run);
  record_.v2i = judge_params_.v2i.use_remaining_time;
  for (const auto& [tls, offset] : scenario_.light_offsets) session_.shift_light_program(tls, offset);
  // `duration` from the ego's departure, and a sumocfg's `end`: whichever comes first.
  end_time_ = std::min(session_.time() + scenario_.duration,
                       scenario_.sumo.end.value_or(std::numeric_limits<double>::infinity()));
}

// observe: the ego's route position (monotonic: searched from the lanelet it was on), whether SUMO
// left the lane plan, and its lateral offset, measured against the planned lane while the ego is on
// a segment's edge.
StepObservation StepLoop::observe() {
  StepObservation now;
  now.sumo = session_.ego();
  const auto located = route_.s_of(now.sumo.lane, now.sumo.edge, now.sumo.lane_pos, hint_);
  if (!located) ++record_.off_route_steps;  // the lane is not on the route: s held (counted)
  const double s_front = located.value_or(last_s_);
  hint_ = route_.index_at(std::max(0.0, s_front - 1e-6));
  last_s_ = s_front;
  now.off_plan = plan_watch_.observe(now.sumo.lane, now.sumo.edge, hint_, s_front, now.sumo.time, record_);
  // Backing up (pull out with `backward`, emulated): not driving forward, negative speed.
  now.backing = backed_up_ < lateral_.backward - 1e-9;
  now.ego = EgoOnRoute{s_front, s_front - b2f_, now.backing ? -kBackwardSpeed : now.sumo.speed};
  if (now.sumo.speed > kRestSpeed) departed_ = true;
  now.segment = behavior_.plan().on_edge(now.sumo.edge);
  now.lateral_offset =
      now.segment ? session_.lateral_offset_from(now.segment->reference_lane) : now.sumo.lateral_offset;
  return now;
}

// maneuver: the behaviour modules (docs/behaviour.md §T8) and the lane changes' phases (sim/behavior_stage).
StepManeuver StepLoop::maneuver(const StepObservation& now) {
  StepManeuver m;
  m.behavior = behavior_.step({.now = now.sumo.time,
                               .ego = now.ego,
                               .accel = now.sumo.accel,
                               .backing = now.backing,
                               .departed = departed_,
                               .segment = now.segment,
                               .lateral_offset = now.lateral_offset},
                              [this](const LateralSegment& seg) { return target_lane_traffic(seg); });
  if (now.segment) m.planned_offset = behavior_.planned_offset(*now.segment, now.ego.s_base, now.backing);
  return m;
}

// A lane change's target lane: the other vehicles on it, in route s (asked only while one waits).
std::vector<OccupiedSpan> StepLoop::target_lane_traffic(const LateralSegment& seg) const {
  std::vector<OccupiedSpan> spans;
  const double lane_start = route_.at(seg.route_index).s_start;
  for (const sumo::SumoSession::LaneVehicle& v : session_.vehicles_on_lane(seg.reference_lane))
    spans.push_back({lane_start + v.pos - v.length, lane_start + v.pos});
  return spans;
}

// window and decide: the decider takes the window of route lanelets around base_link itself, since
// its back length depends on the roundabouts (docs/behaviour.md §T3.2), and resolves the intersection,
// roundabout and behaviour requests.
BlinkerChoice StepLoop::decide(const StepObservation& now, const StepManeuver& maneuver) {
  const TurnSignalDecision decision = decider_.decide(route_, now.ego, maneuver.behavior.behavior);
  return {blinker_of(decision), decision.source};
}

// light: every judge in the window (docs/behaviour.md §L); the ego brakes for the nearest stop requested by any
// of them, and the timeline describes that light, else the nearest one.
StepLights StepLoop::light(const StepObservation& now) {
  StepLights out;
  out.steps = lights_.step(now.sumo.time, now.ego.s_front, now.sumo.speed, now.sumo.accel,
                           [this](const std::string& tls) { return &session_.light_state(tls); });
  for (const LightStep& l : out.steps)
    if (l.result.stop_point_distance &&
        (!out.stopping || *l.result.stop_point_distance < *out.stopping->result.stop_point_distance))
      out.stopping = &l;
  out.shown = out.stopping ? out.stopping : (out.steps.empty() ? nullptr : &out.steps.front());
  // SUMO's right of way would hold the ego at a red line on its own (docs/behaviour.md §S4, measured): while
  // the next junction is a light showing the ego red or yellow, the judge alone decides there.
  out.sumo_right_of_way = !light_decides_next_junction(route_, now.ego.s_front, out.steps);
  return out;
}

// plan: lane limits, and a jerk-limited stop for each stop point (planning/stop/stop_speed_planner).
SpeedPlan StepLoop::plan_speed(const StepObservation& now, const StepManeuver& maneuver, const StepLights& lights) {
  SpeedPlan plan;
  // A light the judge passes on a stop signal (pass_through_yellow: it cannot stop, and reaches the
  // line within the yellow lamp period at its current speed) is crossed at that speed: the limits
  // beyond its stop line apply from the line on (slowing before it for a turn would reach the line
  // on red).
  const double passed_line = passed_on_stop_signal(lights.steps);
  const double limits_speed =
      plan_speed_under_limits(route_, now.ego.s_front, now.sumo.speed, dt_, limits_, passed_line);
  // SUMO would brake ahead of the turn's limit on its own (its safe speed looks at the next lanes'
  // limits): while crossing such a line its lane limits are off, the planner's apply again beyond it.
  plan.sumo_lane_limits = !std::isfinite(passed_line);
  stop_speed_.begin_step(now.sumo.speed, now.sumo.accel, limits_speed, dt_);
  if (lights.stopping) plan.stop_level = stop_speed_.add_stop(*lights.stopping->result.stop_point_distance);
  // The pull-over goal: a jerk-limited stop with base_link at the goal (its level is not recorded).
  std::optional<StopLevel> goal_level;
  if (pull_over_goal_) goal_level = stop_speed_.add_stop(pull_over_goal_->goal_s - now.ego.s_base);
  // A lane change not yet approved: base_link comes to rest before its last possible start (the
  // stop constrains the speed from the step where a normal stop must begin, until approval).
  std::optional<StopLevel> hold_level;
  if (maneuver.behavior.hold_distance) hold_level = stop_speed_.add_stop(*maneuver.behavior.hold_distance);
  plan.speed = stop_speed_.speed();
  plan.emergency_braking = plan.stop_level == StopLevel::Emergency || hold_level == StopLevel::Emergency;
  if (now.backing) plan.speed = 0.0;  // the back-up moves the ego (apply)
  stop_speed_.end_step(plan.speed);
  // What of signalsim holds the ego at rest this step, if anything (the stuck rule).
  // Off the plan, signalsim's stops are for the planned lanes, not the one SUMO drives: it holds nothing.
  if (plan.speed < kRestSpeed && !now.off_plan) {
    plan.held_by = now.backing         ? "backing up"
                   : plan.stop_level   ? "stopped for light " + lights.stopping->light->tls_id
                   : hold_level        ? "the hold point of a lane change waiting for approval"
                   : goal_level        ? "the pull-over goal"
                                       : "its speed plan";
  }
  // In the queue before a red light the ego rests behind others, short of its own stop point: the
  // stuck clock pauses while a judge asks for a stop (a red lasting longer than stuck_rest_time is
  // no deadlock), but does not restart, so a car parked before a light is still found out.
  plan.queued = lights.stopping != nullptr && plan.held_by.empty() && !now.off_plan;
  return plan;
}

// apply: SUMO's modes (right of way, lane limits, emergency braking), the blinker bits and the speed
// (re-sent every step, docs/behaviour.md §S4), the lateral plan's offset, the back-up; then SUMO advances one
// step. Returns false when the ego has arrived.
bool StepLoop::apply(const StepObservation& now, const BlinkerChoice& blinker, const StepLights& lights,
                     const SpeedPlan& plan) {
  session_.set_right_of_way(lights.sumo_right_of_way);
  session_.set_sumo_lane_limits(plan.sumo_lane_limits);
  session_.set_emergency_braking(plan.emergency_braking);
  session_.command(signal_mask(blinker.blinker), plan.speed);
  // The plan's offset where base_link will be after the step (normal lanes of the plan's edge only).
  if (now.segment)
    session_.command_lateral_offset(
        behavior_.planned_offset(*now.segment, now.ego.s_base + plan.speed * dt_, now.backing),
        now.segment->reference_lane);
  if (now.backing) {
    const double back = std::min(kBackwardSpeed * dt_, lateral_.backward - backed_up_);
    session_.move_back(back);
    backed_up_ += back;
  }
  return session_.step();
}

// record: one timeline row, with the mask SUMO showed while executing the decision; events on
// change; stops and red crossings; every light's own entry.
void StepLoop::record_step(const StepObservation& now, const StepManeuver& maneuver, const BlinkerChoice& blinker,
                           const StepLights& lights, const SpeedPlan& plan, bool alive) {
  TimelineRow row = timeline_row(now.sumo, now.ego, now.lateral_offset, maneuver.planned_offset, blinker.blinker,
                                 blinker.source, lights.shown, plan.stop_level);
  row.sumo_signals = alive ? session_.ego_signals() : -1;
  if (!lights.shown)
    if (const sumo::ApproachLight* next = lights_.next_light())  // beyond the horizon
      show_next_light(row, *next, session_.light_state(next->tls_id));
  events_.record(row, maneuver.behavior.transitions, record_);
  outcomes_.observe(row, lights.steps, lights.stopping, leader_, route_, record_);
  log_lights(lights.steps, record_);
  record_.rows.push_back(std::move(row));
}

// end: the ego arrived, the stuck rule holds, or `duration` has passed (sim/stuck_watch).
bool StepLoop::ended(bool alive, const SpeedPlan& plan) {
  if (!alive) {
    record_.arrived = true;
    return true;
  }
  const TimelineRow& last = record_.rows.back();
  if (stuck_.observe(last.time, last.speed, plan.held_by, plan.queued)) return end_not_arrived("stuck");
  if (session_.time() >= end_time_ - 1e-9) return end_not_arrived("duration");
  return false;
}

bool StepLoop::end_not_arrived(const std::string& reason) {
  record_.not_arrived = not_arrived(reason, scenario_.duration, record_.rows.back(), stuck_, leader_, route_);
  plan_watch_.explain(*record_.not_arrived, record_);
  return true;
}

RunRecord StepLoop::finish() {
  record_.collisions = session_.ego_collisions();
  record_.lane_changes = behavior_.lane_change_records();
  record_.maneuver_lines = maneuver_lines(behavior_.plan(), record_.lane_changes,
                                          scenario_.run_params.decider.turn_signal_shift_length_threshold);
  return std::move(record_);
}

}  // namespace signalsim
