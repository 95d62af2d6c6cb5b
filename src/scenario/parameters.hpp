// Parameter sets with Autoware's names: a fixed schema (name, type, default, range), filled from
// parameter files and inline overrides, each value checked where it is read.
#pragma once

#include <map>
#include <string>
#include <variant>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "traffic_light/traffic_light_judge.hpp"
#include "turn_signal/behavior_signal.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

using ParameterValue = std::variant<bool, int, double, std::string>;

struct ParameterSpec {
  std::string name;                   ///< Autoware name; nested Autoware keys joined with '.'
  ParameterValue default_value;
  double min = -1e300;                ///< inclusive bounds for numbers
  double max = 1e300;
  std::vector<std::string> choices;   ///< allowed values for strings (empty: any)
  std::string unit;                   ///< "m", "s", "deg", "m/s", ... or "-"
  std::string spec_section;           ///< where the parameter is defined, e.g. "TSD §10"
};

/// Every parameter signalsim knows, in a fixed order.
const std::vector<ParameterSpec>& parameter_schema();

/// Resolved values: every schema entry present. Each entry remembers where its value came from.
class ParameterSet {
 public:
  ParameterSet();  ///< the schema defaults

  /// Applies a YAML mapping (flat keys, nested maps joined with '.', an optional Autoware
  /// `/**: ros__parameters:` wrapper). Throws InputError naming `origin`, the line and the key for
  /// an unknown key, a wrong type or an out-of-range value.
  void apply(const YAML::Node& mapping, const std::string& origin);
  /// Reads a parameter file and applies it. Throws InputError (missing file, malformed YAML, ...).
  void apply_file(const std::string& path);

  double number(const std::string& name) const;
  int integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& text(const std::string& name) const;

  /// name -> value, in schema order, for summaries.
  const std::map<std::string, ParameterValue>& values() const { return values_; }
  const std::string& origin(const std::string& name) const { return origins_.at(name); }

 private:
  void apply_node(const YAML::Node& node, const std::string& prefix, const std::string& origin);
  void check_consistency(const std::string& origin) const;
  std::map<std::string, ParameterValue> values_;
  std::map<std::string, std::string> origins_;
};

/// The judge's parameters from a resolved set.
TrafficLightJudgeParameters traffic_light_parameters(const ParameterSet& set);

/// The behaviour modules' parameters (spec TSD §8.2) from a resolved set: the decider's shared values
/// plus the module parameters of the schema and the ego's footprint.
BehaviorSignalParameters behavior_parameters(const ParameterSet& set, const TurnSignalParameters& decider,
                                             double vehicle_length, double vehicle_width);

/// The decider's parameters from a resolved set.
TurnSignalParameters turn_signal_parameters(const ParameterSet& set, double base_link_to_front);

}  // namespace signalsim
