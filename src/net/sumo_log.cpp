#include "net/sumo_log.hpp"

#include <fstream>

namespace signalsim::sumo {

SumoLogCounts count_sumo_log(const std::string& path, const std::string& ego) {
  SumoLogCounts counts;
  const std::string ego_vehicle = "Vehicle '" + ego + "' ";
  std::ifstream in(path);
  if (!in) return counts;
  counts.read = true;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("Error: ", 0) == 0) ++counts.errors;
    if (line.rfind("Warning: ", 0) != 0) continue;
    ++counts.warnings;
    if (line.find("Teleporting vehicle") != std::string::npos) ++counts.teleports;
    if (line.find("emergency braking") != std::string::npos) {
      ++counts.emergency_braking;
      if (line.find(ego_vehicle) != std::string::npos) ++counts.ego_emergency_braking;
    }
    if (line.find("ollision") != std::string::npos) ++counts.collisions;
  }
  return counts;
}

}  // namespace signalsim::sumo
