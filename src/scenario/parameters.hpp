// Parameter sets with Autoware's names: a fixed schema (name, type, default, range), filled from
// parameter files and inline overrides, each value checked where it is read; and the typed structs
// made from a resolved set (RunParameters), the only form the rooms above scenario/ read.
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
struct FlatParameter;  // scenario/parameter_keys.hpp

struct ParameterSpec {
  std::string name;                   ///< Autoware name; nested Autoware keys joined with '.'
  ParameterValue default_value;
  double min = -1e300;                ///< inclusive bounds for numbers
  double max = 1e300;
  std::vector<std::string> choices;   ///< allowed values for strings (empty: any)
  std::string unit;                   ///< "m", "s", "deg", "m/s", ... or "-"
  std::string spec_section;           ///< where the parameter is defined, e.g. "docs/behaviour.md §T10"
  /// Where Autoware's shipped parameter file keeps it, module namespace included
  /// (`lane_change.trajectory.max_prepare_duration`); empty when that is `name` itself (a top-level
  /// key of its file, e.g. behavior_path_planner.param.yaml's) or signalsim's own parameter.
  std::string autoware_key;
};

/// Where a mapping of parameters comes from, for messages, strictness and the summary.
struct ParameterOrigin {
  std::string file;   ///< named in messages ("--set" for the command line)
  /// How the summary names the source of a value: empty for "<file>:<line>" (a parameter file),
  /// else e.g. "country jp", "set", "--set".
  std::string label;
  /// A parameter file (Autoware's, as shipped): keys signalsim does not use are listed, not refused;
  /// `strict` checks them against Autoware's keys of the file (scenario/autoware_key_table.hpp). Any
  /// other mapping (a country preset, params.set, --set) refuses every key signalsim does not use.
  bool is_file = false;
  bool strict = true;
};

/// The keys of one parameter file that signalsim does not use (not an error; listed once).
struct UnusedParameters {
  std::string file;
  std::vector<std::string> keys;  ///< dotted names, in file order
};

/// Every parameter signalsim knows, in a fixed order.
const std::vector<ParameterSpec>& parameter_schema();

/// Resolved values: every schema entry present. Each entry remembers where its value came from.
class ParameterSet {
 public:
  ParameterSet();  ///< the schema defaults

  /// Applies a YAML mapping (flat keys, nested maps and dotted keys alike, an optional Autoware
  /// `/**: ros__parameters:` wrapper). A parameter is found by signalsim's name or by its Autoware
  /// place (ParameterSpec::autoware_key). Throws InputError naming the origin's file, the line and
  /// the key as written for a wrong type, an out-of-range value, a parameter given twice, a key
  /// close to a known name ("did you mean"), and, when strict, a key Autoware's file of that name
  /// does not have either (scenario/autoware_key_table.hpp; one Autoware dropped is a warning).
  void apply(const YAML::Node& mapping, const ParameterOrigin& origin);
  /// A strict mapping named `file` in messages and summaries (a preset, params.set, --set).
  void apply(const YAML::Node& mapping, const std::string& file) { apply(mapping, ParameterOrigin{file, file}); }
  /// Reads a parameter file and applies it (keys signalsim does not use are listed; `strict` checks
  /// them against Autoware's). Throws InputError (missing file, malformed YAML, ...).
  void apply_file(const std::string& path, bool strict);

  double number(const std::string& name) const;
  int integer(const std::string& name) const;
  bool boolean(const std::string& name) const;
  const std::string& text(const std::string& name) const;

  /// name -> value, sorted by name (parameter_schema() has the schema's order), for summaries.
  const std::map<std::string, ParameterValue>& values() const { return values_; }
  /// Where the value of `name` came from: "default", "<file>:<line>", "country jp", "set", "--set".
  const std::string& origin(const std::string& name) const { return origins_.at(name); }
  /// The rules between parameters (a window's min <= max), on the values as they are now: call once
  /// after the last apply. Throws InputError naming `file` and both values' origins.
  void check_consistency(const std::string& file) const;
  /// Per parameter file applied with unknown keys allowed: the keys signalsim does not use.
  const std::vector<UnusedParameters>& unused() const { return unused_; }
  /// One line per key of a strict parameter file that Autoware dropped ("<file>:<line>: ...").
  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  void apply_parameters(const std::vector<FlatParameter>& flat, const ParameterOrigin& origin);
  std::map<std::string, ParameterValue> values_;
  std::map<std::string, std::string> origins_;
  std::vector<UnusedParameters> unused_;
  std::vector<std::string> warnings_;
};

/// A resolved set as typed values with units: everything the decider, the behaviour modules, the
/// judge and the run read. Made once from a resolved set (run_parameters(); a scenario keeps it as
/// Scenario::run_params when it is read); outside scenario/ no parameter is read by its name.
/// The ego's footprint is not a parameter: `decider.base_link_to_front` and the footprint fields of
/// `behavior` keep their struct defaults here, and turn_signal_parameters(const Scenario&) /
/// behavior_parameters(const Scenario&) (scenario.hpp) give the structs with the ego's.
struct RunParameters {
  TurnSignalParameters decider;        ///< the turn-signal decider's (docs/behaviour.md §T10)
  BehaviorSignalParameters behavior;   ///< lane change, avoidance, start planner (docs/behaviour.md §T8.2)
  TrafficLightJudgeParameters judge;   ///< the traffic-light judge's (docs/behaviour.md §L4)
  /// [m] the target lane is kept free this far behind the rear bumper before a lane change is approved.
  double lane_change_safety_rear_gap = 10.0;
  /// [m] the target lane is kept free this far beyond the lane change's end before it is approved.
  double lane_change_safety_front_gap = 10.0;
  /// [s] the ego at rest this long while signalsim commands it to drive ends the run as not arrived (0: off).
  double stuck_rest_time = 60.0;

  bool operator==(const RunParameters&) const = default;
};

/// The typed form of a resolved set (every field from its schema entry).
RunParameters run_parameters(const ParameterSet& set);

/// The judge's parameters from a resolved set.
TrafficLightJudgeParameters traffic_light_parameters(const ParameterSet& set);

/// The behaviour modules' parameters (docs/behaviour.md §T8.2) from a resolved set: the decider's shared values
/// plus the module parameters of the schema and the ego's footprint.
BehaviorSignalParameters behavior_parameters(const ParameterSet& set, const TurnSignalParameters& decider,
                                             double vehicle_length, double vehicle_width);

/// The decider's parameters from a resolved set.
TurnSignalParameters turn_signal_parameters(const ParameterSet& set, double base_link_to_front);

}  // namespace signalsim
