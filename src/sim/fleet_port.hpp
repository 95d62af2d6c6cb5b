// Fleet mode's port to SUMO (docs/fleet.md): each step, what fleet/FleetTracker needs of SUMO's
// vehicles (who departed, arrived or started a teleport; where each followed vehicle is; a replaced
// route's edges), and the signal masks it decided, set for the next step. Only the vehicles present
// are asked about, in the byte order of their ids (SUMO's own order: its look-ups stay cached).
#pragma once

#include "fleet/fleet_tracker.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {

class FleetPort {
 public:
  FleetPort(sumo::SumoSession& session, FleetTracker& tracker) : session_(session), tracker_(tracker) {}

  /// One pass after SUMO's step (the first pass takes every vehicle present). Throws sumo::SumoError.
  void step();

 private:
  void depart(const std::string& id);
  void forget_unknown();
  void sort_order();
  void read_states(bool with_signals);

  sumo::SumoSession& session_;
  FleetTracker& tracker_;
  bool started_ = false;
  std::vector<sumo::SumoSession::TrafficState> states_;  // kept: a step allocates nothing once grown
  std::vector<int> masks_;
  bool order_stale_ = true;                 // the followed vehicles changed since order_ was sorted
  std::vector<std::size_t> order_;          // tracker indices in the byte order of their ids
  std::vector<std::string> sorted_ids_;     // the ids in that order
  std::vector<sumo::SumoSession::TrafficState> sorted_states_;  // read in that order
};

}  // namespace signalsim
