// Fleet mode's port to SUMO; see fleet_port.hpp.
#include "sim/fleet_port.hpp"

namespace signalsim {

void FleetPort::depart(const std::string& id) {
  if (!tracker_.may_select(id)) {
    tracker_.depart(id, {});  // counted as seen; its type is not needed
    return;
  }
  if (tracker_.depart(id, session_.traffic_vehicle(id))) session_.track_traffic(id, !tracker_.sets_signals());
}

// Vehicles SUMO no longer knows (removed by another TraCI client between its arrival lists) are
// dropped, with their states, before anything is decided or set for them.
void FleetPort::forget_unknown() {
  for (std::size_t i = states_.size(); i-- > 0;) {
    if (states_[i].known) continue;
    const std::string id = tracker_.followed()[i];
    const std::size_t last = states_.size() - 1;
    tracker_.arrive(id);  // the tracker moves its last vehicle into place i: so do the states
    states_[i] = std::move(states_[last]);
    states_.pop_back();
  }
}

void FleetPort::step() {
  if (!started_) {
    started_ = true;
    for (const std::string& id : session_.traffic_present()) depart(id);
  } else {
    const sumo::SumoSession::TrafficChanges changes = session_.traffic_changes();
    for (const std::string& id : changes.arrived) tracker_.arrive(id);
    for (const std::string& id : changes.departed) depart(id);
    for (const std::string& id : changes.teleport_started) tracker_.teleport(id);
  }
  const bool observe = !tracker_.sets_signals();
  session_.traffic_states(tracker_.followed(), observe, states_);
  forget_unknown();
  const std::vector<std::string>& ids = tracker_.followed();
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (tracker_.route_changed(i, states_[i].route_id))
      tracker_.follow_route(i, states_[i].route_id, session_.traffic_route(ids[i]));
  tracker_.step(session_.time(), states_, masks_);
  if (observe) return;
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (masks_[i] >= 0) session_.set_traffic_signals(ids[i], masks_[i]);
}

}  // namespace signalsim
