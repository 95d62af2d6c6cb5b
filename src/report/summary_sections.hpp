// summary.json's sections of what a run did, from its record alone; report/outputs puts them
// together with the scenario's sections. Numbers are rounded as the files write them (as_written).
#pragma once

#include <nlohmann/json.hpp>

#include "report/timeline.hpp"

namespace signalsim {

/// [s] The span a run simulated: its last row's time less SUMO's begin (a sumocfg's `begin`, else 0):
/// SUMO's clock at the end less where it started, not the clock itself.
double simulated_span(const RunRecord& record, double begin);

/// "counts": steps, the simulated span (simulated_span) and SUMO's clock at the end (end_time),
/// arrival, collisions, steps off the route and off the plan, blinker and light events, steps per
/// blinker, steps where SUMO's signals differed from the blinker.
nlohmann::ordered_json counts_json(const RunRecord& record, double begin);

/// "not_arrived": why the ego did not arrive (step/stuck_watch), null when it did.
nlohmann::ordered_json not_arrived_json(const RunRecord& record);

/// "off_plan": the stretches where SUMO left the lane plan.
nlohmann::ordered_json off_plan_json(const RunRecord& record);

/// "lights": the stops at lights, red-light violations, emergency stops and, only with V2I on, "v2i".
nlohmann::ordered_json lights_json(const RunRecord& record);

/// "lane_changes": each lane change as executed (blinker, approval, prepare, lateral motion).
nlohmann::ordered_json lane_changes_json(const RunRecord& record);

}  // namespace signalsim
