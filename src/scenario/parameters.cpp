#include "scenario/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

#include "scenario/autoware_key_table.hpp"
#include "scenario/input_error.hpp"
#include "scenario/parameter_keys.hpp"
#include "core/number_parsing.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {

int line_of(const YAML::Node& node) { return node.Mark().line >= 0 ? node.Mark().line + 1 : 0; }

// Converts a scalar to the spec's type, or explains why not. `key` is the name as written.
ParameterValue convert(const ParameterSpec& spec, const std::string& key_as_written, const YAML::Node& node,
                       int key_line, const std::string& file) {
  const int line = node.IsScalar() ? line_of(node) : key_line;
  const std::string key = "parameter '" + key_as_written + "'";
  if (!node.IsScalar())
    throw InputError(file, line, key + ": expected a single value, got " + (node.IsSequence() ? "a list" : "nothing"));
  const std::string raw = node.Scalar();
  auto fail_type = [&](const char* expected) {
    throw InputError(file, line, key + ": expected " + expected + ", got '" + raw + "'");
  };
  auto check_range = [&](double x) {
    if (!std::isfinite(x) || x < spec.min || x > spec.max)
      throw InputError(file, line, key + ": value " + raw + " is out of range [" + short_number(spec.min) + ", " +
                                       short_number(spec.max) + "]");
  };
  if (std::holds_alternative<bool>(spec.default_value)) {
    bool value = false;
    if (!YAML::convert<bool>::decode(node, value)) fail_type("true or false");
    return value;
  }
  if (std::holds_alternative<int>(spec.default_value)) {
    int value = 0;
    if (!YAML::convert<int>::decode(node, value)) fail_type("an integer");
    check_range(value);
    return value;
  }
  if (std::holds_alternative<double>(spec.default_value)) {
    double value = 0.0;
    if (node.Tag() == "!" || !YAML::convert<double>::decode(node, value)) fail_type("a number");
    check_range(value);  // NaN and infinities are out of every range
    std::string reason;
    if (!yaml_number(node, reason)) throw InputError(file, line, key + ": " + reason);  // a subnormal
    return value;
  }
  if (!spec.choices.empty() &&
      std::find(spec.choices.begin(), spec.choices.end(), raw) == spec.choices.end()) {
    std::string allowed;
    for (const auto& c : spec.choices) allowed += (allowed.empty() ? "" : ", ") + c;
    throw InputError(file, line, key + ": '" + raw + "' is not one of " + allowed);
  }
  return raw;
}

}  // namespace

ParameterSet::ParameterSet() {
  for (const ParameterSpec& spec : parameter_schema()) {
    values_[spec.name] = spec.default_value;
    origins_[spec.name] = "default";
  }
}

void ParameterSet::apply(const YAML::Node& mapping, const ParameterOrigin& origin) {
  apply_parameters(document_parameters(mapping, origin.file), origin);
}

void ParameterSet::apply_parameters(const std::vector<FlatParameter>& flat, const ParameterOrigin& origin) {
  const std::string& file = origin.file;
  std::map<std::string, const FlatParameter*> given;  // schema name -> where this mapping gave it
  std::vector<std::string> unused;
  for (const FlatParameter& entry : flat) {
    const ParameterSpec* spec = find_parameter(entry.name);
    if (!spec) {
      if (is_parameter_group(entry.name))
        throw InputError(file, entry.line, "'" + entry.name + "' must be a mapping of parameters, got " +
                                               (entry.value.IsSequence() ? "a list" : "a single value"));
      if (const auto near = suggest_parameter(entry.name))
        throw InputError(file, entry.line, "unknown parameter '" + entry.name + "' (did you mean '" + *near + "'?)");
      if (!origin.is_file) throw InputError(file, entry.line, "unknown parameter '" + entry.name + "'");
      // Strict: a key of Autoware's file of that name is listed, one Autoware dropped is a warning, any
      // other an error.
      const std::string autoware_file = std::filesystem::path(file).filename().string();
      if (const auto warning = origin.strict ? strict_key_warning(autoware_key_tables(), autoware_file, file,
                                                                  entry.line, entry.name, "parameter")
                                             : std::nullopt) {
        warnings_.push_back(*warning);
        continue;
      }
      unused.push_back(entry.name);
      continue;
    }
    // Nested and dotted spellings, signalsim's name and Autoware's place: all one parameter.
    if (const auto first = given.find(spec->name); first != given.end()) {
      const FlatParameter& earlier = *first->second;
      throw InputError(file, entry.line, "parameter '" + entry.name + "' is given twice (" +
                                             (earlier.name == entry.name ? "lines " + std::to_string(earlier.line) + " and " +
                                                                               std::to_string(entry.line)
                                                                         : "also as '" + earlier.name + "'" +
                                                                               (earlier.line > 0 ? " at line " + std::to_string(earlier.line) : "")) +
                                             ")");
    }
    given[spec->name] = &entry;
    ParameterValue value = convert(*spec, entry.name, entry.value, entry.line, file);
    if (spec->name == "enable_rtc" && std::get<bool>(value))
      throw InputError(file, entry.line,
                       "parameter '" + entry.name + "': true is not supported (no operator approves in simulation)");
    values_[spec->name] = std::move(value);
    origins_[spec->name] = origin.label.empty() ? file + ":" + std::to_string(entry.line) : origin.label;
  }
  if (origin.is_file && !unused.empty()) unused_.push_back({file, std::move(unused)});
}

