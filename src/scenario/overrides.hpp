// `--set key=value` overrides (the command line, a sweep): applied to the scenario's YAML tree before
// it is read, or collected as parameters when the key is not a scenario key.
#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

#include "scenario/scenario.hpp"

namespace signalsim {

/// Whether `key` is a top-level key of a scenario file (scenario_keys); any other head of an
/// override key is a parameter name.
bool is_scenario_key(const std::string& key);

/// `root` with every override whose head is a scenario key set at its path (`ego.max_speed=10`
/// creates ego: when missing); the others are added to `parameters` (name -> value). Values are
/// parsed as YAML. Throws InputError ("--set", no line) for an item that is not key=value, an empty
/// or malformed value, text that is not UTF-8, or a path through a value that is not a mapping.
YAML::Node apply_overrides(YAML::Node root, const ScenarioOverrides& overrides, YAML::Node& parameters);

}  // namespace signalsim
