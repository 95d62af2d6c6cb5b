// FleetTracker: fleet mode's state across a run (docs/fleet.md), without SUMO. sim/fleet_port reads
// SUMO for it each step and sets the signals it decides:
//
//   at the start:      depart(v) for every vehicle present (the ego skipped)
//   every step:        arrive(v) for SUMO's arrived, depart(v) for its departed, teleport(v) for
//                      those that started a teleport; then for the followed vehicles (followed(),
//                      in this order) their states; a changed route id -> follow_route(i, edges);
//                      step(time, states) -> each vehicle's signal mask (-1: left to SUMO)
//
// Only the vehicles present are touched: per step the work is proportional to them, never to the
// net or to vehicles that left (their state is dropped at arrival). Routes are shared
// (fleet_routes.hpp). Records every blinker change and per junction or roundabout the episodes and
// lead distances (report/fleet_record.hpp); with `signals: observe` it compares with SUMO's own
// blinker instead of setting the signals.
#pragma once

#include <memory>
#include <regex>
#include <string>
#include <unordered_map>
#include <vector>

#include "fleet/fleet_routes.hpp"
#include "fleet/fleet_vehicle.hpp"
#include "report/fleet_record.hpp"
#include "scenario/scenario.hpp"
#include "session/sumo_session.hpp"  // TrafficState: the values sim/fleet_port reads (no SUMO call here)

namespace signalsim {

class FleetTracker {
 public:
  /// `params`: the scenario's decider parameters (its country preset applied); each vehicle gets them
  /// with base_link_to_front scaled to its length (3.7/4.5, as the ego's default).
  /// `step_length` [s]: SUMO's (the brake light's deceleration threshold).
  FleetTracker(const FleetSpec& spec, const TurnSignalParameters& params, std::string country,
               const sumo::NetIndex& net, std::string ego_id, double step_length);

  bool sets_signals() const { return record_.set_signals; }

  /// A vehicle SUMO departed (or that is present when fleet mode starts). Returns whether it is
  /// followed (selected, not the ego, not followed already).
  bool depart(const std::string& id, const sumo::SumoSession::TrafficVehicle& vehicle);
  /// Whether `id` could be selected before its type is known (not the ego, not followed, its id matches).
  bool may_select(const std::string& id) const;
  void arrive(const std::string& id);
  void teleport(const std::string& id);

  /// The followed vehicles, in the order step() takes their states.
  const std::vector<std::string>& followed() const { return ids_; }
  /// Whether the route id of followed vehicle `i` differs from the one it follows.
  bool route_changed(std::size_t i, const std::string& route_id) const { return vehicles_[i]->route_id() != route_id; }
  void follow_route(std::size_t i, const std::string& route_id, const std::vector<std::string>& edges);

  /// One step at SUMO time `time` (after its step): decides every followed vehicle from `states`
  /// (in followed() order) and fills `masks` (the signal mask to set; -1: set nothing).
  void step(double time, const std::vector<sumo::SumoSession::TrafficState>& states, std::vector<int>& masks);

  /// The record (events ordered by time, then vehicle). Call once, after the last step.
  FleetRecord finish();

 private:
  int record_decision(double time, FleetVehicle& v, const FleetDecision& d, int sumo_signals);
  int brake_light(FleetVehicle& v, double speed) const;
  void start_episode(FleetVehicle& v, const FleetDecision& d);
  void compare_with_sumo(FleetVehicle& v, const FleetDecision& d, int sumo_signals);

  FleetSpec spec_;
  std::optional<std::regex> id_pattern_;
  TurnSignalParameters params_;
  std::string ego_id_;
  double step_length_;
  FleetRoutes routes_;
  std::vector<std::unique_ptr<FleetVehicle>> vehicles_;  // followed, present (a vehicle holds its place on its route)
  std::vector<std::string> ids_;        // their ids, same order
  std::unordered_map<std::string, std::size_t> index_;  // id -> position in vehicles_
  FleetRecord record_;
};

}  // namespace signalsim
