// Builds the ego's RouteMap from a list of edges: the planned lane sequence, internal lanes included.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "map/route_map.hpp"
#include "route/lane_change_room.hpp"
#include "net/net_index.hpp"

namespace signalsim::sumo {

/// An id as route messages quote it: 'in_X'.
std::string quoted_id(const std::string& id);

/// Thrown when the route cannot be built. what() names the edge(s) and the reason, e.g.
/// "route edge 'in_X' is not in the net" or "route edges 'a' -> 'b' are not connected".
class RouteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The route uses an element of the net with a NetDefect (the loading rule, net_index.hpp).
/// what() = "<net>:<line>: <detail>"; detail() = "<element>: <reason> (<how the route uses it>)".
class NetDefectError : public RouteError {
 public:
  NetDefectError(std::string file, int line, std::string detail)
      : RouteError(file + ":" + std::to_string(line) + ": " + detail),
        file_(std::move(file)), line_(line), detail_(std::move(detail)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& detail() const { return detail_; }

 private:
  std::string file_;
  int line_;
  std::string detail_;
};

struct RoutePlan {
  RouteMap map;                    ///< normal and internal lanelets, contiguous in s from 0
  /// Planned lane index on each route edge (same order as the edges): the lane with the connection
  /// to the next edge (the lanelet's lane); on the last edge the lane the ego enters on, or the
  /// requested one.
  std::vector<int> lane_per_edge;
  /// The lane the ego enters each edge on (the previous connection's to-lane; first edge: the best
  /// depart lane). Where it differs from lane_per_edge, the ego changes lanes on that edge.
  std::vector<int> entry_lane_per_edge;
  int lane_changes = 0;            ///< lane changes the plan needs (0 when one lane sequence connects all)
  /// Per route edge: the room a lane change has there and the ego's speed (lane_change_room.hpp);
  /// the lateral planner times the route's lane changes in exactly this room.
  std::vector<EdgeRoom> rooms;
  /// The plan's lateral motions (one per edge where the entry lane differs from the planned lane),
  /// in route order, each with its room and whether it fits.
  std::vector<PlannedLaneChange> changes;
};

/// Plans one lane per route edge so that each lane has a connection to the next edge's lane
/// (plan_lanes: first every lane change fits its edge, then the fewest lane changes, then the most
/// room for the tightest one, then the rightmost; never across a lane the ego may not use).
/// `ego` sizes the room (lane_change_room.hpp). Between two edges
/// the connection's via lane and any further internal lanes chained from it become lanelets.
/// Turn directions, roundabout roles (with Lanelet::leaves_ring_at_end on ring lanelets), params,
/// lights and stop offsets per docs/behaviour.md §S3.
/// Throws RouteError; NetDefectError when the route uses an element with a NetDefect: a route
/// edge, a lane it drives (entered, left or crossed), an internal lane (or edge) of a connection it
/// takes, the junction that lane lies in, or the light of such a connection.
/// `required_exit`: requested lane changes (see plan_lanes).
RoutePlan build_route(const NetIndex& net, const std::vector<std::string>& edges,
                      const std::vector<int>& required_exit = {}, const LaneChangeEgo& ego = {});

}  // namespace signalsim::sumo
