// `signalsim inspect`: what the decider will see on a net and a route.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "net/net_index.hpp"
#include "route/route_builder.hpp"

namespace signalsim {

/// Net summary (edges, lights, roundabouts, driving side).
void print_net_summary(std::ostream& out, const sumo::NetIndex& net);

/// One line per lanelet of a planned route: s range, turn direction, roundabout role, light, params
/// (including `enable_exit_turn_signal` where the exit-signal marking set it).
void print_route(std::ostream& out, const sumo::RoutePlan& plan);

}  // namespace signalsim