void ParameterSet::check_consistency(const std::string& file) const {
  // Checked on the final values (after every file, preset and override): a later layer may mend
  // what an earlier one set.
  const auto inverted = [&](const char* low, const char* high, const char* rule) {
    if (number(low) <= number(high)) return;
    throw InputError(file, 0, std::string(low) + " " + short_number(number(low)) + " (" + origin(low) +
                                  ") is greater than " + high + " " + short_number(number(high)) + " (" +
                                  origin(high) + ")" + rule);
  };
  inverted("restart_suppression.min_behind_distance_to_stop", "restart_suppression.max_behind_distance_to_stop",
           " (docs/behaviour.md §L1.6: the restart-suppression window)");
  inverted("min_prepare_duration", "max_prepare_duration", " (docs/behaviour.md §T8.2: the prepare duration lies in [min, max])");
}

void ParameterSet::apply_file(const std::string& path, bool strict) {
  apply(load_shared_yaml_file(path, "parameter file"), ParameterOrigin{path, "", true, strict});
}

double ParameterSet::number(const std::string& name) const {
  const ParameterValue& v = values_.at(name);
  if (const int* i = std::get_if<int>(&v)) return *i;
  return std::get<double>(v);
}
int ParameterSet::integer(const std::string& name) const { return std::get<int>(values_.at(name)); }
bool ParameterSet::boolean(const std::string& name) const { return std::get<bool>(values_.at(name)); }
const std::string& ParameterSet::text(const std::string& name) const {
  return std::get<std::string>(values_.at(name));
}

TurnSignalParameters turn_signal_parameters(const ParameterSet& set, double base_link_to_front) {
  TurnSignalParameters p;
  p.base_link_to_front = base_link_to_front;
  p.turn_signal_intersection_search_distance = set.number("turn_signal_intersection_search_distance");
  p.turn_signal_intersection_angle_threshold_deg = set.number("turn_signal_intersection_angle_threshold_deg");
  p.turn_signal_search_time = set.number("turn_signal_search_time");
  p.turn_signal_minimum_search_distance = set.number("turn_signal_minimum_search_distance");
  p.turn_signal_path_backward_length = set.number("turn_signal_path_backward_length");
  p.forward_path_length = set.number("forward_path_length");
  p.turn_signal_roundabout_on_entry = set.text("turn_signal_roundabout_on_entry");
  p.turn_signal_roundabout_on_exit = set.text("turn_signal_roundabout_on_exit");
  p.turn_signal_roundabout_entry_indicator_persistence =
      set.boolean("turn_signal_roundabout_entry_indicator_persistence");
  p.turn_signal_roundabout_search_distance = set.number("turn_signal_roundabout_search_distance");
  p.turn_signal_roundabout_angle_threshold_deg = set.number("turn_signal_roundabout_angle_threshold_deg");
  p.turn_signal_roundabout_backward_depth = set.integer("turn_signal_roundabout_backward_depth");
  p.turn_signal_shift_length_threshold = set.number("turn_signal_shift_length_threshold");
  p.turn_signal_remaining_shift_length_threshold = set.number("turn_signal_remaining_shift_length_threshold");
  p.turn_signal_remaining_distance_to_bound_threshold =
      set.number("turn_signal_remaining_distance_to_bound_threshold");
  p.turn_signal_on_swerving = set.boolean("turn_signal_on_swerving");
  p.turn_signal_roundabout_exit_signal_from_previous_exit =
      set.boolean("turn_signal_roundabout_exit_signal_from_previous_exit");
  return p;
}

