// The stages of one step of a signalsim-driven run (step_loop.hpp has the algorithm, step_loop.cpp
// the loop): the values each stage hands to the next within a step, and StepLoop, which owns what
// lives from one step to the next (the stages with their own state, the ego's progress along the
// route, the record being filled) and runs one stage per member function.
//
// SUMO is reached through the session only: reads in observe, maneuver (a waiting lane change's
// target-lane traffic), light and record; writes in apply. The order of those calls within a step
// is part of the behaviour (it can change SUMO's results): keep it.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "planning/speed_limit_planner.hpp"
#include "planning/stop/stop_speed_planner.hpp"
#include "report/timeline.hpp"
#include "step/behavior_stage.hpp"
#include "step/light_outcomes.hpp"
#include "step/light_stage.hpp"
#include "step/plan_watch.hpp"
#include "sim/session_setup.hpp"
#include "step/step_record.hpp"
#include "step/stuck_watch.hpp"
#include "net/net_index.hpp"
#include "session/sumo_session.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim {

/// observe: SUMO's ego at the step's start, on the route and against the plans.
struct StepObservation {
  sumo::EgoState sumo;                      ///< as SUMO reports it
  EgoOnRoute ego;                           ///< s_front, s_base; speed signed (negative while backing up)
  bool backing = false;                     ///< emulated backward driving (pull out with `backward`)
  bool off_plan = false;                    ///< on a lane the lane plan does not list (PlanWatch)
  const LateralSegment* segment = nullptr;  ///< the lateral plan's segment on the ego's edge, if any
  double lateral_offset = 0.0;              ///< [m] from the segment's planned lane, else from SUMO's lane
};

/// maneuver: the behaviour modules' merged request, the lane changes' phase changes and hold point,
/// and where the lateral plan wants base_link sideways now.
struct StepManeuver {
  BehaviorStage::Result behavior;
  std::optional<double> planned_offset;  ///< [m] on a segment's edge only
};

/// decide: the blinker and the request it came from.
struct BlinkerChoice {
  Blinker blinker = Blinker::None;
  RequestSource source = RequestSource::None;
};

/// light: every light in the judges' window this step, nearest first.
struct StepLights {
  StepLights() = default;
  StepLights(StepLights&&) = default;
  StepLights(const StepLights&) = delete;  // stopping and shown point into steps

  std::vector<LightStep> steps;
  const LightStep* stopping = nullptr;  ///< the light the ego brakes for: the nearest stop requested
  const LightStep* shown = nullptr;     ///< the light the timeline row describes: stopping, else the nearest
  bool sumo_right_of_way = true;        ///< false while a light decides the next junction
};

/// plan: the speed commanded for the step, SUMO's modes for it, and what holds the ego.
struct SpeedPlan {
  double speed = 0.0;                   ///< [m/s] commanded (0 while backing up)
  std::optional<StopLevel> stop_level;  ///< the constraint set of the light's stop, if braking for one
  bool sumo_lane_limits = true;         ///< false while crossing a line passed on a stop signal
  bool emergency_braking = false;       ///< SUMO may brake beyond the ego's decel
  std::string held_by;                  ///< what of signalsim holds the ego at rest ("" when nothing)
  bool queued = false;                  ///< at rest in a queue before a light asking for a stop
};

class StepLoop {
 public:
  /// Builds the stages for a started run, then shifts the light programs by the scenario's
  /// light_offsets. Throws sumo::SumoError.
  StepLoop(const StartedRun& run, const sumo::NetIndex& net);
  StepLoop(const StepLoop&) = delete;  // pull_over_goal_ points into behavior_; lambdas capture this
  StepLoop& operator=(const StepLoop&) = delete;

  // One step, in this order. Each throws sumo::SumoError when SUMO fails.
  StepObservation observe();
  StepManeuver maneuver(const StepObservation& now);
  BlinkerChoice decide(const StepObservation& now, const StepManeuver& maneuver);
  StepLights light(const StepObservation& now);
  SpeedPlan plan_speed(const StepObservation& now, const StepManeuver& maneuver, const StepLights& lights);
  /// Returns false when the ego has arrived (SUMO's step removed it).
  bool apply(const StepObservation& now, const BlinkerChoice& blinker, const StepLights& lights,
             const SpeedPlan& plan);
  void record_step(const StepObservation& now, const StepManeuver& maneuver, const BlinkerChoice& blinker,
                   const StepLights& lights, const SpeedPlan& plan, bool alive);
  /// Whether the run is over after this step (record: arrived, or why not).
  bool ended(bool alive, const SpeedPlan& plan);

  /// The record, completed with what is known only at the end. Call once, after the last step.
  RunRecord finish();

 private:
  std::vector<OccupiedSpan> target_lane_traffic(const LateralSegment& seg) const;
  bool end_not_arrived(const std::string& reason);

  // The run as started.
  const Scenario& scenario_;
  const RouteMap& route_;
  const LateralPlan& lateral_;
  sumo::SumoSession& session_;
  const double b2f_;  // base_link_to_front [m]
  const double dt_;   // step length [s]
  const SpeedLimits limits_;
  const TrafficLightJudgeParameters judge_params_;

  // The stages, each with its own state.
  TurnSignalDecider decider_;   // the remembered desired starts
  BehaviorStage behavior_;      // the behaviour modules, the lane changes' phases
  TrafficLightStage lights_;    // one judge and perception model per light
  StopSpeedPlanner stop_speed_;
  const LateralSegment* pull_over_goal_ = nullptr;  // the plan's last pull over, if any
  LightOutcomes outcomes_;
  StuckWatch stuck_;
  PlanWatch plan_watch_;        // where SUMO leaves the lane plan
  StepEvents events_;
  LeaderQuery leader_;          // SUMO's leader of the ego (a queue before a light, not-arrived reasons)
  double end_time_ = 0.0;       // [s] SUMO time at which the run ends

  // The ego's progress.
  std::size_t hint_ = 0;        // the route lanelet it was on (the route position is monotonic)
  double last_s_;               // its last route position (held while off the route)
  bool departed_ = false;       // it has moved (start planner: has_departed)
  double backed_up_ = 0.0;      // [m] emulated backward driving done so far

  RunRecord record_;
};

}  // namespace signalsim
