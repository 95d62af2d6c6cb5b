#include "route/route_lanes.hpp"

#include <algorithm>
#include <limits>

#include "route/route_builder.hpp"
#include "route/sumo_lane_choice.hpp"

namespace signalsim::sumo {
namespace {

EdgeRoom room_of(const NetEdge& edge, bool first, const LaneChangeEgo& ego) {
  EdgeRoom r;
  const double length = edge.lanes.front().length;  // netconvert gives every lane its edge's length
  r.room = lane_change_room(length, first, ego);
  for (const NetLane& lane : edge.lanes) r.widths.push_back(lane.width);
  return r;
}

// The limit of a turn between two route edges: the fastest internal lane of their connections
// (infinity without internal lanes), an upper bound on the speed the ego has there.
double turn_limit(const NetIndex& net, const std::vector<const NetConnection*>& links) {
  double fastest = -1.0;
  for (const NetConnection* c : links)
    if (const NetLane* via = c->via.empty() ? nullptr : net.lane(c->via)) fastest = std::max(fastest, via->speed);
  return fastest < 0.0 ? std::numeric_limits<double>::infinity() : fastest;
}

// Each room's speed (lane_change_speed): the edge's fastest lane and the turns on either side.
void set_room_speeds(const NetIndex& net, const std::vector<const NetEdge*>& route,
                     const std::vector<std::vector<const NetConnection*>>& links, const LaneChangeEgo& ego,
                     std::vector<EdgeRoom>& rooms) {
  for (std::size_t i = 0; i < route.size(); ++i) {
    EdgeSpeeds speeds;
    speeds.limit = 0.0;
    for (const NetLane& lane : route[i]->lanes) speeds.limit = std::max(speeds.limit, lane.speed);
    if (i > 0) speeds.entry = turn_limit(net, links[i - 1]);
    if (i + 1 < route.size()) speeds.exit = turn_limit(net, links[i]);
    rooms[i].speed = lane_change_speed(route[i]->lanes.front().length, i == 0, speeds, ego);
  }
}

// "a passenger car" (signalsim's own ego), else "vClass 'bus'".
std::string vehicle_class(const std::string& vclass) {
  return vclass == "passenger" ? "a passenger car" : "vClass " + quoted_id(vclass);
}

/// A route no plan can drive without crossing a lane the ego may not use: the first such crossing
/// of the plan that ignores the permission of the lanes crossed.
[[noreturn]] void refuse_crossing(const std::vector<const NetEdge*>& route, const LanePlan& crossing,
                                  const std::string& vclass) {
  for (std::size_t i = 0; i < route.size(); ++i) {
    const int a = crossing.lanes[i], b = crossing.exit_lanes[i];
    for (int k = std::min(a, b) + 1; k < std::max(a, b); ++k) {
      const NetLane& lane = route[i]->lanes[static_cast<std::size_t>(k)];
      if (lane_permits(lane, vclass)) continue;
      throw RouteError("the lane change the route needs on edge " + quoted_id(route[i]->id) + " (lane " +
                       std::to_string(a) + " -> " + std::to_string(b) + ") crosses lane " + quoted_id(lane.id) +
                       ", which " + vehicle_class(vclass) + " may not use; no other lane sequence connects the route edges");
    }
  }
  throw RouteError("no lane sequence connects the route edges");  // not reached: the crossing exists
}

}  // namespace

RouteLanes plan_route_lanes(const NetIndex& net, const std::vector<const NetEdge*>& route,
                            const std::vector<int>& required_exit, const LaneChangeEgo& ego) {
  // Lane permissions and the connections between consecutive edges.
  std::vector<std::vector<const NetConnection*>> links(route.size() - 1);
  std::vector<std::vector<bool>> usable;
  RouteLanes out;
  for (std::size_t i = 0; i < route.size(); ++i) {
    usable.emplace_back();
    for (const NetLane& lane : route[i]->lanes) usable.back().push_back(lane_permits(lane, ego.vclass));
    out.rooms.push_back(room_of(*route[i], i == 0, ego));
    if (i + 1 == route.size()) break;
    for (const NetLane& lane : route[i]->lanes) {
      for (const NetConnection& c : net.connections_from_lane(lane.id)) {
        if (c.to_edge == route[i + 1]->id) links[i].push_back(&c);
      }
    }
    if (links[i].empty()) {
      throw RouteError("route edges " + quoted_id(route[i]->id) + " -> " + quoted_id(route[i + 1]->id) + " are not connected");
    }
  }

  set_room_speeds(net, route, links, ego, out.rooms);

  // Where a lane has several connections to the next edge, SUMO takes the one to its best
  // continuation lane (sumo_lane_choice.hpp), whatever signalsim plans: only that one is planned.
  // When that leaves no lane sequence, the plan takes any connection (the run then reports where
  // SUMO leaves it: off_plan).
  SumoLookahead lookahead;
  lookahead.vclass = ego.vclass;
  lookahead.max_speed = ego.max_speed;
  lookahead.decel = ego.sumo_decel;
  lookahead.step_length = ego.step_length;
  const std::vector<std::vector<int>> sumo_next = sumo_next_lanes(net, route, lookahead);
  std::vector<std::vector<const NetConnection*>> sumo_links = links;
  for (std::size_t i = 0; i < sumo_links.size(); ++i)
    std::erase_if(sumo_links[i], [&](const NetConnection* c) {
      return c->from_lane < 0 || c->from_lane >= static_cast<int>(sumo_next[i].size()) ||
             sumo_next[i][static_cast<std::size_t>(c->from_lane)] != c->to_lane;
    });
  const bool sumo_connected = std::none_of(sumo_links.begin(), sumo_links.end(), [](const auto& l) { return l.empty(); });
  if (sumo_connected) out.plan = plan_lanes(usable, sumo_links, required_exit, out.rooms, ego);
  if (out.plan.lanes.size() != route.size()) out.plan = plan_lanes(usable, links, required_exit, out.rooms, ego);
  if (out.plan.lanes.size() != route.size()) {
    const LanePlan crossing = plan_lanes(usable, links, required_exit, out.rooms, ego, true);
    if (crossing.lanes.size() == route.size()) refuse_crossing(route, crossing, ego.vclass);
    throw RouteError("route " + quoted_id(route.front()->id) + " ... " + quoted_id(route.back()->id) +
                     ": no lane sequence connects the route edges");
  }
  for (std::size_t i = 0; i < route.size(); ++i) {
    const int from = out.plan.lanes[i], to = out.plan.exit_lanes[i];
    if (from == to) continue;
    const EdgeRoom& r = out.rooms[i];
    PlannedLaneChange c;
    c.edge_index = i;
    c.edge = route[i]->id;
    c.from_lane = from;
    c.to_lane = to;
    c.room = r.room;
    c.shift = lane_shift(r.widths, from, to);
    c.min_length = min_lane_change_length(c.shift, r.speed, ego);
    c.length = default_lane_change(r.room).length;
    c.fits = lane_change_fits(r.room, c.shift, r.speed, ego);
    out.changes.push_back(std::move(c));
  }
  return out;
}

}  // namespace signalsim::sumo
