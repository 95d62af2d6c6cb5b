// Parameters and `--set` keys as JSON Schema definitions.
#include "scenario/parameter_json_schema.hpp"

#include <map>
#include <stdexcept>
#include <variant>
#include <vector>

#include "scenario/parameters.hpp"
#include "scenario/scenario_keys.hpp"

namespace signalsim {
namespace {

std::vector<std::string> split(const std::string& dotted) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t dot; (dot = dotted.find('.', start)) != std::string::npos; start = dot + 1)
    parts.push_back(dotted.substr(start, dot - start));
  parts.push_back(dotted.substr(start));
  return parts;
}

std::string joined(const std::vector<std::string>& parts, std::size_t from, std::size_t to) {
  std::string out;
  for (std::size_t i = from; i < to; ++i) out += (i == from ? "" : ".") + parts[i];
  return out;
}

// The names a parameter is found by (find_parameter): signalsim's, and Autoware's place.
std::vector<std::string> spellings(const ParameterSpec& spec) {
  std::vector<std::string> out = {spec.name};
  if (!spec.autoware_key.empty()) out.push_back(spec.autoware_key);
  return out;
}

SchemaJson parameter_schema_of(const ParameterSpec& spec) {
  std::string description = spec.unit == "-" ? "" : "[" + spec.unit + "] ";
  // "docs/behaviour.md §T10" is where the rule is described; "signalsim: ..." says what signalsim's
  // own parameter does.
  const bool own = spec.spec_section.rfind("signalsim", 0) == 0;
  description += (own ? "" : "See ") + spec.spec_section + ".";
  if (!spec.autoware_key.empty()) description += " In Autoware's files: " + spec.autoware_key + ".";
  SchemaJson s = {{"description", description}};
  std::visit(
      [&](const auto& value) {
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, bool>) {
          s["type"] = "boolean";
        } else if constexpr (std::is_same_v<T, std::string>) {
          if (spec.choices.empty()) s["type"] = "string";
          else s["enum"] = spec.choices;
        } else {
          s["type"] = std::is_same_v<T, int> ? "integer" : "number";
          if constexpr (std::is_same_v<T, int>) {
            s["minimum"] = static_cast<long long>(spec.min);
            s["maximum"] = static_cast<long long>(spec.max);
          } else {
            s["minimum"] = spec.min;
            s["maximum"] = spec.max;
          }
        }
        s["default"] = value;
      },
      spec.default_value);
  return s;
}

// A mapping level of parameter names: at each level a key is any dotted prefix of a spelling's
// rest (`traffic_light.v2i`, `traffic_light`, ...): a leaf when it is the whole rest.
struct NameTree {
  std::map<std::string, std::string> leaves;  // key -> parameter name
  std::map<std::string, NameTree> groups;     // key -> the level below

  void add(const std::vector<std::string>& parts, std::size_t from, const std::string& parameter) {
    for (std::size_t to = from + 1; to <= parts.size(); ++to) {
      const std::string key = joined(parts, from, to);
      if (to == parts.size()) leaves[key] = parameter;
      else groups[key].add(parts, to, parameter);
    }
  }

  SchemaJson schema() const {
    SchemaJson properties = SchemaJson::object();
    std::map<std::string, SchemaJson> sorted;
    for (const auto& [key, parameter] : leaves) sorted[key] = {{"$ref", definition_ref("parameter." + parameter)}};
    for (const auto& [key, group] : groups) {
      if (leaves.count(key)) throw std::logic_error("parameter '" + key + "' is also a group of parameters");
      sorted[key] = group.schema();
    }
    for (auto& [key, value] : sorted) properties[key] = std::move(value);
    return {{"type", "object"}, {"properties", properties}, {"additionalProperties", false}};
  }
};

// The `--set` keys, each with the schema of its value: scenario key paths (their own schema, kept
// as the definition "setting.<path>"), `params.set.<parameter>` and bare parameter names (the
// parameter's definition), and `light_offsets.<tls>` (a pattern).
struct OverrideKeys {
  std::map<std::string, SchemaJson> settings;  // scenario path -> its value's schema
  std::map<std::string, SchemaJson> keys;      // every key -> a $ref
  std::map<std::string, SchemaJson> patterns;  // key pattern -> its value's schema
};

void add_scenario_keys(const KeyTable& table, const std::string& prefix, OverrideKeys& out) {
  for (const KeySpec& key : table.keys) {
    const std::string path = prefix + key.name;
    switch (key.type) {
      case KeyType::Mapping:
        add_scenario_keys(*key.table, path + ".", out);
        break;
      case KeyType::NumberMapping:  // light_offsets.<tls>: one level of free names
        out.patterns["^" + path + "\\.[^.]+$"] = {{"description", key.description}, {"type", "number"}};
        break;
      case KeyType::Parameters:  // params.set.<parameter>
        for (const ParameterSpec& spec : parameter_schema())
          for (const std::string& name : spellings(spec))
            out.keys[path + "." + name] = {{"$ref", definition_ref("parameter." + spec.name)}};
        break;
      default:
        out.settings[path] = key_schema(key);
        out.keys[path] = {{"$ref", definition_ref("setting." + path)}};
    }
  }
}

OverrideKeys override_keys() {
  OverrideKeys out;
  add_scenario_keys(scenario_keys(), "", out);
  for (const ParameterSpec& spec : parameter_schema())
    for (const std::string& name : spellings(spec)) out.keys[name] = {{"$ref", definition_ref("parameter." + spec.name)}};
  return out;
}

SchemaJson override_mapping(const OverrideKeys& overrides, bool lists) {
  const auto value = [&](const SchemaJson& schema) -> SchemaJson {
    if (!lists) return schema;
    return {{"type", "array"}, {"minItems", 1}, {"items", schema}};
  };
  SchemaJson properties = SchemaJson::object(), pattern_properties = SchemaJson::object();
  for (const auto& [key, schema] : overrides.keys) properties[key] = value(schema);
  for (const auto& [pattern, schema] : overrides.patterns) pattern_properties[pattern] = value(schema);
  SchemaJson s = {{"type", "object"}};
  s["description"] = lists ? "`--set` keys (scenario key paths or parameter names), each with a list of values."
                           : "`--set` keys (scenario key paths or parameter names), each with one value.";
  if (lists) s["minProperties"] = 1;
  s["properties"] = properties;
  s["patternProperties"] = pattern_properties;
  s["additionalProperties"] = false;
  return s;
}

}  // namespace

std::string definition_ref(const std::string& name) { return "#/definitions/" + name; }

SchemaJson parameter_definitions() {
  SchemaJson definitions = SchemaJson::object();
  NameTree tree;
  std::map<std::string, SchemaJson> leaves;
  for (const ParameterSpec& spec : parameter_schema()) {
    leaves["parameter." + spec.name] = parameter_schema_of(spec);
    for (const std::string& name : spellings(spec)) tree.add(split(name), 0, spec.name);
  }
  SchemaJson parameters = tree.schema();
  parameters["description"] =
      "Parameters with Autoware's names: signalsim's name or the place Autoware's files keep it, nested or dotted.";
  definitions["parameters"] = parameters;
  for (auto& [name, schema] : leaves) definitions[name] = std::move(schema);
  return definitions;
}

SchemaJson override_definitions() {
  const OverrideKeys overrides = override_keys();
  SchemaJson definitions = {{"override_values", override_mapping(overrides, false)},
                            {"override_lists", override_mapping(overrides, true)}};
  for (const auto& [path, schema] : overrides.settings) definitions["setting." + path] = schema;
  return definitions;
}

}  // namespace signalsim
