// Applying `--set` overrides to a scenario's YAML tree.
#include "scenario/overrides.hpp"

#include "scenario/input_error.hpp"
#include "scenario/scenario_keys.hpp"
#include "scenario/utf8_text.hpp"

namespace signalsim {

bool is_scenario_key(const std::string& key) { return scenario_keys().find(key) != nullptr; }

YAML::Node apply_overrides(YAML::Node root, const ScenarioOverrides& overrides, YAML::Node& parameters) {
  for (const std::string& item : overrides.set) {
    if (const auto bad = find_invalid_utf8(item))
      throw InputError("--set", 0, "an override is not UTF-8 text: " + describe_invalid_utf8(item, *bad));
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--set", 0, "'" + item + "' is not of the form key=value");
    const std::string key = item.substr(0, eq);
    if (eq + 1 == item.size())
      throw InputError("--set", 0, "'" + item + "': empty value (write " + key + "=VALUE)");
    YAML::Node value;
    try {
      value = YAML::Load(item.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw InputError("--set", 0, "'" + item + "': malformed value: " + e.msg);
    }
    // A scalar rebuilt without a parse mark carries no line, so a message about it names no line of
    // the scenario file (it came from the command line).
    if (value.IsScalar()) value = YAML::Node(value.Scalar());
    const std::string head = key.substr(0, key.find('.'));
    if (!is_scenario_key(head)) {
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
        node[part] = value;
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

}  // namespace signalsim
