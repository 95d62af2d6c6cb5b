// Exit-signal marking (signalsim option, not in the reference): derive `enable_exit_turn_signal` for
// the ring lanelets before the ego's exit, which is how Japan's road traffic law times the exit signal.
//
// Why: real nets do not carry `enable_exit_turn_signal` (docs/behaviour.md §T5, map requirement VM-03-19), and
// SUMO's exit lanes are a few metres long, so the reference's exit blinker (docs/behaviour.md §T5.3: from the
// start of the exit lanelet) would last only metres. With the marking, the exit request's desired
// start (§T5.3, the start of the enable_exit_turn_signal chain) moves back to the previous exit.
#pragma once

#include "map/route_map.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// For each roundabout passage on the route, i.e. a maximal run of consecutive lanelets of the same
/// roundabout (`roundabout_id`) that ends with the Exit connection the ego takes:
///   - the branching point is the last Internal (ring) lanelet with `leaves_ring_at_end` before the ring
///     lanelet the ego's own exit branches from (that one always has it): the previous exit. In a SUMO
///     net (sumo/route_builder) both the ring lane ending at the previous exit's junction and the
///     internal ring -> ring lane inside that junction have the flag, so the branching point is that
///     internal lane: the junction itself is not marked, marking starts at the ring lane leaving it
///     (the ego has passed beside the previous exit);
///   - params["enable_exit_turn_signal"] = "true" is set on every Internal lanelet strictly after the
///     branching point up to the exit (the ring lanelets only; the exit lanelet itself is not marked);
///   - when no exit branches off before the ego's exit (it takes the first exit), every Internal
///     lanelet after the entry (or from the start of the passage, when the route starts on the ring)
///     up to the exit is marked.
/// A passage that does not end with an Exit lanelet (the route ends on the ring) is left alone.
/// A lanelet that already has an `enable_exit_turn_signal` param (from the net) keeps its value, so a
/// net's explicit "false" still breaks the chain. Everything else is copied unchanged. Pure; never throws.
///
/// Result on the exit request (docs/behaviour.md §T5.3, on_exit "Left" in Japan): the exit blinker comes on when
/// the front leaves the junction of the previous exit (or the entry, for the first exit) and stays on to
/// the end of the exit lanelet.
RouteMap mark_exit_signal_lanes(RouteMap route);

/// The route as the decider sees it under `params`: marked as above when the country's
/// `turn_signal_roundabout_exit_signal_from_previous_exit` is set (Japan), else unchanged. The one
/// home of that choice, for the ego's route and for every fleet vehicle's.
RouteMap route_for_decider(RouteMap route, const TurnSignalParameters& params);

}  // namespace signalsim
