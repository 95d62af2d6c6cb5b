// The lane plan of a route: one lane per route edge, chosen by a backward dynamic programme.
// Private to route_builder.cpp; pure (no net access), so it is easy to reason about.
#pragma once

#include <vector>

#include "sumo/net_index.hpp"

namespace signalsim::sumo {

struct LanePlan {
  std::vector<int> lanes;                      ///< lane index per edge the ego enters it on
  std::vector<int> exit_lanes;                 ///< planned lane per edge: the one it leaves on (the
                                               ///< connection's from-lane; last edge: see below)
  std::vector<const NetConnection*> links;     ///< per gap i (edge i -> i+1): the connection taken
  int lane_changes = 0;                        ///< total lane changes the plan needs
};

/// `usable[i][l]`: whether the ego may drive lane l of route edge i (lane permissions: a sidewalk
/// or bike lane is not usable). `links[i]`: the connections from edge i to edge i+1
/// (non-empty, size usable.size() - 1). Unusable lanes are never planned.
///
/// Cost of lane l on edge i followed by lane m on edge i+1: 0 when a connection l -> m exists, else
/// the fewest lane changes on edge i to a lane with a connection to m (|l - from|), else impossible.
/// cost_i(l) = min_m cost(l, m) + cost_{i+1}(m); the last edge costs 0. Ties: the lowest (rightmost)
/// lane. The connection taken in gap i is l -> m if it exists, else the one to m whose from-lane is
/// closest to l (ties: the rightmost). `lanes` is empty when no lane sequence exists.
///
/// `required_exit` (empty, or one entry per edge, -1 = free): a requested lane change on edge i to
/// lane r = required_exit[i]. The ego then leaves edge i on lane r (gap i uses a connection from r;
/// on the last edge it ends on r) and does not enter it on r (the change happens on edge i).
LanePlan plan_lanes(const std::vector<std::vector<bool>>& usable,
                    const std::vector<std::vector<const NetConnection*>>& links,
                    const std::vector<int>& required_exit = {});

}  // namespace signalsim::sumo
