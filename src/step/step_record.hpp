// What a signalsim-driven run writes into its RunRecord, besides the lights' outcomes
// (light_outcomes.hpp): the run's SUMO fields, set once before the first step; each step's timeline
// row; the events, on the step a value changes (events.csv); and the light log, every light in the
// judges' window at every step. No SUMO calls here: the step loop hands in what SUMO said.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "report/timeline.hpp"
#include "step/behavior_stage.hpp"
#include "step/light_stage.hpp"
#include "route/approach_lights.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {

/// One step's timeline row as far as signalsim knows it: SUMO's observation at the step's start
/// (`observed`), the ego's route position and signed speed (`ego`), the measured and planned lateral
/// offsets, the blinker with the request it came from, and the light the row shows (`shown`, none:
/// no light columns) with its judge's columns when judged (`stop_level` then too). The caller adds
/// sumo_signals and, when no light is shown, show_next_light.
TimelineRow timeline_row(const sumo::EgoState& observed, const EgoOnRoute& ego, double lateral_offset,
                         std::optional<double> planned_offset, Blinker blinker, RequestSource source,
                         const LightStep* shown, std::optional<StopLevel> stop_level);

/// A row that shows no light in the judges' window shows the next light beyond it: its id and the
/// ego's link in `state`, SUMO's state string of that light (nothing when the link is out of range).
void show_next_light(TimelineRow& row, const sumo::ApproachLight& next, const std::string& state);

/// Every light in the window this step, each its own entry whichever the row shows. Call it before
/// the row is appended to record.rows (the entries name the row by its index).
void log_lights(const std::vector<LightStep>& lights, RunRecord& record);

/// The events of a run, each written on the step its value changes: the blinker, the lane changes'
/// phases, the decision for the light shown, and with V2I on (record.v2i) whether its rule holds.
class StepEvents {
 public:
  /// One step's row and the lane changes' phase changes in it; appends to record.events.
  void record(const TimelineRow& row, const std::vector<BehaviorStage::Transition>& transitions, RunRecord& record);

 private:
  Blinker blinker_ = Blinker::None;
  JudgeDecision decision_ = JudgeDecision::None;
  bool v2i_stop_ = false;
};

}  // namespace signalsim
