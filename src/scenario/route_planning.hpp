// The ego's route for a scenario: built from the net once, then prepared with the options that
// change lanelet attributes (spec TSD §5.3 exit-signal marking, Japan).
#pragma once

#include "planning/shift_line.hpp"
#include "scenario/scenario.hpp"
#include "sumo/net_index.hpp"
#include "sumo/route_builder.hpp"

namespace signalsim {

/// Builds the route of `scenario.ego.route` and, when the parameter
/// `turn_signal_roundabout_exit_signal_from_previous_exit` is true, marks the ring lanes from the
/// previous exit as `enable_exit_turn_signal`. Throws InputError (naming the scenario file and
/// `ego.route`) for a route the net cannot drive.
sumo::RoutePlan plan_route(const Scenario& scenario, const sumo::NetIndex& net);

/// The lateral plan of a scenario (issue 5, spec SUMO §4): the lane change from ego.depart_lane onto
/// the first edge's planned lane (the lane with the connection to the next edge), one shift line on
/// base_link's route s from the depart lane's offset to 0. Offsets are lateral, left positive, from
/// the centre of `reference_lane`. Empty plan when the ego departs on the planned lane.
struct LateralPlan {
  std::string edge;            ///< the edge the plan is driven on (the route's first edge)
  std::string reference_lane;  ///< its planned lane: offsets are measured from its centre
  ShiftPlan plan;
  /// Lateral position of the lane boundary the ego crosses (the adjacent lane's boundary) [m].
  double boundary = 0.0;
  bool active() const { return !plan.empty(); }
};

/// Throws InputError (naming ego.depart_lane or maneuvers) for a depart lane the edge does not have
/// or the ego may not use, a lane change without a lane to change to, or one that does not end
/// while the front bumper is still on the first edge.
LateralPlan plan_lateral(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net);

/// The same preparation for a route built elsewhere (inspect).
sumo::RoutePlan prepare_route(sumo::RoutePlan plan, const ParameterSet& params);

}  // namespace signalsim
