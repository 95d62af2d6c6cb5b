#include "turn_signal/turn_signal_decider.hpp"

#include <algorithm>

#include "turn_signal/roundabout_backward_length.hpp"

namespace signalsim {

TurnSignalDecision TurnSignalDecider::decide(const RouteMap& route, const EgoOnRoute& ego,
                                             const TurnSignalInfo& behavior) {
  TurnSignalDecision decision;
  decision.behavior = behavior;
  // docs/behaviour.md §T3.1: a hazard request (driving backward) bypasses the decider.
  if (behavior.hazard == HazardLights::Enable) {
    decision.turn = TurnIndicator::Disable;
    decision.hazard = HazardLights::Enable;
    decision.source = behavior.source;
    return decision;
  }
  // docs/behaviour.md §T3.2 early return: no path -> the raw, unfiltered behaviour command.
  if (route.empty()) {
    decision.turn = behavior.turn;
    decision.source = behavior.turn == TurnIndicator::NoCommand ? RequestSource::None : behavior.source;
    return decision;
  }
  // docs/behaviour.md §T3.2 / §T5.4: the back length of P, extended in roundabouts. The closest lanelet is the
  // one containing base_link (on a route it always exists).
  decision.path_backward_length = roundabout_backward_length(
      route, route.index_at(ego.s_base), params_.turn_signal_path_backward_length,
      params_.turn_signal_roundabout_backward_depth, roundabouts_.desired_starts());
  const double back = std::max(0.0, ego.s_base - decision.path_backward_length);
  const RouteMap::Window window = route.window(back, ego.s_base + params_.forward_path_length);
  decision.intersection = intersections_.update(route, window, ego, behavior.turn, params_);  // §T4
  decision.roundabout = roundabouts_.update(route, window, ego, params_);                     // §T5
  const ResolvedTurnSignal resolved =
      resolve_turn_signal(ego, decision.intersection, decision.roundabout, behavior);        // §T6
  decision.turn = resolved.command;
  decision.source = resolved.source;
  return decision;
}

}  // namespace signalsim
