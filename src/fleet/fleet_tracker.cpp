// Fleet mode's state across a run; see fleet_tracker.hpp.
#include "fleet/fleet_tracker.hpp"

#include <algorithm>

#include "core/vehicle_defaults.hpp"

namespace signalsim {
namespace {

constexpr std::size_t kLeftExamples = 20;

std::string source_name(RequestSource s) { return s == RequestSource::None ? "none" : std::string(to_string(s)); }

}  // namespace

FleetTracker::FleetTracker(const FleetSpec& spec, const TurnSignalParameters& params, std::string country,
                           const sumo::NetIndex& net, std::string ego_id, double step_length)
    : spec_(spec), params_(params), ego_id_(std::move(ego_id)), step_length_(step_length), routes_(net, params) {
  if (!spec.id_pattern.empty()) id_pattern_.emplace(spec.id_pattern, std::regex::ECMAScript);
  record_.set_signals = spec.set_signals;
  record_.country = std::move(country);
}

bool FleetTracker::may_select(const std::string& id) const {
  return id != ego_id_ && !index_.contains(id) && (!id_pattern_ || std::regex_match(id, *id_pattern_));
}

bool FleetTracker::depart(const std::string& id, const sumo::SumoSession::TrafficVehicle& vehicle) {
  if (id == ego_id_ || index_.contains(id)) return false;
  ++record_.totals.vehicles_seen;
  if (!may_select(id) || (!spec_.vtype.empty() && vehicle.type != spec_.vtype) ||
      (!spec_.vclass.empty() && vehicle.vclass != spec_.vclass))
    return false;
  ++record_.totals.vehicles_selected;
  TurnSignalParameters p = params_;
  p.base_link_to_front = vehicle.length * vehicle_defaults::kBaseLinkToFront / vehicle_defaults::kLength;
  index_.emplace(id, vehicles_.size());
  vehicles_.push_back(std::make_unique<FleetVehicle>(id, vehicle.vclass.empty() ? "passenger" : vehicle.vclass, p));
  ids_.push_back(id);
  return true;
}

void FleetTracker::arrive(const std::string& id) {
  const auto it = index_.find(id);
  if (it == index_.end()) return;
  const std::size_t i = it->second, last = vehicles_.size() - 1;
  index_.erase(it);
  if (i != last) {  // the last one takes its place
    vehicles_[i] = std::move(vehicles_[last]);
    ids_[i] = std::move(ids_[last]);
    index_[ids_[i]] = i;
  }
  vehicles_.pop_back();
  ids_.pop_back();
}

void FleetTracker::teleport(const std::string& id) {
  if (index_.contains(id)) ++record_.totals.teleports;
}

void FleetTracker::follow_route(std::size_t i, const std::string& route_id, const std::vector<std::string>& edges) {
  FleetVehicle& v = *vehicles_[i];
  const bool replaced = !v.route_id().empty();
  const bool was_understood = v.understood();
  v.follow(route_id, routes_.route(edges, v.vclass()));
  if (replaced) ++record_.totals.rerouted;
  if (v.understood() && !was_understood && !v.counted_followed) {
    v.counted_followed = true;
    ++record_.totals.vehicles_followed;
  }
  if (!v.understood() && !v.counted_left) {
    v.counted_left = true;
    ++record_.totals.left_to_sumo;
    if (record_.left_examples.size() < kLeftExamples) record_.left_examples.emplace_back(v.id(), v.route()->error);
  }
}

void FleetTracker::step(double time, const std::vector<sumo::SumoSession::TrafficState>& states, std::vector<int>& masks) {
  masks.assign(vehicles_.size(), -1);
  for (std::size_t i = 0; i < vehicles_.size(); ++i) {
    const sumo::SumoSession::TrafficState& st = states[i];
    const std::optional<FleetDecision> d = vehicles_[i]->decide(st.lane, st.lane_pos, st.speed);
    if (!d) continue;  // teleporting, or a route not understood: SUMO's own blinker
    ++record_.totals.vehicle_steps;
    masks[i] = record_decision(time, *vehicles_[i], *d, st.signals) | brake_light(*vehicles_[i], st.speed);
  }
}

// setSignals replaces every bit SUMO computed for the step, its brake light too, which SUMO's
// junction model reads (jam avoidance). So the mask carries SUMO's rule for it, from the last two
// speeds (one step late): on while standing (below 0.1 m/s) or while slowing down by more than the
// drag SUMO allows for, (0.05 + 0.005 v) v per second (docs/fleet.md). A stop (a bus at its stop)
// is not known here: its brake light shows.
int FleetTracker::brake_light(FleetVehicle& v, double speed) const {
  const std::optional<double> before = v.last_speed;
  v.last_speed = speed;
  const bool slowing = before && speed < *before - (0.05 + 0.005 * *before) * *before * step_length_;
  return speed < 0.1 || slowing ? sumo::kBrakeLight : 0;
}

int FleetTracker::record_decision(double time, FleetVehicle& v, const FleetDecision& d, int sumo_signals) {
  if (d.blinker != v.shown || d.place != v.shown_place) {
    record_.events.push_back({v.id(), time, d.blinker, d.s_front, d.place, d.place_kind, source_name(d.source)});
    v.shown = d.blinker;
    v.shown_place = d.place;
    v.episode.reset();
    if (d.blinker != Blinker::None) start_episode(v, d);
  }
  if (!record_.set_signals) compare_with_sumo(v, d, sumo_signals);
  return signal_mask(d.blinker);
}

// A new blinker-on stretch for a place: counted there with its lead distance (§T4 required start
// minus the front's position now).
void FleetTracker::start_episode(FleetVehicle& v, const FleetDecision& d) {
  v.episode = FleetEpisode{d.place, d.blinker, d.place_s, false};
  if (!v.signalled) {
    v.signalled = true;
    ++record_.totals.vehicles_signalled;
  }
  if (d.place.empty()) return;
  FleetPlaceStats& p = record_.places[d.place];
  const double lead = d.place_s - d.s_front;
  if (p.signals == 0) {
    p.kind = d.place_kind;
    p.lead_min = p.lead_max = lead;
  }
  ++p.signals;
  p.left += d.blinker == Blinker::Left;
  p.right += d.blinker == Blinker::Right;
  p.lead_sum += lead;
  p.lead_min = std::min(p.lead_min, lead);
  p.lead_max = std::max(p.lead_max, lead);
}

// `signals: observe`: the rules' blinker against SUMO's own, this vehicle-step; and whether SUMO
// signals the running episode's direction (first time: its lead distance).
void FleetTracker::compare_with_sumo(FleetVehicle& v, const FleetDecision& d, int sumo_signals) {
  const Blinker sumo = blinker_of_signals(sumo_signals);
  FleetTotals& t = record_.totals;
  if (sumo == d.blinker) ++t.agree_steps;
  else if (sumo == Blinker::None) ++t.rules_only_steps;
  else if (d.blinker == Blinker::None) ++t.sumo_only_steps;
  else ++t.opposite_steps;
  if (v.episode && !v.episode->sumo_seen && sumo == v.episode->blinker && !v.episode->place.empty()) {
    v.episode->sumo_seen = true;
    FleetPlaceStats& p = record_.places[v.episode->place];
    ++p.sumo_signalled;
    p.sumo_lead_sum += v.episode->place_s - d.s_front;
  }
}

FleetRecord FleetTracker::finish() {
  record_.totals.distinct_routes = routes_.distinct();
  record_.totals.routes_not_understood = routes_.not_understood();
  std::stable_sort(record_.events.begin(), record_.events.end(), [](const FleetEvent& a, const FleetEvent& b) {
    return a.time != b.time ? a.time < b.time : a.vehicle < b.vehicle;
  });
  return std::move(record_);
}

}  // namespace signalsim
