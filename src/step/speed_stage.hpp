// The plan stage of a signalsim-driven step (docs/behaviour.md §P): the speed to command and what
// set it, SUMO's modes for it, and what holds the ego at rest.
//
//   a_0     the acceleration the profiles start from (planning/stop/stop_speed_planner: the last
//           command's, while SUMO followed it)
//   limits  the lane limits and the vehicle's maximum, jerk-limited (planning/speed_limit_planner);
//           held to the line of a light passed on a stop signal
//   stops   a jerk-limited stop for the light the ego brakes for, the pull-over goal and a module's
//           hold, each lowering the speed further (the lowest sets `limited_by`)
//   modes   SUMO's own lane limits are off while a line passed on a stop signal is ahead, or while
//           the ego is above a limit it cannot meet within its decel (it brakes at its own decel
//           there, not at SUMO's clamp); emergency braking while a stop needs the emergency level
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "map/route_map.hpp"
#include "planning/speed_limit_planner.hpp"
#include "planning/stop/stop_speed_planner.hpp"
#include "scenario/scenario.hpp"
#include "step/behavior_stage.hpp"
#include "step/light_stage.hpp"

namespace signalsim {

/// plan: the speed commanded for the step, SUMO's modes for it, and what holds the ego.
struct SpeedPlan {
  double speed = 0.0;                   ///< [m/s] commanded (0 while backing up)
  std::string limited_by;               ///< what set it (docs/outputs.md `speed_limited_by`)
  std::optional<StopLevel> stop_level;  ///< the constraint set of the light's stop, if braking for one
  bool sumo_lane_limits = true;         ///< SUMO holds the ego to the lanes' limits itself
  bool emergency_braking = false;       ///< SUMO may brake beyond the ego's decel
  std::string held_by;                  ///< what of signalsim holds the ego at rest ("" when nothing)
  bool queued = false;                  ///< at rest in a queue before a light asking for a stop
};

/// What the plan stage reads of the step.
struct SpeedInput {
  double s_front = 0.0;   ///< [m] route s
  double s_base = 0.0;    ///< [m] route s
  double speed = 0.0;     ///< [m/s] SUMO's
  double accel = 0.0;     ///< [m/s^2] SUMO's (the step's mean)
  bool backing = false;   ///< a back-up is still to drive
  bool moving_back = false;
  bool off_plan = false;
  const std::vector<LightStep>* lights = nullptr;
  const LightStep* stopping = nullptr;  ///< the light the ego brakes for, if any
  const std::optional<BehaviorStage::Hold>* hold = nullptr;
};

class SpeedStage {
 public:
  /// `pull_over_goal`: the plan's last pull over, if any (its goal is a stop for base_link).
  SpeedStage(const Scenario& scenario, const RouteMap& route, const LateralSegment* pull_over_goal);

  SpeedPlan plan(const SpeedInput& in);

 private:
  const RouteMap& route_;
  const SpeedLimits limits_;
  const double dt_;
  const LateralSegment* pull_over_goal_;
  StopSpeedPlanner stop_speed_;
  std::string last_limited_by_;  // the previous step's speed_limited_by
};

}  // namespace signalsim
