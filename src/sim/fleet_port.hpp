// Fleet mode's port to SUMO (docs/fleet.md): each step, what fleet/FleetTracker needs of SUMO's
// vehicles (who departed, arrived or started a teleport; where each followed vehicle is; a replaced
// route's edges), and the signal masks it decided, set for the next step. Only the vehicles present
// are asked about.
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

  sumo::SumoSession& session_;
  FleetTracker& tracker_;
  bool started_ = false;
  std::vector<sumo::SumoSession::TrafficState> states_;  // kept: a step allocates nothing once grown
  std::vector<int> masks_;
};

}  // namespace signalsim
