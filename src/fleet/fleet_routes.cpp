// The lanelet routes of fleet mode; see fleet_routes.hpp.
#include "fleet/fleet_routes.hpp"

#include <algorithm>

#include "route/route_builder.hpp"
#include "turn_signal/exit_signal_marking.hpp"

namespace signalsim {

namespace {

constexpr double kStretchMargin = 1.0;  // [m] around each stretch: rounding never decides a request

bool asks_for_signal(const Lanelet& l) {
  return l.turn_direction == TurnDirection::Left || l.turn_direction == TurnDirection::Right ||
         l.roundabout_role != RoundaboutRole::None || l.turn_signal_distance.has_value() ||
         l.params.contains("enable_exit_turn_signal");
}

// The route's signal stretches: runs of consecutive lanelets that may ask for a blinker.
void find_stretches(FleetRoute& route) {
  for (const Lanelet& l : route.map.lanelets()) {
    if (l.turn_signal_distance) route.max_turn_signal_distance = std::max(route.max_turn_signal_distance, *l.turn_signal_distance);
    if (!asks_for_signal(l)) continue;
    if (!route.stretches.empty() && route.stretches.back().end >= l.s_start - 1e-9)
      route.stretches.back().end = l.s_end();
    else
      route.stretches.push_back({l.s_start, l.s_end()});
  }
}

}  // namespace

bool FleetRoute::quiet_at(double s_front, double s_base, double reach) const {
  // the first stretch base_link has not passed
  const auto it = std::lower_bound(stretches.begin(), stretches.end(), s_base - kStretchMargin,
                                   [](const SignalStretch& s, double v) { return s.end < v; });
  return it == stretches.end() || it->start - kStretchMargin - s_front > reach;
}

std::shared_ptr<const FleetRoute> FleetRoutes::route(const std::vector<std::string>& edges, const std::string& vclass) {
  std::string key = vclass + ' ';
  for (const std::string& edge : edges) {
    key += edge;
    key += ' ';  // edge ids hold no space (SUMO refuses them)
  }
  if (const auto it = routes_.find(key); it != routes_.end()) return it->second;
  auto built = std::make_shared<FleetRoute>();
  try {
    if (edges.empty()) throw sumo::RouteError("the route has no edges");
    sumo::LaneChangeEgo vehicle;
    vehicle.vclass = vclass;
    built->map = route_for_decider(sumo::build_route(net_, edges, {}, vehicle).map, params_);
    find_stretches(*built);
  } catch (const std::exception& e) {
    built->error = e.what();
    ++not_understood_;
  }
  return routes_.emplace(std::move(key), std::move(built)).first->second;
}

}  // namespace signalsim
