// The lanelet routes of fleet mode (docs/fleet.md): one RouteMap per distinct edge list (and vClass: the lanes it may use), built from the
// net the first time a vehicle drives it and shared by every vehicle driving it (memory grows with the
// distinct routes, not with vehicles x route length). An edge list that cannot be built (edges not
// connected for a car, a net defect on it) is remembered with its reason: its vehicles are left to
// SUMO.
#pragma once

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "map/route_map.hpp"
#include "net/net_index.hpp"

namespace signalsim {

/// A route as fleet mode uses it: its lanelets, or why there are none.
struct FleetRoute {
  RouteMap map;
  std::string error;  ///< non-empty: not understood (the route builder's reason)
  bool understood() const { return error.empty(); }
};

class FleetRoutes {
 public:
  explicit FleetRoutes(const sumo::NetIndex& net) : net_(net) {}

  /// The route of `edges` for a vehicle of SUMO class `vclass` (the lanes it may use), built on first
  /// use. Never throws (a failure is the route's error).
  std::shared_ptr<const FleetRoute> route(const std::vector<std::string>& edges, const std::string& vclass);

  int distinct() const { return static_cast<int>(routes_.size()); }
  int not_understood() const { return not_understood_; }

 private:
  const sumo::NetIndex& net_;
  std::unordered_map<std::string, std::shared_ptr<const FleetRoute>> routes_;  // by vClass and edges, joined with ' '
  int not_understood_ = 0;
};

}  // namespace signalsim
