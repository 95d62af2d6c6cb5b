// Fleet mode's port to SUMO; see fleet_port.hpp.
#include "sim/fleet_port.hpp"

#include <algorithm>
#include <numeric>

namespace signalsim {

void FleetPort::depart(const std::string& id) {
  order_stale_ = true;
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
    order_stale_ = true;
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
    if (!changes.arrived.empty()) order_stale_ = true;
    for (const std::string& id : changes.departed) depart(id);
    for (const std::string& id : changes.teleport_started) tracker_.teleport(id);
  }
  const bool observe = !tracker_.sets_signals();
  read_states(observe);
  forget_unknown();
  const std::vector<std::string>& ids = tracker_.followed();
  for (std::size_t i = 0; i < ids.size(); ++i)
    if (tracker_.route_changed(i, states_[i].route_id))
      tracker_.follow_route(i, states_[i].route_id, session_.traffic_route(ids[i]));
  tracker_.step(session_.time(), states_, masks_);
  if (observe) return;
  sort_order();
  for (std::size_t k = 0; k < order_.size(); ++k)
    if (const std::size_t i = order_[k]; masks_[i] >= 0) session_.set_traffic_signals(sorted_ids_[k], masks_[i]);
}

// SUMO finds a vehicle by its id in an ordered map for every call: asked in the map's order (the ids'
// byte order), consecutive look-ups walk mostly the same, cached nodes (docs/performance.md "Fleet
// mode"). The order only changes which vehicle is asked first, never a value read or set.
void FleetPort::sort_order() {
  if (!order_stale_) return;
  order_stale_ = false;
  const std::vector<std::string>& ids = tracker_.followed();
  order_.resize(ids.size());
  std::iota(order_.begin(), order_.end(), std::size_t{0});
  std::sort(order_.begin(), order_.end(), [&ids](std::size_t a, std::size_t b) { return ids[a] < ids[b]; });
  sorted_ids_.resize(ids.size());
  for (std::size_t k = 0; k < order_.size(); ++k) sorted_ids_[k] = ids[order_[k]];
}

// The followed vehicles' states, read in SUMO's map order and put in the tracker's order.
void FleetPort::read_states(bool with_signals) {
  sort_order();
  session_.traffic_states(sorted_ids_, with_signals, sorted_states_);
  states_.resize(order_.size());
  for (std::size_t k = 0; k < order_.size(); ++k) std::swap(states_[order_[k]], sorted_states_[k]);
}

}  // namespace signalsim
