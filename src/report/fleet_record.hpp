// What fleet mode recorded (docs/fleet.md, docs/outputs.md "fleet_events.csv", summary.json `fleet`):
// every blinker change of a followed vehicle, and per junction or roundabout what the rules signalled
// there (and, with `signals: observe`, what SUMO's own blinker did meanwhile). Filled by fleet/, written
// by report/fleet_outputs.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/blinker_signals.hpp"

namespace signalsim {

/// One blinker change of a followed vehicle (a row of fleet_events.csv).
struct FleetEvent {
  std::string vehicle;
  double time = 0.0;               ///< [s] SUMO time after the step the change was decided on
  Blinker blinker = Blinker::None;  ///< the blinker from now on
  double s_front = 0.0;            ///< [m] the front's position on the vehicle's route
  std::string place;               ///< the junction or roundabout the request is for; "" when off
  std::string place_kind;          ///< "junction", "roundabout" or ""
  std::string source;              ///< the request that won (intersection, roundabout_entry, ...); "none"
};

/// What the rules signalled at one junction or roundabout.
struct FleetPlaceStats {
  std::string kind;        ///< "junction" or "roundabout"
  int signals = 0;         ///< blinker-on episodes for this place (a vehicle passing twice counts twice)
  int left = 0, right = 0;  ///< of them, left and right
  /// Lead distance of each episode [m]: the place's start on the route (the turn lane's or the
  /// connection's start, §T4 required start) minus the front's position when the blinker came on.
  double lead_sum = 0.0, lead_min = 0.0, lead_max = 0.0;
  /// `signals: observe`: episodes in which SUMO's own blinker showed the rules' direction at least
  /// one step, and the sum of its lead distances (from its first such step) over them.
  int sumo_signalled = 0;
  double sumo_lead_sum = 0.0;
};

/// The run's fleet counts.
struct FleetTotals {
  int vehicles_seen = 0;       ///< vehicles present or departed while fleet mode ran (the ego not counted)
  int vehicles_selected = 0;   ///< of them, matching the selection
  int vehicles_followed = 0;   ///< of them, with a route signalsim understands (at some time)
  int left_to_sumo = 0;        ///< selected, but a route without lanelets signalsim understands
  int rerouted = 0;            ///< route replacements followed (rerouter, TraCI, ...)
  int teleports = 0;           ///< teleports of followed vehicles
  int distinct_routes = 0;     ///< distinct edge lists built (shared by the vehicles driving them)
  int routes_not_understood = 0;  ///< distinct edge lists that could not be built
  long long vehicle_steps = 0;  ///< decider cycles run (one per followed vehicle and step)
  int vehicles_signalled = 0;  ///< followed vehicles whose blinker was on at least once
  // `signals: observe` only: each vehicle-step's rules blinker against SUMO's own.
  long long agree_steps = 0;      ///< the same (both off included)
  long long rules_only_steps = 0;  ///< the rules on, SUMO off
  long long sumo_only_steps = 0;   ///< SUMO on, the rules off
  long long opposite_steps = 0;    ///< both on, different
};

struct FleetRecord {
  bool set_signals = true;    ///< `signals: set` (false: observe)
  std::string country;        ///< the scenario's preset ("" none)
  std::vector<FleetEvent> events;
  std::map<std::string, FleetPlaceStats> places;  ///< by junction or roundabout id
  FleetTotals totals;
  /// Up to 20 vehicles left to SUMO, with the reason (the route error).
  std::vector<std::pair<std::string, std::string>> left_examples;
};

}  // namespace signalsim
