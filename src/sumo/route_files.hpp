// What a user's route (and additional) files define, read before SUMO starts: the vehicles, trips and
// flows by id (so that signalsim can take one over as its ego, or refuse to add an ego whose id a file
// already uses) and the routes they drive. Vehicle types are SUMO's: signalsim reads them from SUMO
// once the ego departed (a type distribution is only drawn then).
#pragma once

#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace signalsim::sumo {

struct RouteFileVehicle {
  std::string id;
  std::string kind;                ///< "vehicle", "trip" or "flow" (then `id` is the flow's, e.g. "f")
  std::string file;
  int line = 0;
  /// Its edges when the file gives them (an inline <route>, or `route=` naming a <route>); empty
  /// when SUMO computes them at departure (a trip, from/to, a route distribution).
  std::vector<std::string> edges;
  std::string type;                ///< `type`, empty for SUMO's default type
  std::string depart_lane, depart_pos, depart_speed;  ///< as written, empty when absent
};

class RouteFiles {
 public:
  /// Reads each file (plain or gzip). Throws NetError "<file>:<line>: <reason>" for a missing or
  /// malformed file or a vehicle without an id.
  static RouteFiles scan(const std::vector<std::string>& files);

  /// The definition of vehicle `id`: a <vehicle> or <trip> of that id, or the <flow> whose vehicles
  /// SUMO names "<flow>.<n>". Null when no file defines it.
  const RouteFileVehicle* vehicle(const std::string& id) const;

  std::size_t vehicle_count() const { return vehicles_.size(); }
  const std::vector<std::string>& files() const { return files_; }

 private:
  std::vector<std::string> files_;
  std::unordered_map<std::string, RouteFileVehicle> vehicles_;  // vehicles, trips and flows by id
  std::unordered_map<std::string, std::vector<std::string>> routes_;  // <route id> -> edges
};

}  // namespace signalsim::sumo
