// The turn-signal decider (docs/behaviour.md §T3): which blinker, every planning cycle.
//
// Per cycle, for the ego at route positions (s_front, s_base) with signed speed v:
//
//   if the route is empty:                return the behaviour request unfiltered     (§T3.2)
//   if behaviour requests hazards:        turn = DISABLE, hazard = ENABLE              (§T3.1)
//   back := turn_signal_path_backward_length, extended while the ego is on a ring or exit lanelet
//           so that P still reaches the stored desired start of the roundabout entry:
//           DFS over route predecessors, at most turn_signal_roundabout_backward_depth deep  (§T5.4)
//   P  := route lanelets within [s_base - back, s_base + forward_path_length]          (§T3.2)
//   I  := intersection request: turn-lane groups whose start is within
//         turn_signal_search_time * v + turn_signal_intersection_search_distance
//         (or the lanelet's turn_signal_distance) of the front; the desired start is
//         remembered from the first cycle the group came within reach                 (§T4)
//   Rb := roundabout request: entries within turn_signal_search_time * v +
//         turn_signal_roundabout_search_distance (or turn_signal_distance) of the front,
//         command turn_signal_roundabout_on_entry or the entry's exit_turn_signal_left/right
//         tag for the exit taken, optionally kept to the exit's end (persistence); exits from
//         the front reaching the exit (or its enable_exit_turn_signal chain), command
//         turn_signal_roundabout_on_exit; FIRST_ACTIVE of "entries, then exits"         (§T5)
//   B  := behaviour request (lane change, avoidance, pull out/over; given by the caller) (§T8)
//   turn := RESOLVE(I, Rb, B): DISABLE when none is eligible                          (§T6)
//
// State: the remembered desired starts (owned by IntersectionRequests and RoundaboutRequests).
// Never throws.
#pragma once

#include "map/route_map.hpp"
#include "turn_signal/intersection_requests.hpp"
#include "turn_signal/resolver.hpp"
#include "turn_signal/roundabout_requests.hpp"
#include "turn_signal/turn_signal_info.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// What the decider decided in one cycle, with the candidates it weighed (for timelines and plots).
struct TurnSignalDecision {
  TurnIndicator turn = TurnIndicator::Disable;
  HazardLights hazard = HazardLights::Disable;
  RequestSource source = RequestSource::None;  ///< the request that won; None when DISABLE
  TurnSignalInfo intersection;                 ///< candidate I (EMPTY when none)
  TurnSignalInfo roundabout;                   ///< candidate Rb (EMPTY when none)
  TurnSignalInfo behavior;                     ///< candidate B
  double path_backward_length = 0.0;           ///< back length of P used this cycle [m] (§T3.2, §T5.4)
};

class TurnSignalDecider {
 public:
  explicit TurnSignalDecider(TurnSignalParameters params) : params_(std::move(params)) {}

  /// One planning cycle. `behavior` is the merged behaviour-module request (EMPTY when none).
  TurnSignalDecision decide(const RouteMap& route, const EgoOnRoute& ego,
                            const TurnSignalInfo& behavior = {});

  const TurnSignalParameters& parameters() const { return params_; }
  const IntersectionRequests& intersections() const { return intersections_; }
  const RoundaboutRequests& roundabouts() const { return roundabouts_; }

 private:
  TurnSignalParameters params_;
  IntersectionRequests intersections_;
  RoundaboutRequests roundabouts_;
};

}  // namespace signalsim
