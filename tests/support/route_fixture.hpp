// Hand-made routes for unit tests (generate, the step stages): lanelets laid end to end on s (straight shapes; the
// generator's rules use positions and attributes only), with SUMO-like ids.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "map/route_map.hpp"

namespace signalsim::test {

class RouteFixture {
 public:
  /// A normal lane "<edge>_0".
  Lanelet& lane(const std::string& edge, double length, double speed = 13.89) {
    Lanelet l;
    l.lane_id = edge + "_0";
    l.edge_id = edge;
    return add(std::move(l), length, speed);
  }
  /// An internal lane ":<junction>_<n>_0" turning `direction`.
  Lanelet& internal(const std::string& junction, int n, double length, TurnDirection direction,
                    double speed = 8.0) {
    Lanelet l;
    l.edge_id = ":" + junction + "_" + std::to_string(n);
    l.lane_id = l.edge_id + "_0";
    l.junction_id = junction;
    l.is_internal = true;
    l.turn_direction = direction;
    return add(std::move(l), length, speed);
  }
  RouteMap build() const { return RouteMap(lanelets_); }
  double end() const { return lanelets_.empty() ? 0.0 : lanelets_.back().s_end(); }

 private:
  Lanelet& add(Lanelet l, double length, double speed) {
    l.s_start = end();
    l.length = length;
    l.speed_limit = speed;
    l.shape = Polyline({{l.s_start, 0.0}, {l.s_start + length, 0.0}});
    lanelets_.push_back(std::move(l));
    return lanelets_.back();
  }
  std::vector<Lanelet> lanelets_;
};

}  // namespace signalsim::test
