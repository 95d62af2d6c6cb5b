// Route edges -> RouteMap: the planned lane of every edge and, between two edges, the internal lanes of
// the connection taken (docs/behaviour.md §S3: turn lanelets are the internal lanes of the route's connections).
#include "route/route_builder.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <utility>

#include "route/route_lanes.hpp"
#include "route/turn_direction.hpp"
#include "core/number_parsing.hpp"
#include "net/internal_lane.hpp"

namespace signalsim::sumo {
namespace {

// An internal lane chain longer than this is a malformed net (netconvert makes at most two).
constexpr int kMaxInternalChain = 16;


/// Turn directions of the connections leaving `lane_id` that have an internal lane (docs/behaviour.md §S3),
/// in file order, without repeats. For an internal lane, that is the next internal lane of its chain.
std::vector<TurnDirection> successor_directions(const NetIndex& net, const std::string& lane_id) {
  std::vector<TurnDirection> out;
  for (const NetConnection& c : net.connections_from_lane(lane_id)) {
    if (c.via.empty()) continue;
    const TurnDirection d = turn_direction_of(c.dir, net.lefthand());
    if (std::find(out.begin(), out.end(), d) == out.end()) out.push_back(d);
  }
  return out;
}

/// A normal lane's params (its edge's, overlaid by its own) and its turn_signal_distance param.
struct LaneParams {
  std::map<std::string, std::string> params;
  std::optional<double> turn_signal_distance;
};

LaneParams lane_params(const NetEdge& edge, const NetLane& lane) {
  LaneParams out;
  out.params = edge.params;
  for (const auto& [key, value] : lane.params) out.params[key] = value;
  if (auto it = out.params.find("turn_signal_distance"); it != out.params.end()) {
    out.turn_signal_distance = parse_double(it->second);
    if (!out.turn_signal_distance) {
      throw RouteError("lane " + quoted_id(lane.id) + ": param 'turn_signal_distance' is not a number: " +
                       quoted_id(it->second));
    }
  }
  return out;
}

/// The roundabout role of the internal lanes between two route edges (docs/behaviour.md §S3): from the
/// <roundabout> element, never from `dir` (docs/behaviour.md §S2).
std::pair<RoundaboutRole, std::optional<std::size_t>> junction_role(const NetIndex& net, const std::string& from,
                                                                    const std::string& to) {
  const auto ring_from = net.roundabout_of_edge(from);
  const auto ring_to = net.roundabout_of_edge(to);
  if (ring_from && ring_to && *ring_from == *ring_to) return {RoundaboutRole::Internal, ring_from};
  if (ring_to) return {RoundaboutRole::Entry, ring_to};
  if (ring_from) return {RoundaboutRole::Exit, ring_from};
  return {RoundaboutRole::None, std::nullopt};
}

/// Whether a connection leaves roundabout `ring` towards a lane a passenger car may use (an exit).
bool leaves_ring(const NetIndex& net, const NetConnection& c, std::size_t ring) {
  if (net.roundabout_of_edge(c.to_edge) == std::optional<std::size_t>(ring)) return false;
  const NetEdge* to = net.edge(c.to_edge);
  if (to == nullptr || c.to_lane < 0 || static_cast<std::size_t>(c.to_lane) >= to->lanes.size()) return false;
  return to->lanes[static_cast<std::size_t>(c.to_lane)].allows_passenger;
}

/// Whether an exit branches off roundabout `ring` at the end of the ring edge `edge`: a lane of the
/// edge has a connection off the ring. Every lane counts: on a multi-lane ring the exit may leave from
/// another lane than the planned one, but it branches at the same place.
bool ring_edge_has_exit(const NetIndex& net, const NetEdge& edge, std::size_t ring) {
  return std::any_of(edge.lanes.begin(), edge.lanes.end(), [&](const NetLane& lane) {
    const auto& connections = net.connections_from_lane(lane.id);
    return std::any_of(connections.begin(), connections.end(),
                       [&](const NetConnection& c) { return leaves_ring(net, c, ring); });
  });
}

/// Refuses the route when `kind` `id` has a defect; `use` says how the route uses it.
void refuse_defective(const NetIndex& net, NetElement kind, const std::string& id, const std::string& use) {
  if (const NetDefect* d = net.defect(kind, id)) {
    throw NetDefectError(net.path(), d->line, d->element + ": " + d->reason + " (" + use + ")");
  }
}

Lanelet lanelet_of(const NetEdge& edge, const NetLane& lane) {
  Lanelet l;
  l.lane_id = lane.id;
  l.edge_id = edge.id;
  l.is_internal = edge.is_internal;
  l.length = lane.length;
  l.speed_limit = lane.speed;
  l.width = lane.width;
  l.shape = lane.shape;
  l.stop_offset = lane.stop_offset;  // the lane's <stopOffset>, else its edge's (NetIndex)
  return l;
}

// The route's lanelets in order, each starting at the route s where the one before ends.
struct LaneletChain {
  std::vector<Lanelet> lanelets;
  double s = 0.0;

