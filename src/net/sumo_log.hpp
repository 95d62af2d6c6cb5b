// What SUMO said during a run, counted from its log file (SUMO's --log): warnings, and among them the
// kinds a user looks for (teleports, emergency braking, collisions). Pure: reads a file, no SUMO.
#pragma once

#include <string>

namespace signalsim::sumo {

struct SumoLogCounts {
  bool read = false;        ///< the log file existed
  int warnings = 0;         ///< lines "Warning: ..."
  int errors = 0;           ///< lines "Error: ..."
  int teleports = 0;        ///< warnings "Teleporting vehicle ..."
  int emergency_braking = 0;///< warnings "... performs emergency braking ..."
  int ego_emergency_braking = 0;  ///< of those, the ego's ("Vehicle '<ego>' performs emergency braking")
  int collisions = 0;       ///< warnings "... collision ..."
};

/// Counts the lines of SUMO's log `path` (`ego`: the ego's SUMO id); a missing file gives read =
/// false and zeros.
SumoLogCounts count_sumo_log(const std::string& path, const std::string& ego);

}  // namespace signalsim::sumo
