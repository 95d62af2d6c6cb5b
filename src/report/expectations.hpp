// Checking a scenario's expectations against what the run recorded.
#pragma once

#include <vector>

#include "map/route_map.hpp"
#include "scenario/scenario.hpp"
#include "report/timeline.hpp"

namespace signalsim {

/// Throws InputError (naming the scenario file) when an expectation names a junction or lanelet
/// that is not on the route. Call before running, so bad input never costs a simulation.
void check_expectations_apply(const Scenario& scenario, const RouteMap& route);

/// One result per expectation, in file order, then one failed result per lane change the run
/// missed (LaneChangeRecord phase "missed"), then a failed "ego arrives (not stuck)" when the stuck
/// rule ended the run (RunRecord::not_arrived reason "stuck").
std::vector<ExpectationResult> evaluate_expectations(const Scenario& scenario, const RouteMap& route,
                                                     const RunRecord& record);

}  // namespace signalsim
