// Backward length of the path P while the ego is in a roundabout (docs/behaviour.md §T5.4).
#pragma once

#include <cstddef>
#include <map>

#include "map/route_map.hpp"

namespace signalsim {

/// docs/behaviour.md §T5.4: the back length of P to use instead of `default_backward_length`, so that the entry
/// whose desired start is stored stays on P while the ego drives round the roundabout.
///
/// If the ego's closest lanelet `current_index` (the one containing s_base) is an Internal or Exit
/// lanelet of a roundabout, a depth-first search runs backward over route predecessors from it:
///   - a node's accumulated length includes its own full length;
///   - nodes at depth >= `max_depth` are not expanded (depth 0 = the current lanelet; a negative
///     `max_depth` is unlimited);
///   - an Entry predecessor of the same roundabout with a stored desired start records the route
///     lanelet containing that stored s;
///   - a recorded lanelet met later as a predecessor gives a candidate: accumulated length + its length.
/// Returns max(default_backward_length, largest candidate); `default_backward_length` otherwise.
/// Quirk kept from the reference: a stored start inside the entry itself adds nothing (the entry was
/// already visited).
///
/// `desired_starts` are RoundaboutRequests::desired_starts() (route index -> s). signalsim's route is
/// a line, so a lanelet's only route predecessor is the previous route lanelet: the search is the
/// reference's DFS run on that line (visited set by route index). Lengths are the lanelets' route
/// lengths (SUMO lane lengths, the unit of s), not their 2-D shape lengths. Never throws.
double roundabout_backward_length(const RouteMap& route, std::size_t current_index, double default_backward_length,
                                  int max_depth, const std::map<std::size_t, double>& desired_starts);

}  // namespace signalsim
