// Where a parameter sits in a YAML mapping: the keys of a parameter file flattened to dotted names
// (nested maps and dotted keys are the same key), each parameter found by signalsim's name or by the
// place Autoware's shipped file keeps it (`lane_change.trajectory.max_prepare_duration`), and a
// "did you mean" for a key that is nearly a known one.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scenario/parameters.hpp"

namespace signalsim {

/// One leaf of a parameter mapping: its dotted name, its value node and the line of its key.
struct FlatParameter {
  std::string name;
  YAML::Node value;
  int line = 0;
};

/// The parameter mappings of a file: each node section's `ros__parameters` of a ROS parameter file
/// (`/**:` or `<node>:` sections; several are all applied), else the mapping itself; none for an
/// empty file or `/**:` alone. Throws InputError (naming `file` and the line) for a mapping that is
/// not one, a section with a key beside ros__parameters (a misspelt `ros_parameters`: "did you mean"),
/// or a ros__parameters that is not a mapping.
std::vector<YAML::Node> parameter_sections(const YAML::Node& mapping, const std::string& file);

/// The leaves of every section of a parameter document (parameter_sections, then
/// flatten_parameters of each), in file order.
std::vector<FlatParameter> document_parameters(const YAML::Node& document, const std::string& file);

/// The leaves of `mapping`, in file order: a map value is descended into (its keys joined with '.'),
/// any other value (scalar, list, null) is a leaf. Throws InputError (naming `file`) for a key that
/// is not a plain scalar or a key repeated in one mapping.
std::vector<FlatParameter> flatten_parameters(const YAML::Node& mapping, const std::string& file);

/// The schema entry named `key`: its signalsim name or its Autoware place (`ParameterSpec::autoware_key`).
const ParameterSpec* find_parameter(const std::string& key);

/// A known name `key` was probably meant to be, for an unknown key: one edit away (a typo), or the
/// same parameter name under the same module namespace but at another depth
/// (`lane_change.max_prepare_duration` for `lane_change.trajectory.max_prepare_duration`). Keys of
/// Autoware's files that signalsim does not use (`...min_longitudinal_acc` beside the known
/// `...max_longitudinal_acc`, two edits apart) are not suggestions.
std::optional<std::string> suggest_parameter(const std::string& key);

/// True when `key` is the module namespace (or a nested group) of known parameters, e.g.
/// `traffic_light` or `lane_change.trajectory`: such a key must hold a mapping.
bool is_parameter_group(const std::string& key);

/// Damerau-Levenshtein distance (adjacent transpositions count as one edit).
std::size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace signalsim
