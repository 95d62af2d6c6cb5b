// The ego's route for a scenario: built from the net once, then prepared with the options that
// change lanelet attributes (spec TSD §5.3 exit-signal marking, Japan).
#pragma once

#include "scenario/scenario.hpp"
#include "sumo/net_index.hpp"
#include "sumo/route_builder.hpp"

namespace signalsim {

/// Builds the route of `scenario.ego.route` and, when the parameter
/// `turn_signal_roundabout_exit_signal_from_previous_exit` is true, marks the ring lanes from the
/// previous exit as `enable_exit_turn_signal`. Throws InputError (naming the scenario file and
/// `ego.route`) for a route the net cannot drive.
sumo::RoutePlan plan_route(const Scenario& scenario, const sumo::NetIndex& net);

/// The same preparation for a route built elsewhere (inspect).
sumo::RoutePlan prepare_route(sumo::RoutePlan plan, const ParameterSet& params);

}  // namespace signalsim
