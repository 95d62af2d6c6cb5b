// One vehicle of the fleet; see fleet_vehicle.hpp.
#include "fleet/fleet_vehicle.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {
namespace {

// A SUMO lane id is its edge's id, '_' and its index.
std::string edge_of_lane(const std::string& lane) {
  const auto underscore = lane.rfind('_');
  return underscore == std::string::npos ? lane : lane.substr(0, underscore);
}

Blinker blinker_of(const TurnSignalDecision& d) {
  if (d.hazard == HazardLights::Enable) return Blinker::Hazard;
  if (d.turn == TurnIndicator::EnableLeft) return Blinker::Left;
  if (d.turn == TurnIndicator::EnableRight) return Blinker::Right;
  return Blinker::None;
}

// The junction the winning request is for: the lanelet where its lanelets start (an internal lane
// lies in its junction; a normal lane is named by itself).
void set_place(const RouteMap& route, const TurnSignalDecision& d, FleetDecision& out) {
  const bool roundabout = d.source == RequestSource::RoundaboutEntry || d.source == RequestSource::RoundaboutExit;
  if (!roundabout && d.source != RequestSource::Intersection) return;
  const TurnSignalInfo& info = roundabout ? d.roundabout : d.intersection;
  const Lanelet& lanelet = route.at(route.index_at(info.required_start));
  out.place = lanelet.junction_id.empty() ? lanelet.lane_id : lanelet.junction_id;
  out.place_kind = roundabout ? "roundabout" : "junction";
  out.place_s = info.required_start;
}

}  // namespace

void FleetVehicle::follow(std::string route_id, std::shared_ptr<const FleetRoute> route) {
  route_id_ = std::move(route_id);
  route_ = std::move(route);
  locator_.reset();
  decider_.reset();
}

std::optional<FleetDecision> FleetVehicle::decide(const std::string& lane, double lane_pos, double speed) {
  if (lane.empty() || !understood()) return std::nullopt;
  const RouteMap& map = route_->map;
  const std::string edge = edge_of_lane(lane);
  if (!locator_) locator_.emplace(map, map.s_of(lane, edge, lane_pos).value_or(0.0));
  if (!decider_) decider_.emplace(params_);
  const RouteLocator::Place place = locator_->locate(lane, edge, lane_pos);
  EgoOnRoute on_route;
  on_route.s_front = place.s_front;
  on_route.s_base = place.s_front - params_.base_link_to_front;
  on_route.speed = speed;
  FleetDecision out;
  out.s_front = place.s_front;
  // Far from every signal stretch the decider can only answer DISABLE (§T4.1, §T5): it is not run.
  const double reach = params_.turn_signal_search_time * std::abs(speed) +
                       std::max({params_.turn_signal_intersection_search_distance,
                                 params_.turn_signal_roundabout_search_distance, route_->max_turn_signal_distance});
  if (route_->quiet_at(on_route.s_front, on_route.s_base, reach)) return out;
  const TurnSignalDecision d = decider_->decide(map, on_route);
  out.blinker = blinker_of(d);
  out.source = out.blinker == Blinker::None ? RequestSource::None : d.source;
  if (out.blinker != Blinker::None) set_place(map, d, out);
  return out;
}

}  // namespace signalsim
