// The behaviour stage of the step loop (docs/behaviour.md §T8): every step it builds the inputs of the four
// behaviour modules from the scenario's lateral plan and the ego, runs them in Autoware's order
// (merge_behavior_requests), and moves each lane change through its phases (pending, waiting for
// approval, running, done; planning/lane_change_execution.hpp). It also says where the ego must be
// sideways: the planned offset of the maneuver on the ego's edge.
//
// When each module runs (as Autoware would run it):
// - lane change: the first lane change not yet done whose earliest start lies within the module
//   path (forward_path_length ahead of base_link), until base_link passes its lateral motion's end;
//   the module is reset after each lane change, so the next one starts afresh;
// - avoidance: once its whole plan lies within the module path (Autoware registers shift lines only
//   for objects within the path), until its last line is behind base_link; its lines count from
//   approval (waiting, holding: planning/avoidance_execution.hpp);
// - start planner (pull out): from the run's start until base_link passes the pull-out end; it holds
//   the ego before engagement and for prepare_time_before_start after (planning/pull_out_departure.hpp);
// - goal planner (pull over): once the pull-over goal lies within the module path.
// No SUMO here: the stage names the lane whose traffic it may need (waiting_lane_change) and is handed
// that traffic with the step's observation.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/vehicle_defaults.hpp"
#include "planning/avoidance_execution.hpp"
#include "planning/lane_change_execution.hpp"
#include "planning/pull_out_departure.hpp"
#include "step/route_planning.hpp"
#include "report/timeline.hpp"
#include "turn_signal/behavior_modules.hpp"

namespace signalsim {

struct BehaviorStageConfig {
  double path_forward = 300.0;   ///< [m] module path ahead of base_link (forward_path_length)
  double route_length = 0.0;     ///< [m]
  double vehicle_length = vehicle_defaults::kLength;  ///< [m]
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< [m/s] the ego's (the lane change's prepare segment)
  LaneChangeGaps gaps;           ///< the lane-change approval's target-lane margins
  double start_time = 0.0;       ///< [s] SUMO time of the run's first step (a pull out's engagement counts from it)
};

/// The behaviour modules' path of one step [m route s]: from 5 m behind base_link to
/// forward_path_length ahead of it (at most the route's end).
struct ModulePath {
  double front = 0.0;
  double back = 0.0;
};

/// The inputs of the four behaviour modules in one step, and the requests pointing at them.
struct ModuleInputs {
  ModuleInputs() = default;
  ModuleInputs(const ModuleInputs&) = delete;  // requests point into this object
  LaneChangeSignal::Input lane_change;
  AvoidanceSignal::Input avoidance;
  PullOutSignal::Input pull_out;
  PullOverSignal::Input pull_over;
  BehaviorRequests requests;
};

class BehaviorStage {
 public:
  BehaviorStage(LateralPlan plan, const BehaviorSignalParameters& params, const BehaviorStageConfig& config);

  struct Observation {
    double now = 0.0;
    EgoOnRoute ego;
    double accel = 0.0;     ///< [m/s^2] measured
    bool backing = false;   ///< emulated backward driving (pull out): not driving forward
    bool departed = false;  ///< the ego has moved (start planner has_departed)
    const LateralSegment* segment = nullptr;  ///< plan().on_edge(the ego's edge)
    double lateral_offset = 0.0;  ///< measured from segment->reference_lane's centre [m]
    /// The other vehicles on waiting_lane_change(ego.s_base)'s target lane, in route s.
    std::vector<OccupiedSpan> target_lane;
  };

  struct Transition {
    std::string edge;  ///< the lane change's edge
    LaneChangePhase from = LaneChangePhase::Pending;
    LaneChangePhase to = LaneChangePhase::Pending;
  };
  /// A module holds the ego: base_link must come to rest within `distance` [m].
  struct Hold {
    double distance = 0.0;
    const char* reason = "";  ///< what holds it ("the hold point of a lane change waiting for approval", ...)
    /// The same as the timeline's speed_limited_by says it: lane_change_hold, avoidance_hold, pull_out_wait.
    const char* kind = "";
  };
  struct Result {
    TurnSignalInfo behavior;               ///< the merged request for the decider
    std::vector<Transition> transitions;   ///< lane-change phase changes this step
    std::optional<Hold> hold;              ///< the nearest hold of this step, if any
  };

  /// The lane change whose target lane's traffic a step with base_link at `s_base` may need: the one
  /// the step runs, unless it is already running (its approval needs the traffic). nullptr: none.
  const LateralSegment* waiting_lane_change(double s_base) const;

  /// One step. observation.target_lane is read only while a lane change waits for approval.
  Result step(const Observation& observation);

  /// The offset `seg` plans for base_link at s (left positive, from its reference lane's centre).
  /// Backing up: the pull out's road-side offset. A lane change or an avoidance not yet approved:
  /// its original lane.
  double planned_offset(const LateralSegment& seg, double s, bool backing) const;

  const LateralPlan& plan() const { return plan_; }

  /// Every lane change of the plan as executed so far, in route order.
  std::vector<LaneChangeRecord> lane_change_records() const;

  /// The ego is engaged at `now` (planning/pull_out_departure.hpp); always without a pull out.
  bool engaged(double now) const { return departure_.engaged(now); }

 private:
  const LaneChangeExecution* execution_of(const LateralSegment& seg) const;
  /// The index of the lane change a step with base_link at `s_base` runs (the first not done whose
  /// earliest start lies within the module path), or the number of segments.
  std::size_t current_lane_change(double s_base) const;
  LaneChangeExecution::Step lane_change_step(const Observation& o) const;
  void add_lane_change(const LateralSegment& seg, LaneChangeExecution& execution, const LaneChangeExecution::Step& step,
                       const ModulePath& path, ModuleInputs& in) const;
  void advance_lane_change(std::size_t index, LaneChangeExecution::Step step, const Observation& o, Result& result);
  void run_avoidance(const LateralSegment& seg, const Observation& o, const ModulePath& path, ModuleInputs& in,
                     Result& result);
  void run_pull_out(const LateralSegment& seg, const Observation& o, const ModulePath& path, ModuleInputs& in,
                    Result& result);

  LateralPlan plan_;
  BehaviorSignalParameters params_;
  BehaviorStageConfig config_;
  BehaviorModules modules_;
  std::vector<LaneChangeExecution> executions_;  ///< one per segment (used by lane changes only)
  std::vector<AvoidanceExecution> avoidances_;   ///< one per segment (used by avoidances only)
  PullOutDeparture departure_;                   ///< the pull out's clock (engaged from the start without one)
};

/// The lateral motions the metrics measure, ordered by start: each lane change's executed line
/// (`executed` matched by edge; none for a lane change recorded without one, i.e. never approved; the
/// nominal line from the earliest start for a lane change `executed` does not list), and each
/// shift line of an avoidance, pull out or pull over moving at least `min_shift` metres sideways
/// (turn_signal_shift_length_threshold: smaller shifts never ask for a blinker, docs/behaviour.md §T8.1).
std::vector<ManeuverLine> maneuver_lines(const LateralPlan& plan, const std::vector<LaneChangeRecord>& executed,
                                         double min_shift);

}  // namespace signalsim
