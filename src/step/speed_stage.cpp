// The plan stage: the speed under the lane limits and the stops of the step; see speed_stage.hpp.
#include "step/speed_stage.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include "step/stuck_watch.hpp"

namespace signalsim {
namespace {

// The nearest stop line ahead of a light the judge passes on a stop signal (docs/behaviour.md §L2.3
// "can pass through during yellow lamp"), or +infinity.
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

}  // namespace

SpeedStage::SpeedStage(const Scenario& scenario, const RouteMap& route, const LateralSegment* pull_over_goal)
    : route_(route),
      limits_{scenario.ego.max_speed, scenario.ego.accel, scenario.ego.decel},
      dt_(scenario.step_length),
      pull_over_goal_(pull_over_goal),
      stop_speed_(stop_planner_for(scenario.ego)) {
  // After SUMO braked the ego harder than its decel (a leader, a junction), the plan goes on from
  // the ego's own limits, not from that braking (behaviour.md §P1).
  stop_speed_.set_start_bounds(-limits_.decel, limits_.accel);
}

// The lane limits, then a jerk-limited stop for each stop point (planning/stop/stop_speed_planner).
SpeedPlan SpeedStage::plan(const SpeedInput& in) {
  SpeedPlan plan;
  // A light the judge passes on a stop signal (pass_through_yellow: it cannot stop, and reaches the
  // line within the yellow lamp period at its current speed) is crossed at that speed: held (no
  // acceleration), and the limits beyond its stop line apply from the line on (slowing before it for
  // a turn would reach the line on red).
  const HeldToLine held{passed_on_stop_signal(*in.lights)};
  const double a0 = stop_speed_.begin_step(in.speed, in.accel, dt_);
  const LimitsPlan limits = plan_speed_under_limits(route_, in.s_front, in.speed, a0, dt_, limits_, held);
  // SUMO would brake ahead of a limit at its own (type) decel: while crossing a line passed on a stop
  // signal, or above a limit the ego's decel cannot meet, its lane limits are off and the ego brakes
  // at its own decel (docs/behaviour.md §P1.3).
  plan.sumo_lane_limits = !std::isfinite(held.stop_line) && limits.feasible;
  stop_speed_.set_cruise(limits.step.speed, limits.step.accel);
  // Releasing a deceleration (jerk-limited), the slowing is still for what set the speed before.
  plan.limited_by = limits.releasing && !last_limited_by_.empty() ? last_limited_by_ : std::string(to_string(limits.by));
  // The stop that sets the speed names it: the lowest speed any stop alone would command, and among
  // equal ones (at rest every stop says 0) the nearest point (a hold point before a light's line).
  std::optional<std::pair<double, double>> lowest;  // (speed alone, to_go)
  const auto add_stop = [&](double to_go, const char* what) {
    const std::optional<StopLevel> level = stop_speed_.add_stop(to_go);
    const double alone = stop_speed_.last_speed_alone();
    if (alone < limits.step.speed || level) {
      const std::pair<double, double> key{alone, to_go};
      if (!lowest || alone < lowest->first - 1e-9 || (alone <= lowest->first + 1e-9 && to_go < lowest->second)) {
        lowest = key;
        plan.limited_by = what;
      }
    }
    return level;
  };
  if (in.stopping) plan.stop_level = add_stop(*in.stopping->result.stop_point_distance, "light_stop");
  // The pull-over goal: a jerk-limited stop with base_link at the goal (its level is not recorded).
  std::optional<StopLevel> goal_level;
  if (pull_over_goal_) goal_level = add_stop(pull_over_goal_->goal_s - in.s_base, "pull_over_goal");
  // A module's hold (a lane change or an avoidance waiting for approval, an avoidance holding on
  // approval, a pull out before it starts): base_link comes to rest there (the stop constrains the
  // speed from the step where a normal stop must begin, until the hold ends).
  const std::optional<BehaviorStage::Hold>& hold = *in.hold;
  std::optional<StopLevel> hold_level;
  if (hold) hold_level = add_stop(hold->distance, hold->kind);
  plan.speed = stop_speed_.speed();
  plan.emergency_braking = plan.stop_level == StopLevel::Emergency || hold_level == StopLevel::Emergency;
  if (in.backing) {
    plan.speed = 0.0;  // the back-up moves the ego (apply)
    plan.limited_by = "backing";
  }
  stop_speed_.end_step(plan.speed);
  last_limited_by_ = plan.limited_by;
  // What of signalsim holds the ego at rest this step, if anything (the stuck rule).
  // Off the plan, signalsim's stops are for the planned lanes, not the one SUMO drives: it holds nothing.
  // A command above the current speed is a start (a gentle one begins below kRestSpeed): not a hold.
  if (plan.speed < kRestSpeed && plan.speed <= in.speed && !in.off_plan) {
    plan.held_by = in.moving_back    ? "backing up"
                   : plan.stop_level ? "stopped for light " + in.stopping->light->tls_id
                   : hold_level      ? std::string(hold->reason)
                   : goal_level      ? "the pull-over goal"
                                     : "its speed plan";
  }
  // In the queue before a red light the ego rests behind others, short of its own stop point: the
  // stuck clock pauses while a judge asks for a stop (a red lasting longer than stuck_rest_time is
  // no deadlock), but does not restart, so a car parked before a light is still found out.
  plan.queued = in.stopping != nullptr && plan.held_by.empty() && !in.off_plan;
  return plan;
}

}  // namespace signalsim
