// The route locator's rules; see route_locator.hpp.
#include "map/route_locator.hpp"

#include <algorithm>

namespace signalsim {

RouteLocator::Place RouteLocator::locate(const std::string& lane, const std::string& edge, double lane_pos) {
  Place place;
  place.on_plan = route_.find_lane(lane, hint_).has_value();
  std::optional<double> s = route_.s_of(lane, edge, lane_pos, hint_);
  // Another connection of a route junction: never behind the last position.
  if (s && !place.on_plan && !edge.empty() && edge.front() == ':') s = std::max(*s, last_s_);
  place.on_route = s.has_value();
  place.s_front = s.value_or(last_s_);
  hint_ = route_.index_at(std::max(0.0, place.s_front - 1e-6));
  place.index = hint_;
  last_s_ = place.s_front;
  return place;
}

}  // namespace signalsim
