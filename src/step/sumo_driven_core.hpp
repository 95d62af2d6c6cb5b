// The core of a SUMO-driven run (`signalsim run S --driver sumo`, docs/compare.md; run_core.hpp):
// SUMO drives the ego on its own and signalsim only observes, into the same RunRecord a
// signalsim-driven run fills, so that metrics and expectations measure both drivers with the same
// code. The ego is inserted exactly as for a signalsim-driven run (route, depart lane/pos/speed,
// vType, seed, traffic, light offsets: RunContext::sumo_drives), then nothing is commanded: no
// speed, signals, lane changes or speed mode (SUMO's defaults, docs/behaviour.md §S5).
//
//   each step until the ego arrives or the run's time is over (step_core.hpp run_end_time: `duration`
//   after departure, or the sumocfg's `end`):
//     observe  the ego's lane, lane position, speed and SUMO's signal mask, at the same moment
//     locate   route s of the front (map/route_locator, the rule both drivers use); steps off the
//              planned lanes are recorded (RunRecord::off_plan), steps off the route counted
//     blinker  SUMO's mask decoded: the hazard bit, or left and right together, is hazard; else left
//              or right; blinker_source "sumo"; sumo_signals is that same mask
//     lights   the nearest light not passed by more than 2 m: its id and the ego's link state
//     stop     the first step at rest (< 0.01 m/s) with the front on that light's approach lanelet
//              while its link shows r, u, y or Y: the rest position against the stop point the judge
//              would use (stop line - stop_margin, docs/behaviour.md §L9.2); a new stop only after moving again
//     red      the front crosses a stop line (+5 cm) during a step that began with its link r or u
#pragma once

#include <vector>

#include "core/blinker_signals.hpp"
#include "map/route_locator.hpp"
#include "report/timeline.hpp"
#include "route/approach_lights.hpp"
#include "scenario/scenario.hpp"
#include "step/run_core.hpp"
#include "step/step_core.hpp"
#include "step/step_record.hpp"

namespace signalsim {

/// Records stops and red crossings at every light of the route (in route order) as they happen.
class LightWatch {
 public:
  LightWatch(std::vector<sumo::ApproachLight> lights, const RouteMap& route, double stop_margin)
      : lights_(std::move(lights)), route_(route), stop_margin_(stop_margin), states_(lights_.size(), 0) {}
  /// The lights whose states a row at `s_front` reads.
  void demand(double s_front, ObservationDemand& want) const;
  /// One step: `row` is observed (s_front, speed, time); `seen` holds the states demand() asked for.
  void observe(const TimelineRow& row, const StepObservation& seen, RunRecord& record);
  /// The nearest light not left behind, or nullptr.
  const sumo::ApproachLight* nearest() const { return nearest_ < lights_.size() ? &lights_[nearest_] : nullptr; }
  char nearest_state() const { return nearest_ < lights_.size() ? states_[nearest_] : 0; }

 private:
  std::size_t nearest_after(double s_front) const;

  std::vector<sumo::ApproachLight> lights_;
  const RouteMap& route_;
  double stop_margin_;
  std::vector<char> states_;     // each light's link state at the last row it was followed
  std::size_t nearest_ = 0;      // lights before it are left behind
  double previous_front_ = 0.0;
  bool have_previous_ = false;
  bool resting_ = false;
};

class SumoDrivenCore final : public RunCore {
 public:
  explicit SumoDrivenCore(CoreSetup setup);

  ObservationDemand demand(const sumo::EgoState& ego) override;
  /// Commands nothing (Commands::drive false).
  Commands step(const StepObservation& seen) override;
  bool record(const StepObservation& seen, const StepFeedback& feedback) override;
  RunRecord finish(int collisions) override;

 private:
  const RouteMap& route_;
  const double end_time_;
  LightWatch lights_;
  RouteLocator locator_;
  RouteLocator::Place place_;
  bool previous_off_plan_ = false;
  StepEvents events_;
  RunRecord record_;
};

}  // namespace signalsim
