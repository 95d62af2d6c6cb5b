// A vehicle of the user's route files as the ego (`ego: {id: veh42}`, docs/sumo.md): before SUMO starts,
// its route comes from the route files (and no file may already use the id of an ego signalsim adds);
// once it departed, its vType and departure are what SUMO says, and a scenario key that says
// otherwise is an error naming both.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "scenario/scenario.hpp"
#include "net/route_files.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {

/// Reads the scenario's route and additional files. With `ego.id`: fills `ego.route` from the
/// vehicle's definition and returns it. Without: checks that no file defines a vehicle "ego" (the id
/// signalsim gives the ego it adds) and returns null. Throws InputError naming the file and line.
std::optional<sumo::RouteFileVehicle> resolve_route_file_ego(Scenario& scenario);

/// The scenario with the taken-over vehicle's values as SUMO has them (length, width, max speed,
/// accel, emergency decel, departure lane, position and speed), and base_link_to_front from its length
/// (vehicle_defaults::kBaseLinkShare) unless given. Throws InputError when a given key contradicts SUMO's value.
Scenario with_taken_over_ego(const Scenario& scenario, const sumo::EgoVehicle& vehicle,
                             const sumo::RouteFileVehicle& definition);

/// Edge ids as messages write them: "a b c".
std::string edges_text(const std::vector<std::string>& edges);

/// Where each ego value of the run came from ("scenario", "default", "vType 'passenger1'", ...), by
/// EgoSpec key, for summary.json.
std::map<std::string, std::string> ego_sources(const Scenario& scenario, const std::string& vehicle_type);

}  // namespace signalsim
