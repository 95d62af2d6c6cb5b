// The walk graph of a net, from the NetIndex (passenger lanes, internal links, no U-turns).
#include "generate/net_graph.hpp"

#include <algorithm>
#include <unordered_map>

namespace signalsim::generate {
namespace {

bool drivable(const sumo::NetIndex& net, const sumo::NetEdge& edge) {
  if (edge.is_internal || edge.id.empty() || edge.id.front() == ':') return false;
  if (!sumo::sumo_cannot_drive(net, edge).empty()) return false;  // SUMO 1.15 aborts there
  return std::any_of(edge.lanes.begin(), edge.lanes.end(), [](const sumo::NetLane& l) { return l.allows_passenger; });
}

bool usable_turn(char dir) { return dir == 's' || dir == 'l' || dir == 'r' || dir == 'L' || dir == 'R'; }

}  // namespace

RouteGraph graph_of_net(const sumo::NetIndex& net) {
  std::vector<GraphEdge> edges;
  std::unordered_map<std::string, std::size_t> index;  // lookups only; the graph sorts by id
  for (const sumo::NetEdge& e : net.edges()) {
    if (!drivable(net, e)) continue;
    double length = 0.0;
    for (const sumo::NetLane& l : e.lanes)
      if (l.allows_passenger) length = std::max(length, l.length);
    index.emplace(e.id, edges.size());
    edges.push_back({e.id, e.from_junction, e.to_junction, length});
  }
  std::vector<std::vector<GraphLink>> links(edges.size());
  for (const sumo::NetEdge& e : net.edges()) {
    const auto from = index.find(e.id);
    if (from == index.end()) continue;
    for (const sumo::NetLane& lane : e.lanes) {
      if (!lane.allows_passenger) continue;
      for (const sumo::NetConnection& c : net.connections_from_lane(lane.id)) {
        if (c.via.empty() || !usable_turn(c.dir)) continue;
        const auto to = index.find(c.to_edge);
        if (to == index.end()) continue;
        const sumo::NetEdge* target = net.edge(c.to_edge);
        if (c.to_lane < 0 || static_cast<std::size_t>(c.to_lane) >= target->lanes.size() ||
            !target->lanes[static_cast<std::size_t>(c.to_lane)].allows_passenger)
          continue;
        const sumo::NetLane* via = net.lane(c.via);
        links[from->second].push_back({to->second, via ? via->length : 0.0});
      }
    }
  }
  return RouteGraph(std::move(edges), std::move(links));
}

}  // namespace signalsim::generate
