// What happened at the lights of a signalsim-driven run, as it happens (RunRecord::stops and
// RunRecord::red_violations): each stop of the ego at a light it brakes for (its rest position
// against the stop point, the worst stop level on the way, a queue or junction it waited behind
// instead), and each crossing of a stop line on red, at every light in the judges' window.
// step/sumo_driven_core keeps the same rules for a SUMO-driven run (LightWatch).
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "map/route_map.hpp"
#include "report/timeline.hpp"
#include "step/light_stage.hpp"
#include "step/stuck_watch.hpp"

namespace signalsim {

/// [m] a front this far beyond a stop line has crossed it (a stopping tolerance).
inline constexpr double kCrossingTolerance = 0.05;

/// A red crossing: during the step from `previous_front` to `front` [m route s] the front passed
/// `stop_line` + kCrossingTolerance while the ego's link showed `state_at_step_start` red (r or u). Both
/// drivers count red crossings by this rule.
inline bool crossed_on_red(double previous_front, double front, double stop_line, char state_at_step_start) {
  const double line = stop_line + kCrossingTolerance;
  return previous_front <= line && front > line && (state_at_step_start == 'r' || state_at_step_start == 'u');
}

/// Whether a row's speed_limited_by is a behaviour module's hold or the pull-over goal.
bool held_by_module(const std::string& speed_limited_by);

class LightOutcomes {
 public:
  /// `stop_margin` [m]: the judge's (a stop's error is measured against stop line - stop_margin).
  explicit LightOutcomes(double stop_margin) : stop_margin_(stop_margin) {}

  /// One step's row. `lights`: every light in the window this step. `stopping`: the light whose
  /// stop the ego is braking for this step, if any. `leader`: SUMO's vehicle ahead at the row (within
  /// kLeaderRange, observed when needs_leader said so), to tell a rest in the queue before a light
  /// from the ego's own stop. A rest a module holds (held_by_module(row.speed_limited_by)) is no stop
  /// at a light. Appends to record.stops and record.red_violations.
  void observe(const TimelineRow& row, const std::vector<LightStep>& lights, const LightStep* stopping,
               const std::optional<LeaderInfo>& leader, const RouteMap& route, RunRecord& record);

  /// Whether a row with this signed `speed` may begin a stop (the ego comes to rest): the step's
  /// observation must then hold SUMO's leader.
  bool needs_leader(double speed) const { return speed < kRestSpeed && !resting_; }

 private:
  struct Previous {
    double front = 0.0;
    char state = 0;
  };
  static constexpr double kQueueGap = 0.5;            // [m] closer to its stop point, the ego stopped itself
  double stop_margin_;
  bool resting_ = false;
  StopLevel worst_level_ = StopLevel::Normal;
  std::map<std::size_t, Previous> previous_;  // by approach route index
};

}  // namespace signalsim
