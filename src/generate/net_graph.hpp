// The generator's walk graph of a net (route_graph.hpp), indexed once from the NetIndex: every
// normal edge with a lane a passenger car may use (and that SUMO 1.15 can drive: not a multi-lane bidi
// edge, sumo::sumo_cannot_drive), and between two of them every connection from
// such a lane to such a lane that has an internal lane (build_route needs it) and is not a U-turn
// (dir t/T) or invalid. The edge's length is its longest such lane; a link's is the connection's
// first internal lane.
#pragma once

#include "generate/route_graph.hpp"
#include "net/net_index.hpp"

namespace signalsim::generate {

RouteGraph graph_of_net(const sumo::NetIndex& net);

}  // namespace signalsim::generate
