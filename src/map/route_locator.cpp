// The route locator's rules; see route_locator.hpp.
#include "map/route_locator.hpp"

#include <algorithm>

namespace signalsim {

RouteLocator::Place RouteLocator::locate(const std::string& lane, const std::string& edge, double lane_pos) {
  Place place;
  std::optional<double> s;
  if (hint_ < route_.size() && route_.at(hint_).lane_id == lane) {
    // Still on the lanelet it was on: what find_lane and s_of give (a lane's indices are ascending,
    // so the first at or after hint_ is hint_), without looking the lane up.
    place.on_plan = true;
    s = route_.at(hint_).s_start + std::min(lane_pos, route_.at(hint_).length);
  } else {
    place.on_plan = route_.find_lane(lane, hint_).has_value();
    s = route_.s_of(lane, edge, lane_pos, hint_);
  }
  // Another connection of a route junction: never behind the last position.
  if (s && !place.on_plan && !edge.empty() && edge.front() == ':') s = std::max(*s, last_s_);
  place.on_route = s.has_value();
  place.s_front = s.value_or(last_s_);
  hint_ = route_.index_at(std::max(0.0, place.s_front - 1e-6), hint_);
  place.index = hint_;
  last_s_ = place.s_front;
  return place;
}

}  // namespace signalsim
