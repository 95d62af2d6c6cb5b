// Vehicles of a user's route (and additional) files by id, found before SUMO starts: the one signalsim
// takes over as its ego (with the route it drives), or one that already uses the id of an ego
// signalsim would add. Route files can be large (a city's day of demand): they are searched for the
// id's attribute, and only the element found is parsed; nothing else is kept in memory.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace signalsim::sumo {

struct RouteFileVehicle {
  std::string id;
  std::string kind;                ///< "vehicle", "trip" or "flow" (then `id` is the flow's, e.g. "f")
  std::string file;
  int line = 0;
  /// Its edges when the file gives them (an inline <route>, or `route=` naming a <route> of one of
  /// the files); empty when SUMO computes them at departure (a trip, a route distribution).
  std::vector<std::string> edges;
  std::string type;                ///< `type`, empty for SUMO's default type
  /// The vClass of its <vType> in the files ("passenger": SUMO's default type, or a type the files
  /// do not define, e.g. a distribution's).
  std::string vclass = "passenger";
  std::string depart;              ///< `depart` (a flow's `begin`), as written
  std::string depart_lane, depart_pos, depart_speed;  ///< as written, empty when absent
  int stops = 0;                   ///< <stop> children of the vehicle (or of its inline route)
};

/// The definition of vehicle `id` in `files`: a <vehicle> or <trip> of that id, or the <flow> whose
/// vehicles SUMO names "<flow>.<n>" (only when `include_flows`). Nothing when no file defines it.
/// Throws NetError "<file>:<line>: <reason>" for a missing or unreadable file, or a found element
/// that is not well-formed XML.
std::optional<RouteFileVehicle> find_route_file_vehicle(const std::vector<std::string>& files, const std::string& id,
                                                        bool include_flows = true);

}  // namespace signalsim::sumo