  void push(Lanelet l) {
    l.s_start = s;
    s += l.length;
    lanelets.push_back(std::move(l));
  }
};

// The route's edges, after checking that every one exists, is a normal edge with lanes, has no
// defect and can be driven by SUMO.
std::vector<const NetEdge*> route_edges(const NetIndex& net, const std::vector<std::string>& edges) {
  if (edges.empty()) throw RouteError("the route has no edges");
  std::vector<const NetEdge*> route;
  route.reserve(edges.size());
  for (const std::string& id : edges) {
    const NetEdge* edge = net.edge(id);
    if (edge == nullptr) throw RouteError("route edge " + quoted_id(id) + " is not in the net " + quoted_id(net.path()));
    // SUMO reserves ids starting with ':' for junction edges (internal, crossing, walkingarea).
    if (edge->is_internal || id.front() == ':') {
      throw RouteError("route edge " + quoted_id(id) + " is an internal (junction) edge; a route lists normal edges");
    }
    refuse_defective(net, NetElement::Edge, id, "a route edge");
    if (edge->lanes.empty()) throw RouteError("route edge " + quoted_id(id) + " has no lanes");
    if (const std::string why = sumo_cannot_drive(net, *edge); !why.empty()) throw RouteError("route " + why);
    route.push_back(edge);
  }
  return route;
}

// The lanelet of route edge `i` (`edge`): its planned lane, with its params, its ring role and the
// light of `link`, the connection taken to the next edge (null on the last edge). Refuses the route
// when a lane it drives on the edge or that light has a defect.
Lanelet edge_lanelet(const NetIndex& net, const std::vector<std::string>& edges, std::size_t i, const NetEdge& edge,
                     const LanePlan& plan, const NetConnection* link) {
  const NetLane& lane = edge.lanes[static_cast<std::size_t>(plan.exit_lanes[i])];
  const auto edge_ring = net.roundabout_of_edge(edge.id);
  // The lanes the ego drives here: entered on, left on, and crossed between them.
  for (int k = std::min(plan.lanes[i], plan.exit_lanes[i]); k <= std::max(plan.lanes[i], plan.exit_lanes[i]); ++k) {
    refuse_defective(net, NetElement::Lane, edge.lanes[static_cast<std::size_t>(k)].id,
                     "a lane the route drives on edge " + quoted_id(edge.id));
  }

  Lanelet normal = lanelet_of(edge, lane);
  normal.successor_turn_directions = successor_directions(net, lane.id);
  LaneParams own = lane_params(edge, lane);
  normal.params = std::move(own.params);
  normal.turn_signal_distance = own.turn_signal_distance;
  if (edge_ring) {
    normal.roundabout_role = RoundaboutRole::Internal;
    normal.roundabout_id = std::to_string(*edge_ring);
    // Lanelet::leaves_ring_at_end: an exit branches off at the end of this ring lane.
    normal.leaves_ring_at_end = ring_edge_has_exit(net, edge, *edge_ring);
  }
  if (link != nullptr && !link->tl.empty()) {
    refuse_defective(net, NetElement::TlLogic, link->tl,
                     "the light of the route's connection " + quoted_id(edge.id) + " -> " + quoted_id(edges[i + 1]));
  }
  // The stop line is this lane's end: the light of the connection taken leaves it.
  if (link != nullptr && !link->tl.empty()) normal.traffic_light = TrafficLightLink{link->tl, link->link_index};
  return normal;
}

// Pushes the internal lanes of `link`, the connection taken from `edge` to `next_edge`, then those
// chained from them towards `next_lane`, the planned lane of the next edge. Refuses a connection
// without internal lanes, a chain that does not end, and an internal lane, its edge or its junction
// with a defect.
void push_connection_lanelets(const NetIndex& net, const NetEdge& edge, const std::string& next_edge,
                              const NetConnection& link, int next_lane, LaneletChain& chain) {
  if (link.via.empty()) {
    throw RouteError("route edges " + quoted_id(edge.id) + " -> " + quoted_id(next_edge) +
                     ": the connection has no internal lane; the net has no internal lanes "
                     "(built with netconvert --no-internal-links)");
  }
  // Internal lanes take the params of the approach lane, the one the connection starts from (docs/behaviour.md §S3).
  const NetLane& approach = edge.lanes[static_cast<std::size_t>(link.from_lane)];
  const LaneParams approach_params = lane_params(edge, approach);
  const auto [role, ring] = junction_role(net, edge.id, next_edge);

  std::string via = link.via;
  for (int chained = 0; !via.empty(); ++chained) {
    if (chained >= kMaxInternalChain) {
      throw RouteError("route edges " + quoted_id(edge.id) + " -> " + quoted_id(next_edge) +
                       ": the internal lanes of the connection do not end");
    }
    const NetLane* internal = net.lane(via);
    const NetEdge* internal_edge = net.edge_of_lane(via);
    if (internal == nullptr || internal_edge == nullptr) {
      throw RouteError("route edges " + quoted_id(edge.id) + " -> " + quoted_id(next_edge) + ": internal lane " +
                       quoted_id(via) + " is not in the net");
    }
    const std::string use = "an internal lane of the route's connection " + quoted_id(edge.id) + " -> " + quoted_id(next_edge);
    refuse_defective(net, NetElement::Edge, internal_edge->id, use);
    refuse_defective(net, NetElement::Lane, via, use);
    Lanelet l = lanelet_of(*internal_edge, *internal);
    l.is_internal = true;
    l.junction_id = junction_of_internal_lane(via);
    if (net.junction(l.junction_id) == nullptr) l.junction_id = edge.to_junction;
    refuse_defective(net, NetElement::Junction, l.junction_id,
                     "the junction of the route's connection " + quoted_id(edge.id) + " -> " + quoted_id(next_edge));
    const NetConnection* via_of = net.connection_via(via);
    l.turn_direction = turn_direction_of(via_of != nullptr ? via_of->dir : link.dir, net.lefthand());
    l.successor_turn_directions = successor_directions(net, via);
    l.params = approach_params.params;
    l.turn_signal_distance = approach_params.turn_signal_distance;
    l.roundabout_role = role;
    if (ring) l.roundabout_id = std::to_string(*ring);
    // An internal ring -> ring lane lies in the junction where the exits of the ring edge before it
    // branch off: it carries leaves_ring_at_end when that junction has such an exit.
    if (role == RoundaboutRole::Internal) l.leaves_ring_at_end = ring_edge_has_exit(net, edge, *ring);
    chain.push(std::move(l));

    // The connection from this internal lane towards the planned lane of the next edge.
    const NetConnection* onward = nullptr;
    for (const NetConnection& c : net.connections_from_lane(via)) {
      if (c.to_edge != next_edge) continue;
      if (onward == nullptr || (c.to_lane == next_lane && onward->to_lane != next_lane)) onward = &c;
    }
    via = onward != nullptr ? onward->via : std::string();
  }
}

}  // namespace

std::string quoted_id(const std::string& id) { return "'" + id + "'"; }

RoutePlan build_route(const NetIndex& net, const std::vector<std::string>& edges,
                      const std::vector<int>& required_exit, const LaneChangeEgo& ego) {
  const std::vector<const NetEdge*> route = route_edges(net, edges);
  // The lane plan (route_lanes.cpp): connections, permissions, the room of every edge.
  const RouteLanes lanes = plan_route_lanes(net, route, required_exit, ego);
  const LanePlan& plan = lanes.plan;

  LaneletChain chain;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const NetConnection* link = i + 1 < route.size() ? plan.links[i] : nullptr;
    chain.push(edge_lanelet(net, edges, i, *route[i], plan, link));
    if (link == nullptr) break;
    push_connection_lanelets(net, *route[i], edges[i + 1], *link, plan.lanes[i + 1], chain);
  }

  RoutePlan out;
  out.map = RouteMap(std::move(chain.lanelets));
  out.lane_per_edge = plan.exit_lanes;
  out.entry_lane_per_edge = plan.lanes;
  out.lane_changes = plan.lane_changes;
  out.rooms = lanes.rooms;
  out.changes = lanes.changes;
  return out;
}

}  // namespace signalsim::sumo
