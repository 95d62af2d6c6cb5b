#include "sumo/route_lanes.hpp"

#include <algorithm>

#include "sumo/route_builder.hpp"

namespace signalsim::sumo {
namespace {

std::string quoted(const std::string& id) { return "'" + id + "'"; }

EdgeRoom room_of(const NetEdge& edge, bool first, const LaneChangeEgo& ego) {
  EdgeRoom r;
  const double length = edge.lanes.front().length;  // netconvert gives every lane its edge's length
  r.room = lane_change_room(length, first, ego);
  double fastest = 0.0;
  for (const NetLane& lane : edge.lanes) {
    r.widths.push_back(lane.width);
    fastest = std::max(fastest, lane.speed);
  }
  r.speed = std::min(ego.max_speed, fastest);
  return r;
}

/// A route no plan can drive without crossing a lane the ego may not use: the first such crossing
/// of the plan that ignores the permission of the lanes crossed.
[[noreturn]] void refuse_crossing(const std::vector<const NetEdge*>& route, const LanePlan& crossing) {
  for (std::size_t i = 0; i < route.size(); ++i) {
    const int a = crossing.lanes[i], b = crossing.exit_lanes[i];
    for (int k = std::min(a, b) + 1; k < std::max(a, b); ++k) {
      const NetLane& lane = route[i]->lanes[static_cast<std::size_t>(k)];
      if (lane.allows_passenger) continue;
      throw RouteError("the lane change the route needs on edge " + quoted(route[i]->id) + " (lane " +
                       std::to_string(a) + " -> " + std::to_string(b) + ") crosses lane " + quoted(lane.id) +
                       ", which a passenger car may not use; no other lane sequence connects the route edges");
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
    for (const NetLane& lane : route[i]->lanes) usable.back().push_back(lane.allows_passenger);
    out.rooms.push_back(room_of(*route[i], i == 0, ego));
    if (i + 1 == route.size()) break;
    for (const NetLane& lane : route[i]->lanes) {
      for (const NetConnection& c : net.connections_from_lane(lane.id)) {
        if (c.to_edge == route[i + 1]->id) links[i].push_back(&c);
      }
    }
    if (links[i].empty()) {
      throw RouteError("route edges " + quoted(route[i]->id) + " -> " + quoted(route[i + 1]->id) + " are not connected");
    }
  }

  out.plan = plan_lanes(usable, links, required_exit, out.rooms, ego);
  if (out.plan.lanes.size() != route.size()) {
    const LanePlan crossing = plan_lanes(usable, links, required_exit, out.rooms, ego, true);
    if (crossing.lanes.size() == route.size()) refuse_crossing(route, crossing);
    throw RouteError("route " + quoted(route.front()->id) + " ... " + quoted(route.back()->id) +
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