BehaviorSignalParameters behavior_parameters(const ParameterSet& set, const TurnSignalParameters& decider,
                                             double vehicle_length, double vehicle_width) {
  BehaviorSignalParameters p = behavior_signal_parameters(decider);
  p.rear_overhang = vehicle_length - decider.base_link_to_front;
  p.vehicle_width = vehicle_width;
  p.min_length_for_turn_signal_activation = set.number("min_length_for_turn_signal_activation");
  p.max_prepare_duration = set.number("max_prepare_duration");
  p.min_prepare_duration = set.number("min_prepare_duration");
  p.min_lane_changing_velocity = set.number("min_lane_changing_velocity");
  p.max_longitudinal_acc = set.number("max_longitudinal_acc");
  p.lane_change_required_end_at_boundary = set.boolean("lane_change_required_end_at_boundary");
  p.max_prepare_time = set.number("max_prepare_time");
  // The schema admits only the four names (a file with another gets its line and the choices).
  p.candidate_path_turn_signal = candidate_turn_signal_policy(set.text("candidate_path_turn_signal")).value();
  p.turn_signal_on_approval_hold_duration = set.number("turn_signal_on_approval_hold_duration");
  p.turn_signal_on_centerline_start = set.text("turn_signal_on_centerline_start");
  p.minimum_shift_length = set.number("minimum_shift_length");
  p.th_distance_to_middle_of_the_road = set.number("th_distance_to_middle_of_the_road");
  p.prepare_time_before_start = set.number("prepare_time_before_start");
  p.enable_back = set.boolean("enable_back");
  return p;
}

TrafficLightJudgeParameters traffic_light_parameters(const ParameterSet& set) {
  TrafficLightJudgeParameters p;
  p.stop_margin = set.number("stop_margin");
  p.tl_state_timeout = set.number("tl_state_timeout");
  p.stop_time_hysteresis = set.number("stop_time_hysteresis");
  p.yellow_lamp_period = set.number("yellow_lamp_period");
  p.yellow_light_stop_velocity = set.number("yellow_light_stop_velocity");
  p.enable_pass_judge = set.boolean("enable_pass_judge");
  p.is_simulation = set.boolean("is_simulation");
  p.restart_suppression.min_behind_distance_to_stop = set.number("restart_suppression.min_behind_distance_to_stop");
  p.restart_suppression.max_behind_distance_to_stop = set.number("restart_suppression.max_behind_distance_to_stop");
  p.enable_arrow_aware_yellow_passing = set.boolean("enable_arrow_aware_yellow_passing");
  p.max_accel = set.number("max_accel");
  p.max_jerk = set.number("max_jerk");
  p.delay_response_time = set.number("delay_response_time");
  p.v2i.use_remaining_time = set.boolean("v2i.use_remaining_time");  // docs/behaviour.md §L1.7
  p.v2i.last_time_allowed_to_pass = set.number("v2i.last_time_allowed_to_pass");
  p.v2i.velocity_threshold = set.number("v2i.velocity_threshold");
  p.v2i.required_time_to_departure = set.number("v2i.required_time_to_departure");
  p.stop_release_confirmation_time = set.number("stop_release_confirmation_time");  // signalsim's own
  return p;
}

RunParameters run_parameters(const ParameterSet& set) {
  RunParameters r;
  r.decider = turn_signal_parameters(set, r.decider.base_link_to_front);
  const BehaviorSignalParameters footprint;  // the struct's: the ego's is set per scenario
  r.behavior = behavior_parameters(set, r.decider, 0.0, footprint.vehicle_width);
  r.behavior.rear_overhang = footprint.rear_overhang;
  r.judge = traffic_light_parameters(set);
  r.lane_change_safety_rear_gap = set.number("lane_change_safety_rear_gap");
  r.lane_change_safety_front_gap = set.number("lane_change_safety_front_gap");
  r.stuck_rest_time = set.number("stuck_rest_time");
  return r;
}

}  // namespace signalsim
