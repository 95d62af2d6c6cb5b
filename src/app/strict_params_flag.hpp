// --strict-params: the command-line form of the scenario key `params.strict: true` (every key of a
// parameter file must be one signalsim uses). It becomes an override, so batch workers inherit it.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace signalsim::app {

inline constexpr const char* kStrictParamsOverride = "params.strict=true";

inline void add_strict_params_flag(CLI::App* sub, std::vector<std::string>& overrides) {
  sub->add_flag_callback(
      "--strict-params", [&overrides] { overrides.push_back(kStrictParamsOverride); },
      "Refuse every key of a parameter file that signalsim does not use (default: list them in a note)");
}

}  // namespace signalsim::app
