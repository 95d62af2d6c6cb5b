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
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// A stretch of a route where the decider may ask for a blinker with no behaviour request: a run of
/// consecutive lanelets turning left or right (§T4.1 NEEDS), with a roundabout role (§T5), or with a
/// turn_signal_distance or enable_exit_turn_signal param. Route s [m].
struct SignalStretch {
  double start = 0.0;
  double end = 0.0;
};

/// A route as fleet mode uses it: its lanelets, or why there are none.
struct FleetRoute {
  RouteMap map;
  std::string error;  ///< non-empty: not understood (the route builder's reason)
  std::vector<SignalStretch> stretches;  ///< in route order, not overlapping
  double max_turn_signal_distance = 0.0;  ///< [m] the largest per-lanelet turn_signal_distance (0: none)
  bool understood() const { return error.empty(); }
  /// Whether the decider can only answer DISABLE for a vehicle with front `s_front`, base_link
  /// `s_base` and search reach `reach` [m]: every stretch is passed by base_link or lies beyond the
  /// reach of the front (docs/fleet.md "What each vehicle gets").
  bool quiet_at(double s_front, double s_base, double reach) const;
};

class FleetRoutes {
 public:
  /// `params`: the scenario's decider parameters (its country's exit-signal marking is applied to
  /// every route, as to the ego's: exit_signal_marking.hpp).
  FleetRoutes(const sumo::NetIndex& net, const TurnSignalParameters& params) : net_(net), params_(params) {}

  /// The route of `edges` for a vehicle of SUMO class `vclass` (the lanes it may use), built on first
  /// use. Never throws (a failure is the route's error).
  std::shared_ptr<const FleetRoute> route(const std::vector<std::string>& edges, const std::string& vclass);

  int distinct() const { return static_cast<int>(routes_.size()); }
  int not_understood() const { return not_understood_; }

 private:
  const sumo::NetIndex& net_;
  TurnSignalParameters params_;
  std::unordered_map<std::string, std::shared_ptr<const FleetRoute>> routes_;  // by vClass and edges, joined with ' '
  int not_understood_ = 0;
};

}  // namespace signalsim
