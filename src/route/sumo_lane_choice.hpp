// Which lane of the next route edge SUMO drives a vehicle onto from each lane of a route edge.
//
// When a lane has several connections to the next route edge (bologna_acosta: 85_1 -> 72[0] via
// :9_12_1 to 72[0]_1 and via :9_12_2 to 72[0]_2), SUMO does not choose at random and does not
// follow signalsim's lane plan: MSLane::succLinkSec takes the link whose to-lane is the next lane of
// the vehicle's "best continuation" (MSVehicle::getBestLanesContinuation), and that comes from
// MSVehicle::updateBestLanes, computed when the vehicle enters the edge:
//   - look-ahead: the route edges from the current one while (seen <= 4 or seen length < max(B,
//     3000 m)) and (seen <= 8 or seen length < max(B, 200 m)), B = the current lane's length +
//     tau v_max + brake gap(v_max) + minGap;
//   - on the last edge looked at, every lane the class may use has its length (else 0); lanes off
//     the best ones get an offset to the nearest best lane;
//   - backwards, each lane adds the length of its best connected next lane (the longest one it has
//     a link to, then the least |offset|, then the first, i.e. the rightmost), or the edge's best
//     length when that lane is as good as the best connected one and within one lane change;
//     a lane whose next link has lower priority than the best lane's keeps only its own length.
// The lane plan (route_lanes.cpp) keeps, per lane, only the connection SUMO will take, so the plan
// and SUMO agree (signalsim turns SUMO's lane changes off for the ego). Not modelled: stops and
// waypoints, an arrival lane, changeLeft/changeRight prohibitions, the live state of a light's link
// (a signalised link counts as a priority link), bidi lanes and the elecHybrid device.
// Read from SUMO's MSVehicle.cpp (updateBestLanes, nextLinkPriority) and MSLane.cpp (succLinkSec).
#pragma once

#include <string>
#include <vector>

#include "core/vehicle_defaults.hpp"
#include "net/net_index.hpp"

namespace signalsim::sumo {

/// What SUMO's look-ahead depends on (MSCFModel defaults for tau and minGap).
struct SumoLookahead {
  std::string vclass = "passenger";
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< [m/s] the vehicle's
  double decel = vehicle_defaults::kSumoDecel;  ///< [m/s^2] its vType's decel
  double tau = 1.0;           ///< [s]
  double min_gap = 2.5;       ///< [m]
  double step_length = 0.1;   ///< [s]
};

/// Per route gap i (edge i -> edge i+1), per lane index l of edge i: the lane index on edge i+1
/// SUMO drives onto from lane l, or -1 when SUMO has no continuation from l (it would stop at its
/// end). Size route.size() - 1.
std::vector<std::vector<int>> sumo_next_lanes(const NetIndex& net, const std::vector<const NetEdge*>& route,
                                              const SumoLookahead& vehicle);

}  // namespace signalsim::sumo
