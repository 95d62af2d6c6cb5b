// Key paths and where they came from (key_origins.hpp).
#include "scenario/key_origins.hpp"

#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {

void add_lines(const YAML::Node& node, const std::string& path, std::map<std::string, int>& out) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      const std::string key = path.empty() ? entry.first.Scalar() : path + "." + entry.first.Scalar();
      out.emplace(key, yaml_line(entry.first));
      add_lines(entry.second, key, out);
    }
  } else if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i) {
      const std::string key = path + "[" + std::to_string(i) + "]";
      out.emplace(key, yaml_line(node[i]));
      add_lines(node[i], key, out);
    }
  }
}

// The entry of `map` for `key`, or for the nearest key path holding it ("ego" for "ego.route",
// "obstacles[1]" for "obstacles[1].pos"); end() when none.
template <typename Map>
typename Map::const_iterator nearest(const Map& map, std::string key) {
  while (!key.empty()) {
    if (const auto it = map.find(key); it != map.end()) return it;
    const std::size_t cut = key.find_last_of(".[");
    if (cut == std::string::npos || cut == 0) break;
    key.resize(cut);
  }
  return map.end();
}

}  // namespace

std::map<std::string, int> key_lines(const YAML::Node& root) {
  std::map<std::string, int> out;
  add_lines(root, "", out);
  return out;
}

InputError key_error(const std::string& file, const KeyOrigins& origins, const std::string& key,
                     const std::string& reason) {
  if (const auto set = nearest(origins.set, key); set != origins.set.end())
    return InputError("--set " + set->second, 0, reason, key);
  const auto line = nearest(origins.lines, key);
  return InputError(file, line == origins.lines.end() ? 0 : line->second, reason, key);
}

InputError attributed(const InputError& error, const std::string& file, const KeyOrigins& origins) {
  if (error.file() != file || error.key().empty()) return error;
  if (const auto set = nearest(origins.set, error.key()); set != origins.set.end())
    return InputError("--set " + set->second, 0, error.reason(), error.key());
  return error;
}

}  // namespace signalsim
