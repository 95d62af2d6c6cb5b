// Where the ego's front is on the route, step after step (docs/run.md "Locating the ego"): the one
// rule both drivers use. SUMO may put the ego on a lane the lane plan does not list:
//   - a planned lane gives its route s (searched from the lanelet the front was on: the route
//     position is monotonic);
//   - another lane of a route edge gives that edge's route lanelet s plus the lane position (the
//     lanes of an edge share its length);
//   - an internal lane of another connection of a route junction gives the s of the junction's route
//     lanelet plus the lane position, at most that lanelet's end, and never less than the previous
//     step's s (connections differ in length: the position must neither go back nor run past the
//     junction);
//   - any other lane is off the route: s is held at the previous step's.
#pragma once

#include <cstddef>
#include <string>

#include "map/route_map.hpp"

namespace signalsim {

class RouteLocator {
 public:
  /// `start_s` [m]: the front's route position before the first step (the departure position).
  RouteLocator(const RouteMap& route, double start_s) : route_(route), last_s_(start_s) {}

  struct Place {
    double s_front = 0.0;     ///< [m] route s (held when off the route)
    bool on_route = false;    ///< the lane lies on the route (a lanelet, its edge or its junction)
    bool on_plan = false;     ///< the lane is the route's lanelet there
    std::size_t index = 0;    ///< the route lanelet the front is on
  };

  /// The place of SUMO's (lane, edge, lane position) of the front; the next call searches from it.
  Place locate(const std::string& lane, const std::string& edge, double lane_pos);

 private:
  const RouteMap& route_;
  std::size_t hint_ = 0;  // the route lanelet the front was on
  double last_s_;         // its last route position
};

}  // namespace signalsim
