// summary.json's "decider" and "light_judge" objects (docs/outputs.md): with a system under test
// (docs/decider.md), how often its decisions agreed with the reference run in shadow, and, per signal
// section, where each of them had the section's blinker on and off. Computed from the run's rows alone
// (timeline.csv's blinker / ref_blinker and tl_decision / ref_tl_decision columns), so the same from
// a run directory read back. Without a SUT of the role the object is absent (null from these functions).
//
//   agreement  agreeing rows / compared rows, rounded half away from zero to 4 decimals (1e-4); null
//              when no row was compared
//   sections   measure_sections (section_metrics.hpp) run twice on the same sections: once on the
//              rows' blinker (the SUT's), once with each row's blinker replaced by ref_blinker
#pragma once

#include <nlohmann/json.hpp>

#include "map/route_map.hpp"
#include "report/timeline.hpp"
#include "scenario/scenario.hpp"

namespace signalsim {

/// "decider": {name, agreement, steps, agreeing_steps, sections: [{kind, id, blinker, s_start, s_end,
/// sut: {on_s, off_s, lead_distance, missed}, reference: {...}}]}; null without a decider under test.
nlohmann::ordered_json decider_agreement_json(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

/// "light_judge": {name, agreement, steps, agreeing_steps, lights: [{id, steps, agreeing_steps, sut:
/// [decisions], reference: [decisions]}]}; null without a light judge under test. A light's decision
/// lists are the judge's decisions for it in the order they followed each other (repeats collapsed).
nlohmann::ordered_json light_judge_agreement_json(const RunRecord& record);

}  // namespace signalsim
