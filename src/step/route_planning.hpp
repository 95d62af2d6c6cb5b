// The ego's route for a scenario: built from the net once, then prepared with the options that
// change lanelet attributes (docs/behaviour.md §T5.3 exit-signal marking, Japan).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "planning/avoidance_execution.hpp"
#include "planning/lane_change_execution.hpp"
#include "planning/shift_line.hpp"
#include "scenario/scenario.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"

namespace signalsim {

/// Builds the route of `scenario.ego.route` and, when the parameter
/// `turn_signal_roundabout_exit_signal_from_previous_exit` is true, marks the ring lanes from the
/// previous exit as `enable_exit_turn_signal`. Throws InputError (naming the scenario file and
/// `ego.route`) for a route the net cannot drive.
sumo::RoutePlan plan_route(const Scenario& scenario, const sumo::NetIndex& net);

/// The lateral plan of a scenario (docs/maneuvers.md, docs/behaviour.md §S4), one segment per maneuver, each driven on
/// one route edge: the lane change from ego.depart_lane onto the first edge's planned lane (the lane
/// with the connection to the next edge), and the avoidance of declared obstacles. Shift lines are on
/// base_link's route s; offsets are lateral, left positive, from the centre of the segment's
/// `reference_lane` (the edge's planned lane).
enum class LateralKind { LaneChange, Avoidance, PullOut, PullOver };
struct LateralSegment {
  LateralKind kind = LateralKind::LaneChange;
  std::string edge;            ///< the edge the plan is driven on
  std::string reference_lane;  ///< its planned lane: offsets are measured from its centre
  /// The lateral plan; for a lane change the nominal one (lateral motion from its earliest start),
  /// the executed line is decided at approval (lane_change).
  ShiftPlan plan;
  LaneChangeTiming lane_change;  ///< lane change only
  AvoidanceTiming avoidance;     ///< avoidance only: its wait point and approval delay
  /// Lane change: lateral position of the lane boundary the ego crosses (the adjacent lane's boundary) [m].
  double boundary = 0.0;
  double left_half_width = 1.6;   ///< of the reference lane [m] (lane-bound test)
  double right_half_width = 1.6;
  std::uint64_t first_line_id = 0;  ///< ids of the lines: first_line_id + index
  std::size_t route_index = 0;      ///< the edge's lanelet on the route
  double goal_s = 0.0;              ///< pull over: base_link's route s at the goal stop [m]
};
struct LateralPlan {
  std::vector<LateralSegment> segments;  ///< ordered along the route, at most one per edge
  bool active() const { return !segments.empty(); }
  /// Pull out: the lateral offset the ego departs with (SUMO departPosLat), 0 otherwise.
  double depart_offset = 0.0;
  /// Pull out: metres the ego backs up (emulated) before it pulls out.
  double backward = 0.0;
  /// Pull out: [s] after the run's first step the ego is engaged (pull_out.engage_delay).
  double engage_delay = 0.0;
  const LateralSegment* on_edge(const std::string& edge) const {
    for (const LateralSegment& seg : segments)
      if (seg.edge == edge) return &seg;
    return nullptr;
  }
};

/// Throws InputError (naming ego.depart_lane or maneuvers) for a depart lane the edge does not have
/// or the ego may not use, a lane change without a lane to change to, an obstacle off the route's
/// planned lanes, an avoidance of an unknown obstacle, or a shift that does not start and end while
/// the ego is on the segment's edge (no lateral command on internal lanes).
LateralPlan plan_lateral(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net);

/// Per route edge, the lane a requested lane change (maneuvers: lane_change with `edge`) ends on,
/// -1 elsewhere; empty without one (sumo::build_route's required_exit).
std::vector<int> required_exit_lanes(const Scenario& scenario);

/// What limits the ego's lane changes (route/lane_change_room.hpp): base_link_to_front, depart_pos,
/// max_speed, and its grip, ego.emergency_decel.
sumo::LaneChangeEgo lane_change_ego(const Scenario& scenario);

/// sumo::build_route for the scenario's route, requested lane changes and ego (no preparation, no
/// checks: plan_route does both). The one way a scenario's lane plan is made.
sumo::RoutePlan build_scenario_route(const Scenario& scenario, const sumo::NetIndex& net);

/// "no lane plan leaves room for every lane change ...; the best one changes lanes on edge 'x'
/// (lane 0 -> 1, a 3.20 m shift, 0.54 m of room; at 13.89 m/s it needs 19.90 m of lateral motion,
/// so 26.13 m of room)": the edges of a plan's lane changes with their room.
std::string no_room_message(const sumo::RoutePlan& plan);

/// The same preparation for a route built elsewhere (inspect).
sumo::RoutePlan prepare_route(sumo::RoutePlan plan, const TurnSignalParameters& params);

}  // namespace signalsim
