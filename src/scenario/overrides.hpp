// `--set key=value` overrides (the command line, a sweep): applied to the scenario's YAML tree before
// it is read, or collected as parameters when the key is not a scenario key.
#pragma once

#include <map>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenario/scenario.hpp"

namespace signalsim {

/// Whether `key` is a top-level key of a scenario file (scenario_keys); any other head of an
/// override key is a parameter name.
bool is_scenario_key(const std::string& key);

/// `root` with every override whose head is a scenario key set at its path (`ego.max_speed=10`
/// creates ego: when missing), or appended to the list there for `key+=value` (each item of a list
/// value; `params.files+=/abs/candidate.yaml` creates params.files: when missing); the others are
/// added to `parameters` (name -> value). Values are parsed as YAML. Throws InputError ("--set", no
/// line) for an item that is not key=value, an empty or malformed value, text that is not UTF-8 or
/// holds a control character, a path through a value that is not a mapping, += on a value that is not
/// a list or on a parameter. The values carry no lines (they are not the file's), and `set_items`, when
/// given, gets the key path each scenario key override set -> its item (scenario/key_origins.hpp).
YAML::Node apply_overrides(YAML::Node root, const ScenarioOverrides& overrides, YAML::Node& parameters,
                           std::map<std::string, std::string>* set_items = nullptr);

/// Whether `file`, an InputError's, is the overrides' own input rather than a scenario's: "--set" or
/// "--set <item>" (a value an override gave), or a file an override appends to a list
/// (`params.files+=FILE`, --params). Every scenario would fail alike.
bool is_override_input(const std::string& file, const ScenarioOverrides& overrides);

}  // namespace signalsim
