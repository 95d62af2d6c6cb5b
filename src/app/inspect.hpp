// `signalsim inspect`: what the decider will see on a net and a route.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "sumo/net_index.hpp"

namespace signalsim {

/// Net summary (edges, lights, roundabouts, driving side); with a route, one line per lanelet.
/// Throws sumo::RouteError for a bad route.
void print_inspection(std::ostream& out, const sumo::NetIndex& net, const std::vector<std::string>& route);

}  // namespace signalsim
