// Reading the table of Autoware's keys and judging a key of a strict parameter file by it.
#include "scenario/autoware_key_table.hpp"

#include <algorithm>
#include <filesystem>

#include <yaml-cpp/yaml.h>

#include "scenario/data_dir.hpp"
#include "scenario/input_error.hpp"
#include "scenario/parameter_keys.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {

// A scalar field of a table entry, or an error naming the entry's line.
std::string table_text(const YAML::Node& entry, const char* field, const std::string& path) {
  const YAML::Node value = entry[field];
  if (!value || !value.IsScalar())
    throw InputError(path, yaml_line(entry), std::string("expected '") + field + "': a text");
  return value.Scalar();
}

AutowareFileKeys read_file_entry(const std::string& name, const YAML::Node& entry, const std::string& path) {
  if (!entry.IsMap()) throw InputError(path, yaml_line(entry), "'" + name + "' must be a mapping");
  AutowareFileKeys keys;
  keys.file = name;
  const YAML::Node known = entry["known"];
  if (!known || !known.IsSequence()) throw InputError(path, yaml_line(entry), "'" + name + ".known' must be a list");
  for (const YAML::Node& key : known) {
    if (!key.IsScalar()) throw InputError(path, yaml_line(key), "'" + name + ".known': expected a key name");
    keys.known.push_back(key.Scalar());
  }
  const YAML::Node dropped = entry["dropped"];
  if (!dropped || !dropped.IsMap()) throw InputError(path, yaml_line(entry), "'" + name + ".dropped' must be a mapping");
  for (const auto& item : dropped) {
    if (!item.second.IsMap())
      throw InputError(path, yaml_line(item.first), "'" + name + ".dropped." + item.first.Scalar() + "' must be a mapping");
    keys.dropped[item.first.Scalar()] = DroppedKey{table_text(item.second, "repository", path),
                                                   table_text(item.second, "commit", path),
                                                   table_text(item.second, "date", path)};
  }
  return keys;
}

}  // namespace

bool AutowareFileKeys::knows(const std::string& key) const {
  return std::find(known.begin(), known.end(), key) != known.end();
}

const DroppedKey* AutowareFileKeys::dropped_key(const std::string& key) const {
  const auto found = dropped.find(key);
  return found == dropped.end() ? nullptr : &found->second;
}

std::string AutowareFileKeys::nearest_known(const std::string& key_as_written) const {
  // Past the longest known key, more characters only add edits: a very long key (a fuzzer's) is cut
  // there, so that it is not compared cell by cell with every key.
  std::size_t longest = 0;
  for (const std::string& candidate : known) longest = std::max(longest, candidate.size());
  const std::string key = key_as_written.substr(0, longest + 1);
  std::string nearest;
  std::size_t fewest = std::string::npos;
  for (const std::string& candidate : known) {
    // The distance is at least the difference in length: most names need no table of edits.
    const std::size_t least = candidate.size() > key.size() ? candidate.size() - key.size() : key.size() - candidate.size();
    if (least >= fewest) continue;
    if (const std::size_t edits = edit_distance(key, candidate); edits < fewest) {
      fewest = edits;
      nearest = candidate;
    }
  }
  return nearest;
}

AutowareKeyTables read_autoware_key_tables(const std::string& path) {
  const YAML::Node root = load_yaml_file(path, "table of Autoware's keys");
  const YAML::Node files = root.IsMap() ? root["files"] : YAML::Node();
  if (!files || !files.IsMap()) throw InputError(path, yaml_line(root), "expected 'files': a mapping of file name to keys");
  AutowareKeyTables tables;
  tables.path = path;
  for (const auto& file : files) {
    const std::string name = file.first.Scalar();
    tables.files[name] = read_file_entry(name, file.second, path);
  }
  return tables;
}

const AutowareKeyTables& autoware_key_tables() {
  static const AutowareKeyTables tables =
      read_autoware_key_tables((std::filesystem::path(data_dir()) / "data" / "autoware_keys.yaml").string());
  return tables;
}

std::optional<std::string> strict_key_warning(const AutowareKeyTables& tables, const std::string& autoware_file,
                                              const std::string& file, int line, const std::string& key,
                                              const std::string& noun) {
  const std::string& name = autoware_file;
  const auto entry = tables.files.find(name);
  if (entry == tables.files.end())
    throw InputError(file, line, "unknown " + noun + " '" + key + "' (strict parameters: every key must be known)");
  const AutowareFileKeys& keys = entry->second;
  if (keys.knows(key)) return std::nullopt;
  if (const DroppedKey* dropped = keys.dropped_key(key))  // "<file>:<line>: " as in an error
    return InputError(file, line, noun + " '" + key + "' was dropped from Autoware's " + name + " (" +
                                      dropped->repository + " " + dropped->commit + ", " + dropped->date +
                                      "): it has no effect")
        .what();
  throw InputError(file, line, "unknown " + noun + " '" + key + "': not a key of Autoware's " + name +
                                   " (did you mean '" + keys.nearest_known(key) + "'?)");
}

}  // namespace signalsim
