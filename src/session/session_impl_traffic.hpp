// SessionImpl<Api>, part 4: the other vehicles, for fleet mode (docs/fleet.md). Each step the fleet
// asks what changed (departed, arrived, teleporting) and, for the vehicles it follows, where each is;
// it sets their signal masks. Over TraCI a followed vehicle's variables are subscribed (one answer
// with the step for all of them); in process the getters are asked, each once a step, as for the ego
// (session_impl.hpp: libsumo's subscriptions cost more than its getters).
// Included by session_impl.hpp only.
#pragma once

namespace signalsim::sumo {

template <class Api>
SumoSession::TrafficChanges SessionImpl<Api>::traffic_changes() const {
  return guarded("the vehicles that departed or arrived", [] {
    TrafficChanges c;
    c.departed = Api::Simulation::getDepartedIDList();
    c.arrived = Api::Simulation::getArrivedIDList();
    c.teleport_started = Api::Simulation::getStartingTeleportIDList();
    return c;
  });
}

template <class Api>
std::vector<std::string> SessionImpl<Api>::traffic_present() const {
  return guarded("the vehicles present", [] { return Api::Vehicle::getIDList(); });
}

template <class Api>
SumoSession::TrafficVehicle SessionImpl<Api>::traffic_vehicle(const std::string& id) const {
  return guarded("a vehicle's type", [&id] {
    TrafficVehicle v;
    v.type = Api::Vehicle::getTypeID(id);
    v.vclass = Api::Vehicle::getVehicleClass(id);
    v.length = Api::Vehicle::getLength(id);
    return v;
  });
}

template <class Api>
std::vector<std::string> SessionImpl<Api>::traffic_route(const std::string& id) const {
  return guarded("a vehicle's route", [&id] { return Api::Vehicle::getRoute(id); });
}

namespace traffic {
// The variables of a followed vehicle subscribed over TraCI (the signals only when asked).
inline std::vector<int> subscribed_variables(bool with_signals) {
  std::vector<int> v{libsumo::VAR_ROUTE_ID, libsumo::VAR_LANE_ID, libsumo::VAR_LANEPOSITION, libsumo::VAR_SPEED};
  if (with_signals) v.push_back(libsumo::VAR_SIGNALS);
  return v;
}
}  // namespace traffic

template <class Api>
void SessionImpl<Api>::track_traffic(const std::string& id, bool with_signals) {
  if constexpr (Api::kSubscribes) {
    guarded("a vehicle's variables", [&] {
      Api::Vehicle::subscribe(id, traffic::subscribed_variables(with_signals));
      return 0;
    });
  }
}

template <class Api>
void SessionImpl<Api>::traffic_states(const std::vector<std::string>& ids, bool with_signals,
                                      std::vector<TrafficState>& out) const {
  guarded("the vehicles' positions", [&] {
    out.resize(ids.size());
    const std::size_t wanted = with_signals ? 5 : 4;
    libsumo::SubscriptionResults all;
    if constexpr (Api::kSubscribes) all = Api::Vehicle::getAllSubscriptionResults();
    for (std::size_t i = 0; i < ids.size(); ++i) {
      TrafficState& s = out[i];
      const auto found = all.find(ids[i]);
      if (found != all.end() && found->second.size() >= wanted) {
        const libsumo::TraCIResults& r = found->second;
        s.route_id = subscription::subscribed_text(r, libsumo::VAR_ROUTE_ID);
        s.lane = subscription::subscribed_text(r, libsumo::VAR_LANE_ID);
        s.lane_pos = subscription::subscribed_number(r, libsumo::VAR_LANEPOSITION);
        s.speed = subscription::subscribed_number(r, libsumo::VAR_SPEED);
        s.signals = with_signals ? subscription::subscribed_int(r, libsumo::VAR_SIGNALS, 0) : 0;
        s.known = true;
        continue;
      }
      try {  // in process, or not yet answered over TraCI
        s.route_id = Api::Vehicle::getRouteID(ids[i]);
        s.lane = Api::Vehicle::getLaneID(ids[i]);
        s.lane_pos = Api::Vehicle::getLanePosition(ids[i]);
        s.speed = Api::Vehicle::getSpeed(ids[i]);
        s.signals = with_signals ? Api::Vehicle::getSignals(ids[i]) : 0;
        s.known = true;
      } catch (const libsumo::TraCIException&) {
        s.known = false;  // gone between SUMO's arrival lists (another client removed it)
      }
    }
    return 0;
  });
}

template <class Api>
void SessionImpl<Api>::set_traffic_signals(const std::string& id, int signal_mask) {
  try {
    Api::Vehicle::setSignals(id, signal_mask);
  } catch (const libsumo::TraCIException&) {
    // unknown: another TraCI client removed it this round; SUMO's arrival list reports it next
  } catch (const std::exception& e) {
    throw SumoError("SUMO refused the signals of vehicle '" + id + "': " + failure_reason(e));
  }
}

}  // namespace signalsim::sumo
