// The lanelet routes of fleet mode; see fleet_routes.hpp.
#include "fleet/fleet_routes.hpp"

#include "route/route_builder.hpp"

namespace signalsim {

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
    built->map = sumo::build_route(net_, edges, {}, vehicle).map;
  } catch (const std::exception& e) {
    built->error = e.what();
    ++not_understood_;
  }
  return routes_.emplace(std::move(key), std::move(built)).first->second;
}

}  // namespace signalsim
