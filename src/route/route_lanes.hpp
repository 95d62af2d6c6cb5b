// The lane plan of a route on a net: the inputs of plan_lanes (lane permissions, connections, the
// room of every edge) from the NetIndex, and the refusals when no lane sequence exists. Private to
// route_builder.cpp.
#pragma once

#include <string>
#include <vector>

#include "route/lane_change_room.hpp"
#include "route/lane_plan.hpp"
#include "net/net_index.hpp"

namespace signalsim::sumo {

struct RouteLanes {
  LanePlan plan;
  std::vector<EdgeRoom> rooms;              ///< per route edge
  std::vector<PlannedLaneChange> changes;   ///< the plan's lateral motions, in route order
};

/// Throws RouteError: consecutive edges not connected; no lane sequence, naming the edge and the
/// lane a passenger car may not use when every sequence would cross one (SUMO keeps a vehicle off
/// a lane its class may not use, so no lane change can cross it).
RouteLanes plan_route_lanes(const NetIndex& net, const std::vector<const NetEdge*>& route,
                            const std::vector<int>& required_exit, const LaneChangeEgo& ego);

}  // namespace signalsim::sumo
