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

// The parameters of a mapping: inside Autoware's `<node>: ros__parameters:` wrapper (`/**` for
// every node) when there is one.
YAML::Node unwrap_ros_parameters(const YAML::Node& mapping, const std::string& file) {
  if (!mapping.IsMap()) throw InputError(file, yaml_line(mapping), "parameters must be a mapping of name: value");
  if (mapping.size() != 1) return mapping;
  const auto only = *mapping.begin();
  if (!only.second.IsMap() || !only.second["ros__parameters"]) return mapping;
  for (const auto& entry : only.second)
    if (entry.first.Scalar() != "ros__parameters")
      throw InputError(file, yaml_line(entry.first), "unknown key '" + only.first.Scalar() + "." + entry.first.Scalar() +
                                                       "' beside ros__parameters");
  const YAML::Node parameters = only.second["ros__parameters"];
  if (parameters.IsNull()) return YAML::Node(YAML::NodeType::Map);
  if (!parameters.IsMap())
    throw InputError(file, yaml_line(parameters), "'" + only.first.Scalar() + ".ros__parameters' must be a mapping of name: value, got " +
                                                    (parameters.IsSequence() ? "a list" : "'" + parameters.Scalar() + "'"));
  return parameters;
}

std::vector<FlatParameter> flatten_parameters(const YAML::Node& mapping, const std::string& file) {
  std::vector<FlatParameter> out;
  flatten_into(mapping, "", file, out);
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
  // The length test first (the distance is at least the length difference): a long key is not
  // compared cell by cell with every name (fuzzing: 0.4 s for one mutated file, mostly here).
  const auto within_one_length = [&](const std::string& known) {
    return key.size() <= known.size() + 1 && known.size() <= key.size() + 1;
  };
  for (const ParameterSpec& spec : parameter_schema())
    for (const std::string* known : {&spec.name, &spec.autoware_key})
      if (!known->empty() && within_one_length(*known) && edit_distance(key, *known) <= 1) return *known;
  // The right name at the wrong depth of a known module namespace.
  for (const ParameterSpec& spec : parameter_schema()) {
    const std::string& place = spec.autoware_key;
    if (place.find('.') == std::string::npos || key.find('.') == std::string::npos) continue;
    if (namespace_of(place) == namespace_of(key) && leaf_of(place) == leaf_of(key)) return place;
  }
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
