// A user's SUMO configuration file (.sumocfg): the options it sets, read as SUMO reads them
// (`<option value="..."/>` elements, in categories or not; `${VAR}` replaced by the environment
// variable; relative file names relative to the .sumocfg).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "net/sumo_options.hpp"

namespace signalsim::sumo {

struct SumoConfigFile {
  std::string path;
  std::string dir;                          ///< the folder relative names are resolved from
  std::optional<std::string> net;           ///< net-file, resolved
  std::vector<std::string> route_files;     ///< route-files, resolved, in order
  std::vector<std::string> additional;      ///< additional-files, resolved, in order
  std::optional<double> begin, end, step_length;
  int end_line = 0;                         ///< the line of `end`
  int step_length_line = 0;                 ///< the line of `step-length`
  std::optional<int> seed;
  /// Every other option, in file order (input file names still relative to `dir`), with its line.
  struct Other {
    SumoOption option;
    int line = 0;
  };
  std::vector<Other> others;
};

/// Reads `path` (plain or gzip). Throws NetError "<path>:<line>: <reason>" for a missing or unreadable
/// file, XML that is not a SUMO configuration, a number that does not parse, or a listed input file
/// (net, route or additional file) that is not a file (core/file_paths.hpp input_file_problem).
SumoConfigFile read_sumocfg(const std::string& path);

}  // namespace signalsim::sumo
