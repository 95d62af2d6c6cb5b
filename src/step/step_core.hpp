// The core of a signalsim-driven run (run_core.hpp): the stages of one step between SUMO's ports,
// and what lives from one step to the next (the stages with their own state, the ego's progress
// along the route, the record being filled). It reads SUMO only through the StepObservation it
// asked for and writes only the Commands it returns: no session.
//
//   demand    locate the ego's front on the route (map/route_locator); ask for the offset from the
//             lateral plan's lane on the ego's edge, a waiting lane change's target-lane traffic,
//             the lights of the window (light_stage), and SUMO's leader when this row may need it
//             (a stop may begin, the stuck rule or the end may end the run: the leader at the row;
//             SUMO executed less than the last command: the leader explains that row)
//   step      observe (the ego against the plans) -> maneuver -> decide -> light -> plan -> Commands
//   record    the row with the mask SUMO showed while executing the commands; events on change;
//             stops and red crossings; the end: arrived, stuck or out of time
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "map/route_locator.hpp"
#include "report/timeline.hpp"
#include "route/approach_lights.hpp"
#include "scenario/scenario.hpp"
#include "step/behavior_stage.hpp"
#include "step/light_outcomes.hpp"
#include "step/light_stage.hpp"
#include "step/plan_watch.hpp"
#include "step/speed_stage.hpp"
#include "step/run_core.hpp"
#include "step/step_record.hpp"
#include "step/stuck_watch.hpp"
#include "sut/system_under_test.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim {

/// What a core is built from: the run as SUMO started it, without SUMO.
struct CoreSetup {
  const Scenario& scenario;                   ///< as run (a taken-over vehicle's type filled in)
  const RouteMap& route;                      ///< the route as driven
  const LateralPlan& lateral;
  std::vector<sumo::ApproachLight> lights;    ///< the route's lights, has_arrow from SUMO's programs
  RunSumoInfo sumo;                           ///< the record's `sumo` fields
  double start_time = 0.0;                    ///< [s] SUMO's time at the first step
  /// The decider and light judge under test, if any (docs/decider.md): they decide, signalsim's own
  /// run in shadow as the reference.
  SystemsUnderTest suts;
};

/// [s] SUMO time at which a run started at `start_time` ends: `duration` after the ego's departure
/// or the sumocfg's `end`, whichever comes first (docs/sumo.md).
double run_end_time(const Scenario& scenario, double start_time);

// The values StepCore's stages hand to each other within one step (namespace scope: a nested struct
// with default member initializers is not default-constructible inside its class for clang).

/// observe: the ego against the route and the plans, as demand() located it.
struct StepNow {
  sumo::EgoState sumo;                      ///< as SUMO reports it
  EgoOnRoute ego;                           ///< s_front, s_base; speed signed (negative while backing up)
  bool backing = false;                     ///< a pull out's back-up is still to drive (not driving forward)
  bool moving_back = false;                 ///< backing and engaged: the back-up moves the ego this step
  bool off_plan = false;                    ///< on a lane the lane plan does not list (PlanWatch)
  const LateralSegment* segment = nullptr;  ///< the lateral plan's segment on the ego's edge, if any
  double lateral_offset = 0.0;              ///< [m] from the segment's planned lane, else from SUMO's lane
};

/// decide: the blinker and the request it came from.
struct BlinkerChoice {
  Blinker blinker = Blinker::None;
  RequestSource source = RequestSource::None;
};

/// light: every light in the judges' window this step, nearest first.
struct StepLights {
  std::vector<LightStep> steps;
  const LightStep* stopping = nullptr;  ///< the light the ego brakes for: the nearest stop requested
  const LightStep* shown = nullptr;     ///< the light the row describes: stopping, else the nearest
  bool sumo_right_of_way = true;        ///< false while a light decides the next junction
};

/// Sets `stopping` (the nearest stop requested, if any) and `shown` (that light, else the nearest).
void choose_stopping_and_shown(StepLights& lights);

/// A step of StepCore between step() and record().
struct PendingStep {
  StepNow now;
  BehaviorStage::Result behavior;
  std::optional<double> planned_offset;  ///< [m] on a segment's edge only
  BlinkerChoice blinker;           ///< commanded: the decider under test's, else the reference's
  std::optional<BlinkerChoice> reference;  ///< the reference's, when a decider under test decides
  StepLights lights;
  SpeedPlan plan;
};

class StepCore final : public RunCore {
 public:
  explicit StepCore(CoreSetup setup);
  StepCore(const StepCore&) = delete;  // the speed stage and the pending step point into members
  StepCore& operator=(const StepCore&) = delete;

  ObservationDemand demand(const sumo::EgoState& ego) override;
  Commands step(const StepObservation& seen) override;
  bool record(const StepObservation& seen, const StepFeedback& feedback) override;
  RunRecord finish(int collisions) override;

 private:
  bool backing() const;
  double row_speed_of(double sumo_speed, double time) const;
  StepNow observe(const StepObservation& seen);
  bool fell_short(double sumo_speed) const;
  void explain_previous_row(const StepObservation& seen);
  std::vector<OccupiedSpan> target_lane_traffic(const StepObservation& seen, double s_base) const;
  StepLights light(const StepNow& now, const StepObservation& seen);
  Commands commands(const PendingStep& step);
  SutStep sut_step(const StepNow& now, const StepObservation& seen, const TurnSignalInfo& request,
                   double path_backward_length) const;
  void judge_under_test(SutStep& in, StepLights& lights);
  bool ended(const StepObservation& seen, const StepFeedback& feedback, const SpeedPlan& plan);
  bool end_not_arrived(const std::string& reason, const std::optional<LeaderInfo>& leader);

  // The run as started.
  const Scenario& scenario_;
  const RouteMap& route_;
  const LateralPlan& lateral_;
  const double b2f_;  // base_link_to_front [m]
  const double dt_;   // step length [s]
  const TrafficLightJudgeParameters judge_params_;
  const double end_time_;  // [s] SUMO time at which the run ends

  // The stages, each with its own state.
  TurnSignalDecider decider_;   // the remembered desired starts
  BehaviorStage behavior_;      // the behaviour modules, the lane changes' phases
  TrafficLightStage lights_;    // one judge and perception model per light
  LightOutcomes outcomes_;
  StuckWatch stuck_;
  PlanWatch plan_watch_;        // where SUMO leaves the lane plan
  StepEvents events_;

  // The ego's progress.
  RouteLocator locator_;
  RouteLocator::Place place_;   // where demand() located the front this step
  bool departed_ = false;       // it has moved (start planner: has_departed)
  double backed_up_ = 0.0;      // [m] emulated backward driving done so far

  std::optional<PendingStep> pending_;
  RunRecord record_;
  SystemsUnderTest suts_;
  SpeedStage speed_;            // after behavior_: the pull-over goal is its plan's
};

}  // namespace signalsim
