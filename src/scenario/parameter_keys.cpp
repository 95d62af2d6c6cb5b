// Flattening parameter mappings, finding schema entries by either name, and typo suggestions.
#include "scenario/parameter_keys.hpp"

#include <algorithm>
#include <set>

#include "scenario/input_error.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {

void flatten_into(const YAML::Node& mapping, const std::string& prefix, const std::string& file,
                  std::vector<FlatParameter>& out) {
  std::set<std::string> seen;
  for (const auto& entry : mapping) {
    if (!entry.first.IsScalar() || entry.first.Scalar().empty())
      throw InputError(file, yaml_line(entry.first), "a parameter name must be a plain text key");
    const std::string key = entry.first.Scalar();
    const std::string name = prefix + key;
    if (!seen.insert(key).second) throw InputError(file, yaml_line(entry.first), "duplicate key '" + name + "'");
    if (entry.second.IsMap()) {
      flatten_into(entry.second, name + ".", file, out);
      continue;
    }
    out.push_back({name, entry.second, yaml_line(entry.first)});
  }
}

std::string namespace_of(const std::string& key) { return key.substr(0, key.find('.')); }
std::string leaf_of(const std::string& key) {
  const auto dot = key.rfind('.');
  return dot == std::string::npos ? key : key.substr(dot + 1);
}

}  // namespace

namespace {

bool is_wrapper_key(const std::string& key) { return key == "ros__parameters" || edit_distance(key, "ros__parameters") <= 2; }

// A ROS parameter file: some top-level value is a node section (`ros__parameters`, or nearly),
// or a top-level key is a node name pattern (`/**`, `/planning/...`).
bool is_ros_file(const YAML::Node& mapping) {
  for (const auto& entry : mapping) {
    if (entry.first.IsScalar() && entry.first.Scalar().rfind('/', 0) == 0) return true;
    if (entry.second.IsMap())
      for (const auto& inner : entry.second)
        if (inner.first.IsScalar() && is_wrapper_key(inner.first.Scalar())) return true;
  }
  return false;
}

}  // namespace

std::vector<YAML::Node> parameter_sections(const YAML::Node& mapping, const std::string& file) {
  if (!mapping || mapping.IsNull()) return {};
  if (!mapping.IsMap()) throw InputError(file, yaml_line(mapping), "parameters must be a mapping of name: value");
  if (!is_ros_file(mapping)) return {mapping};
  std::vector<YAML::Node> sections;
  for (const auto& node : mapping) {
    const std::string name = node.first.Scalar();
    if (node.second.IsNull()) continue;  // `/**:` with nothing under it
    if (!node.second.IsMap())
      throw InputError(file, yaml_line(node.first), "'" + name + "' must hold ros__parameters: (a ROS parameter file)");
    for (const auto& entry : node.second) {
      const std::string key = entry.first.Scalar();
      if (key == "ros__parameters") continue;
      throw InputError(file, yaml_line(entry.first), "unknown key '" + name + "." + key + "'" +
                                                       (is_wrapper_key(key) ? " (did you mean 'ros__parameters'?)"
                                                                            : " beside ros__parameters"));
    }
    const YAML::Node parameters = node.second["ros__parameters"];
    if (!parameters || parameters.IsNull()) continue;
    if (!parameters.IsMap())
      throw InputError(file, yaml_line(parameters), "'" + name + ".ros__parameters' must be a mapping of name: value, got " +
                                                      (parameters.IsSequence() ? "a list" : "'" + parameters.Scalar() + "'"));
    sections.push_back(parameters);
  }
  return sections;
}

std::vector<FlatParameter> flatten_parameters(const YAML::Node& mapping, const std::string& file) {
  std::vector<FlatParameter> out;
  flatten_into(mapping, "", file, out);
  return out;
}

std::vector<FlatParameter> document_parameters(const YAML::Node& document, const std::string& file) {
  std::vector<FlatParameter> out;
  for (const YAML::Node& section : parameter_sections(document, file)) flatten_into(section, "", file, out);
  return out;
}

const ParameterSpec* find_parameter(const std::string& key) {
  for (const ParameterSpec& spec : parameter_schema())
    if (spec.name == key || (!spec.autoware_key.empty() && spec.autoware_key == key)) return &spec;
  return nullptr;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::optional<std::string> suggest_parameter(const std::string& key) {
  // One edit on the whole name: measured on autoware_launch's shipped files, no key signalsim does
  // not use is one edit from a known name, while two edits already pair min_/max_ siblings.
  // A '.' for a '_' (or back) is another nesting, not a typo: path_generator.param.yaml's
  // `turn_signal.search_time` is its own parameter, not turn_signal_search_time.
  const auto same_but_nesting = [](const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i] != b[i] && !((a[i] == '.' && b[i] == '_') || (a[i] == '_' && b[i] == '.'))) return false;
    return true;
  };
  // The length test first (the distance is at least the length difference): a long key is not
  // compared cell by cell with every name (fuzzing: 0.4 s for one mutated file, mostly here).
  const auto within_one_length = [&](const std::string& known) {
    return key.size() <= known.size() + 1 && known.size() <= key.size() + 1;
  };
  for (const ParameterSpec& spec : parameter_schema())
    for (const std::string* known : {&spec.name, &spec.autoware_key})
      if (!known->empty() && within_one_length(*known) && edit_distance(key, *known) <= 1 &&
          !same_but_nesting(key, *known))
        return *known;
  // The right name at the wrong depth of a known module namespace.
  for (const ParameterSpec& spec : parameter_schema()) {
    const std::string& place = spec.autoware_key;
    if (place.find('.') == std::string::npos || key.find('.') == std::string::npos) continue;
    if (namespace_of(place) == namespace_of(key) && leaf_of(place) == leaf_of(key)) return place;
  }
  // A known parameter directly under another known module (`lane_change.stop_margin`,
  // `traffic_light.max_accel`): signalsim reads it only from its own place. Deeper keys of a module
  // may reuse a name for another parameter (start_planner...safety_check_params.forward_path_length).
  const std::string head = namespace_of(key);
  if (key.size() > head.size() && key.find('.', head.size() + 1) == std::string::npos && is_parameter_group(head))
    for (const ParameterSpec& spec : parameter_schema())
      if (leaf_of(key) == leaf_of(spec.name) || (!spec.autoware_key.empty() && leaf_of(key) == leaf_of(spec.autoware_key)))
        return spec.autoware_key.empty() ? spec.name : spec.autoware_key;
  return std::nullopt;
}

bool is_parameter_group(const std::string& key) {
  const std::string prefix = key + ".";
  for (const ParameterSpec& spec : parameter_schema())
    for (const std::string* known : {&spec.name, &spec.autoware_key})
      if (known->rfind(prefix, 0) == 0) return true;
  return false;
}

}  // namespace signalsim
