#include "scenario/take_over.hpp"

#include <cmath>
#include <sstream>

#include "scenario/input_error.hpp"
#include "core/number_parsing.hpp"

namespace signalsim {
namespace {

std::string where(const sumo::RouteFileVehicle& v) { return v.file + ":" + std::to_string(v.line); }

}  // namespace

std::optional<sumo::RouteFileVehicle> resolve_route_file_ego(Scenario& scenario) {
  std::vector<std::string> files = scenario.sumo.route_files;
  files.insert(files.end(), scenario.additional.begin(), scenario.additional.end());
  const std::string& id = scenario.ego.id;
  if (files.empty()) {
    if (!id.empty())
      throw key_error(scenario, "ego.id",
                       "ego.id '" + id + "': the scenario loads no route files (routes: or a sumocfg with "
                       "route-files) that could define it");
    return std::nullopt;
  }
  if (id.empty()) {
    // A <flow id="ego"> names its vehicles ego.0, ego.1, ...: no clash.
    if (const auto clash = sumo::find_route_file_vehicle(files, sumo::kDefaultEgoId, false))
      throw InputError(clash->file, clash->line,
                       "<" + clash->kind + "> '" + clash->id + "' has the id signalsim gives the ego it adds (" +
                           scenario.path + "): take it over with ego.id: " + clash->id + ", or rename it");
    return std::nullopt;
  }
  const std::optional<sumo::RouteFileVehicle> v = sumo::find_route_file_vehicle(files, id);
  if (!v)
    throw key_error(scenario, "ego.id",
                     "ego.id '" + id + "': no <vehicle>, <trip> or <flow> of the route files defines it (" +
                         edges_text(files) + ")");
  if (v->edges.empty())
    throw InputError(v->file, v->line,
                     "<" + v->kind + "> '" + v->id + "' (ego.id) has no edges of its own (a trip, or a route "
                     "distribution): SUMO computes its route only when it departs, and signalsim plans the ego's "
                     "lanes before SUMO starts; give it a <route> (e.g. with duarouter) or take over another vehicle");
  if (v->stops > 0)
    throw InputError(v->file, v->line,
                     "<" + v->kind + "> '" + v->id + "' (ego.id) has " + std::to_string(v->stops) +
                         " <stop>(s): SUMO would stop it on its own, while signalsim drives the ego's speed; take "
                         "over a vehicle without stops (a pull-over is a maneuver of the scenario)");
  // SUMO never inserts a vehicle that departs before the simulation begins: waiting for it is futile.
  double depart = 0.0;
  if (std::istringstream(v->depart) >> depart; !v->depart.empty() && depart < scenario.sumo.begin)
    throw InputError(v->file, v->line,
                     "<" + v->kind + "> '" + v->id + "' (ego.id) departs at " + v->depart + " s, before the simulation "
                     "begins (" + short_number(scenario.sumo.begin) + " s): SUMO never inserts it");
  if (scenario.sumo.end && !v->depart.empty() && depart >= *scenario.sumo.end)
    throw InputError(v->file, v->line,
                     "<" + v->kind + "> '" + v->id + "' (ego.id) departs at " + v->depart + " s, at or after the end of "
                     "the simulation (" + short_number(*scenario.sumo.end) + " s)");
  if (scenario.ego.given.count("route") && scenario.ego.route != v->edges)
    throw key_error(scenario, "ego.route",
                     "ego.route [" + edges_text(scenario.ego.route) + "] contradicts the route of '" + id + "' in " +
                         where(*v) + " [" + edges_text(v->edges) + "]");
  scenario.ego.route = v->edges;
  scenario.ego.vclass = v->vclass;  // its lanes: those its vType's class may use
  return *v;
}

Scenario with_taken_over_ego(const Scenario& scenario, const sumo::EgoVehicle& vehicle,
                             const sumo::RouteFileVehicle& definition) {
  Scenario s = scenario;
  EgoSpec& ego = s.ego;
  // A given key must repeat SUMO's value (to 1 mm, 1 mm/s); otherwise SUMO's value is the ego's.
  const auto take = [&](const char* key, double& field, double sumo_value) {
    if (ego.given.count(key) && std::abs(field - sumo_value) > 1e-3)
      throw key_error(scenario, std::string("ego.") + key, std::string("ego.") + key + " " + short_number(field) + " contradicts vehicle '" +
                                             vehicle.id + "' of " + where(definition) + ": its vType '" + vehicle.type +
                                             "' has " + short_number(sumo_value));
    field = sumo_value;
  };
  take("length", ego.length, vehicle.length);
  take("width", ego.width, vehicle.width);
  take("max_speed", ego.max_speed, vehicle.max_speed);
  take("accel", ego.accel, vehicle.accel);
  take("emergency_decel", ego.emergency_decel, vehicle.emergency_decel);
  if (!ego.given.count("base_link_to_front")) ego.base_link_to_front = vehicle_defaults::kBaseLinkShare * ego.length;
  if (ego.base_link_to_front > ego.length)
    throw key_error(scenario, "ego.base_link_to_front", "ego.base_link_to_front " + short_number(ego.base_link_to_front) +
                                           " m is longer than vehicle '" + vehicle.id + "' (" + short_number(ego.length) + " m)");
  ego.vclass = vehicle.vclass.empty() ? ego.vclass : vehicle.vclass;
  ego.sumo_decel = vehicle.decel;
  ego.depart_lane = vehicle.depart_lane;
  ego.depart_pos = vehicle.depart_pos;
  ego.depart_speed = vehicle.depart_speed;
  return s;
}

std::string edges_text(const std::vector<std::string>& edges) {
  std::string out;
  for (const std::string& e : edges) out += (out.empty() ? "" : " ") + e;
  return out;
}

std::map<std::string, std::string> ego_sources(const Scenario& scenario, const std::string& vehicle_type) {
  const EgoSpec& ego = scenario.ego;
  const bool taken = !ego.id.empty();
  const std::string sumo_type = "vType '" + vehicle_type + "'";
  std::map<std::string, std::string> out;
  const auto source = [&](const char* key, bool from_sumo) {
    out[key] = ego.from_vehicle_info.count(key) ? "vehicle_info " + ego.vehicle_info
               : ego.given.count(key)           ? (ego.lines.count(key) && ego.lines.at(key) == 0 ? "--set" : "scenario")
               : (taken && from_sumo ? sumo_type : "default");
  };
  source("route", true);
  for (const char* key : {"length", "width", "max_speed", "accel", "emergency_decel"}) source(key, true);
  source("decel", false);
  if (!ego.given.count("base_link_to_front")) out["base_link_to_front"] = "length x 3.7/4.5";
  else source("base_link_to_front", false);
  if (taken) {
    out["route"] = ego.given.count("route") ? "scenario (equal to its route file's)" : "route file";
    for (const char* key : {"depart_lane", "depart_pos", "depart_speed"}) out[key] = "SUMO (its departure)";
  } else {
    for (const char* key : {"depart_lane", "depart_pos", "depart_speed"}) source(key, false);
  }
  return out;
}

}  // namespace signalsim
