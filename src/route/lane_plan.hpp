// The lane plan of a route: one lane per route edge, chosen by a backward dynamic programme.
// Private to route_builder.cpp; pure (no net access), so it is easy to reason about.
#pragma once

#include <limits>
#include <vector>

#include "route/lane_change_room.hpp"
#include "net/net_index.hpp"

namespace signalsim::sumo {

struct LanePlan {
  std::vector<int> lanes;                      ///< lane index per edge the ego enters it on
  std::vector<int> exit_lanes;                 ///< planned lane per edge: the one it leaves on (the
                                               ///< connection's from-lane; last edge: see below)
  std::vector<const NetConnection*> links;     ///< per gap i (edge i -> i+1): the connection taken
  int lane_changes = 0;                        ///< total lane changes the plan needs
  int unfit = 0;                               ///< of its lane changes (edges), those that do not fit
  /// The least room of its lane changes [m]; infinity without any.
  double tightest_room = std::numeric_limits<double>::infinity();
};

/// `usable[i][l]`: whether the ego may drive lane l of route edge i (lane permissions: a sidewalk
/// or bus lane is not usable). `links[i]`: the connections from edge i to edge i+1
/// (non-empty, size usable.size() - 1). Unusable lanes are never planned, entered, left or crossed:
/// a lane change across one is impossible (another lane sequence is taken; `cross_unusable` allows
/// it, to diagnose a route that has no other).
///
/// On edge i the ego enters on lane l and takes a connection c to lane m of edge i+1; it changes
/// lanes on edge i from l to c's from-lane (|l - from| lane changes, one lateral motion). A plan is
/// better when (in this order):
///   1. fewer of its lane changes do not fit their edge (`rooms`: lane_change_fits, the lateral
///      planner's own rule; without `rooms` every one fits),
///   2. it has fewer lane changes,
///   3. its tightest lane change (least room) has more room,
///   4. ties: at each edge the lowest next lane m, then the connection whose from-lane is closest to
///      l (then the rightmost); on the first edge the lowest lane (the rightmost plan).
/// With `ego.first_lane` (the lane a taken-over vehicle departed on) the plan starts on that lane
/// whenever the route can be driven from it, however it ranks.
/// Each criterion is monotone along the route, so the backward programme finds the best plan.
/// `lanes` is empty when no lane sequence exists.
///
/// `required_exit` (empty, or one entry per edge, -1 = free): a requested lane change on edge i to
/// lane r = required_exit[i]. The ego then leaves edge i on lane r (gap i uses a connection from r;
/// on the last edge it ends on r) and does not enter it on r (the change happens on edge i).
LanePlan plan_lanes(const std::vector<std::vector<bool>>& usable,
                    const std::vector<std::vector<const NetConnection*>>& links,
                    const std::vector<int>& required_exit = {}, const std::vector<EdgeRoom>& rooms = {},
                    const LaneChangeEgo& ego = {}, bool cross_unusable = false);

}  // namespace signalsim::sumo
