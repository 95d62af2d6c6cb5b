// --set, --params and --strict-params: the options that change every scenario of run, batch, check
// and compare. Each becomes an override (scenario/overrides.hpp), so batch workers inherit it:
//   --set K=V         a scenario key or a parameter, as given;
//   --params FILE...  `params.files+=FILE` (its absolute path: relative to the current directory, not to
//                     the scenario), after the scenario's own parameter files;
//   --strict-params   `params.strict=true`, the scenario key: every key of a parameter file is checked
//                     against Autoware's keys of that file (docs/parameters.md "Strict mode").
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <yaml-cpp/yaml.h>

namespace signalsim::app {

inline constexpr const char* kStrictParamsOverride = "params.strict=true";

inline const char* const kSetHelp = "Override for every run: a scenario key or a parameter (key=value); repeatable";

/// The override that appends the parameter file `path` (relative to the current directory) to a
/// scenario's params.files.
inline std::string params_file_override(const std::string& path) {
  YAML::Emitter quoted;  // a path is text, whatever YAML would make of it unquoted
  quoted << YAML::DoubleQuoted << std::filesystem::absolute(path).lexically_normal().string();
  return std::string("params.files+=") + quoted.c_str();
}

/// Adds --set (described by `set_help`), --params and --strict-params to `sub`, each collecting into
/// `overrides`. --set is added first: CLI11 assigns its values, the other two append theirs after.
inline void add_override_flags(CLI::App* sub, std::vector<std::string>& overrides, const std::string& set_help = kSetHelp) {
  sub->add_option("--set", overrides, set_help);
  sub->add_option_function<std::vector<std::string>>(
      "--params",
      [&overrides](const std::vector<std::string>& files) {
        for (const std::string& file : files) overrides.push_back(params_file_override(file));
      },
      "Parameter files (Autoware's as shipped, or signalsim's names) applied to every scenario after its own "
      "params.files; relative to the current directory");
  sub->add_flag_callback(
      "--strict-params", [&overrides] { overrides.push_back(kStrictParamsOverride); },
      "Check every key of a parameter file against Autoware's keys of that file: a key Autoware does not know "
      "is an error (default: keys signalsim does not use are listed in a note)");
}

}  // namespace signalsim::app
