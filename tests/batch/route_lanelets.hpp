// Lanelets of a hand-made route for the tests of a run's report (comparison, metrics, the SUT's
// columns): a lane id, where it starts on the route and how long it is, its turn and junction.
#pragma once

#include <string>

#include "map/route_map.hpp"

namespace signalsim::test {

inline Lanelet lanelet(const std::string& lane, double s_start, double length, TurnDirection turn = TurnDirection::None,
                       const std::string& junction = "", RoundaboutRole role = RoundaboutRole::None) {
  Lanelet l;
  l.lane_id = lane;
  l.edge_id = lane.substr(0, lane.rfind('_'));
  l.junction_id = junction;
  l.is_internal = !junction.empty();
  l.s_start = s_start;
  l.length = length;
  l.turn_direction = turn;
  l.roundabout_role = role;
  if (role != RoundaboutRole::None) l.roundabout_id = "0";
  return l;
}

}  // namespace signalsim::test
