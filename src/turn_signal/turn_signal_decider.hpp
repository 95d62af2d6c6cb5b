// The turn-signal decider (spec TSD §3): which blinker, every planning cycle.
//
// Per cycle, for the ego at route positions (s_front, s_base) with signed speed v:
//
//   if the route is empty:                return the behaviour request unfiltered     (§3.2)
//   if behaviour requests hazards:        turn = DISABLE, hazard = ENABLE              (§3.1)
//   P  := route lanelets within [s_base - turn_signal_path_backward_length,
//                                s_base + forward_path_length]                        (§3.2)
//   I  := intersection request: turn-lane groups whose start is within
//         turn_signal_search_time * v + turn_signal_intersection_search_distance
//         (or the lanelet's turn_signal_distance) of the front; the desired start is
//         remembered from the first cycle the group came within reach                 (§4)
//   Rb := roundabout request (EMPTY until roundabouts land)                           (§5)
//   B  := behaviour request (lane change, avoidance, pull out/over; EMPTY for now)    (§8)
//   turn := RESOLVE(I, Rb, B): DISABLE when none is eligible                          (§6)
//
// State: the remembered desired starts (owned by IntersectionRequests). Never throws.
#pragma once

#include "map/route_map.hpp"
#include "turn_signal/intersection_requests.hpp"
#include "turn_signal/resolver.hpp"
#include "turn_signal/turn_signal_info.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// What the decider decided in one cycle, with the candidates it weighed (for timelines and plots).
struct TurnSignalDecision {
  TurnIndicator turn = TurnIndicator::Disable;
  HazardLights hazard = HazardLights::Disable;
  RequestSource source = RequestSource::None;  ///< the request that won; None when DISABLE
  TurnSignalInfo intersection;                 ///< candidate I (EMPTY when none)
  TurnSignalInfo roundabout;                   ///< candidate Rb
  TurnSignalInfo behavior;                     ///< candidate B
};

class TurnSignalDecider {
 public:
  explicit TurnSignalDecider(TurnSignalParameters params) : params_(std::move(params)) {}

  /// One planning cycle. `behavior` is the merged behaviour-module request (EMPTY when none).
  TurnSignalDecision decide(const RouteMap& route, const EgoOnRoute& ego,
                            const TurnSignalInfo& behavior = {});

  const TurnSignalParameters& parameters() const { return params_; }

 private:
  TurnSignalParameters params_;
  IntersectionRequests intersections_;
};

}  // namespace signalsim
