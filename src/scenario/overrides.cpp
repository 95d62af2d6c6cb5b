// Applying `--set` overrides to a scenario's YAML tree.
#include "scenario/overrides.hpp"

#include <map>

#include "scenario/input_error.hpp"
#include "scenario/scenario_keys.hpp"
#include "scenario/utf8_text.hpp"
#include "scenario/yaml_text.hpp"

namespace signalsim {

namespace {

// `mapping[key]` (a list, or absent) with `value` appended (each item of a list value); the key path
// of each appended item is recorded as given by `item` (`path` is the list's).
void append_to_list(YAML::Node& mapping, const std::string& key, const YAML::Node& value, const std::string& item,
                    const std::string& path, std::map<std::string, std::string>* set_items) {
  if (!mapping[key] || mapping[key].IsNull()) mapping[key] = YAML::Node(YAML::NodeType::Sequence);
  YAML::Node list = mapping[key];
  if (!list.IsSequence()) throw InputError("--set", 0, "'" + item + "': '" + key + "' is not a list");
  const auto push = [&](const YAML::Node& element) {
    if (set_items) (*set_items)[path + "[" + std::to_string(list.size()) + "]"] = item;
    list.push_back(element);
  };
  if (value.IsSequence())
    for (const YAML::Node& element : value) push(element);
  else
    push(value);
}

}  // namespace

bool is_scenario_key(const std::string& key) { return scenario_keys().find(key) != nullptr; }

YAML::Node apply_overrides(YAML::Node root, const ScenarioOverrides& overrides, YAML::Node& parameters,
                           std::map<std::string, std::string>* set_items) {
  for (const std::string& item : overrides.set) {
    if (const auto bad = find_invalid_utf8(item))
      throw InputError("--set", 0, "an override is not UTF-8 text: " + describe_invalid_utf8(item, *bad));
    if (const auto control = find_control_character(item, false))
      throw InputError("--set", 0, "an override holds " + describe_control_character(item, *control));
    const auto eq = item.find('=');
    // key+=value appends to a list of the scenario.
    const bool append = eq != std::string::npos && eq > 0 && item[eq - 1] == '+';
    if (eq == std::string::npos || eq == 0 || (append && eq == 1))
      throw InputError("--set", 0, "'" + item + "' is not of the form key=value");
    const std::string key = item.substr(0, append ? eq - 1 : eq);
    if (eq + 1 == item.size())
      throw InputError("--set", 0, "'" + item + "': empty value (write " + key + (append ? "+=" : "=") + "VALUE)");
    YAML::Node value;
    try {
      value = YAML::Load(item.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw InputError("--set", 0, "'" + item + "': malformed value: " + e.msg);
    }
    check_yaml_values(value, "--set", "'" + item + "'");
    // A value rebuilt without parse marks carries no line, so a message about it names no line of
    // the scenario file (it came from the command line; its marks would be the item's own).
    value = value.IsScalar() ? YAML::Node(value.Scalar()) : YAML::Clone(value);
    const std::string head = key.substr(0, key.find('.'));
    if (!is_scenario_key(head)) {
      if (append) throw InputError("--set", 0, "'" + item + "': += appends to a list of the scenario, and '" + key +
                                                   "' is a parameter");
      parameters[key] = value;
      continue;
    }
    // Walk (creating) the mapping path a.b.c and set its last element.
    YAML::Node node = root;
    std::size_t start = 0;
    while (true) {
      const std::size_t dot = key.find('.', start);
      const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      if (dot == std::string::npos) {
        if (append) {
          append_to_list(node, part, value, item, key, set_items);
        } else {
          node.remove(part);  // the file's key keeps its line: a new one has none
          node[part] = value;
          if (set_items) (*set_items)[key] = item;
        }
        break;
      }
      if (!node[part] || node[part].IsNull()) node[part] = YAML::Node(YAML::NodeType::Map);
      if (!node[part].IsMap()) throw InputError("--set", 0, "'" + key + "': '" + part + "' is not a mapping");
      YAML::Node child = node[part];
      node.reset(child);
      start = dot + 1;
    }
  }
  return root;
}

bool is_override_input(const std::string& file, const ScenarioOverrides& overrides) {
  if (file == "--set" || file.rfind("--set ", 0) == 0) return true;  // "--set <item>": a value an override gave
  for (const std::string& item : overrides.set) {
    const auto append = item.find("+=");
    if (append == std::string::npos || item.find('=') != append + 1) continue;
    try {
      const YAML::Node value = YAML::Load(item.substr(append + 2));
      if (value.IsScalar() && value.Scalar() == file) return true;
      if (value.IsSequence())
        for (const YAML::Node& element : value)
          if (element.IsScalar() && element.Scalar() == file) return true;
    } catch (const YAML::Exception&) {  // apply_overrides refuses it
    }
  }
  return false;
}

}  // namespace signalsim
