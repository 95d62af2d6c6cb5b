// The route's signal sections for the metrics: the stretches of the route that ask for a blinker,
// found from the route alone (RouteMap), in route order, by the decider's own rules
// (turn_signal/signal_sections.hpp):
//
//   turn              consecutive turn lanelets with the same left/right direction (a left turn's
//                     two chained internal lanes are one section), outside roundabouts; the expected
//                     blinker is the direction
//   roundabout_entry  an entry lanelet (one section per lanelet of the connection); expected blinker
//                     turn_signal_roundabout_on_entry, or left/right when the entry's
//                     exit_turn_signal_left/right names the exit the route takes: one of its lanelets or
//                     the edge it leads onto (docs/behaviour.md §T5.2)
//   roundabout_exit   an exit lanelet; expected blinker turn_signal_roundabout_on_exit
//
// A run adds its maneuvers' lateral motions (lane_change, avoidance, pull_out, pull_over) from
// RunRecord::maneuver_lines: see compute_metrics (metrics.hpp).
#pragma once

#include <string>
#include <vector>

#include "map/route_map.hpp"
#include "turn_signal/turn_signal_parameters.hpp"
#include "scenario/scenario.hpp"  // Blinker

namespace signalsim {

/// A stretch of the route that asks for a blinker.
struct SignalSection {
  std::string kind;                   ///< "turn", "roundabout_entry", "roundabout_exit", or a maneuver kind
  std::string id;                     ///< junction id (turns, roundabouts), else the first lane id
  Blinker blinker = Blinker::None;    ///< the blinker the section asks for (None: it asks for none)
  double s_start = 0.0;               ///< route s where the section starts [m]
  double s_end = 0.0;                 ///< route s where it ends [m]
  std::vector<std::string> lanelets;  ///< lane ids, in route order
};

/// The route's signal sections in route order. `params` gives the roundabout on_entry/on_exit.
std::vector<SignalSection> signal_sections(const RouteMap& route, const TurnSignalParameters& params);

}  // namespace signalsim
