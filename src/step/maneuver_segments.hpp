// The lateral segments of the maneuvers a scenario declares beside its lane changes: an avoidance,
// the pull out and the pull over (docs/maneuvers.md), each planned on one route edge and checked
// before SUMO starts. plan_lateral (route_planning.hpp) puts them together with the lane changes.
#pragma once

#include <cstddef>

#include "route/route_builder.hpp"
#include "scenario/scenario.hpp"
#include "step/route_planning.hpp"

namespace signalsim {

/// The avoidance of `scenario.avoids[index]`: shift out, hold, shift back past its obstacle, with its
/// wait point and approval delay (docs/behaviour.md §T8.2 "Avoidance"). Throws InputError for an unknown
/// obstacle, one off the ego's route or planned lane, or a plan that leaves the obstacle's edge.
LateralSegment avoid_segment(const Scenario& scenario, const sumo::RoutePlan& plan, const AvoidManeuver& avoid,
                             std::size_t index);

/// The pull out of `scenario.pull_out` on the first edge. Throws InputError (with the maneuver's line)
/// for a back-up off the edge's start or without enable_back, a back-up or a wait at the start
/// (engage_delay, prepare_time_before_start) from a moving start, or a plan that leaves the edge.
LateralSegment pull_out_segment(const Scenario& scenario, const sumo::RoutePlan& plan);

/// The pull over of `scenario.pull_over`. Throws InputError for a goal edge off the route or a plan
/// that leaves the edge.
LateralSegment pull_over_segment(const Scenario& scenario, const sumo::RoutePlan& plan);

}  // namespace signalsim
