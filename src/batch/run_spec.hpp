// RunSpec: one run of a batch, a sweep or a check, as the run list (run_list.hpp) makes it and the
// batch runner, results.csv and --resume read it.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace signalsim {

/// One run of a batch or sweep.
struct RunSpec {
  std::size_t index = 0;
  std::string scenario;                                     ///< the scenario file
  std::string name;  ///< the scenario file's stem, or a swept `name` (run directory, progress lines)
  std::vector<std::pair<std::string, std::string>> values;  ///< swept key -> value, sweep order
  std::vector<std::string> set;                             ///< every --set item for the run
};

}  // namespace signalsim
