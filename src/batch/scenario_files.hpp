// Scenario paths as the command line and a sweep file's `scenarios:` give them, turned into the
// scenario files to run: a file as it is, a directory as its *.yaml / *.yml files.
#pragma once

#include <string>
#include <vector>

namespace signalsim {

/// Scenario files from paths: a file as given, a directory's *.yaml and *.yml (sorted by name). Throws
/// InputError for a missing path or an empty directory (`origin`/`line` name where it was given).
std::vector<std::string> scenario_files(const std::vector<std::string>& paths, const std::string& origin = "",
                                        int line = 0);

}  // namespace signalsim
