// Strict reading of YAML mappings: every key must be known, every value of the right type and range.
// A mapping read through its key table (scenario/key_table.hpp) takes the table's defaults, ranges
// and choices, and a key the table does not list is unknown.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "scenario/key_table.hpp"

namespace signalsim {

/// Reads the fields of one mapping; `finish()` rejects keys nobody asked for.
class YamlFields {
 public:
  /// `where` names the mapping in messages ("ego", "params", ...); empty for the top level.
  YamlFields(const YAML::Node& mapping, std::string file, std::string where);
  /// Reads through `keys` (which must outlive this object): every key asked about must be in the
  /// table and of the shape read (else std::logic_error: a loader bug, not bad input), and finish()
  /// rejects a key the table does not list as well as one never read (a key read only with another).
  YamlFields(const YAML::Node& mapping, std::string file, std::string where, const KeyTable& keys);

  bool has(const std::string& key) const;
  std::string text(const std::string& key) const;  ///< required
  std::string text_or(const std::string& key, const std::string& fallback) const;
  double number(const std::string& key, double fallback, double min, double max) const;
  double required_number(const std::string& key, double min, double max) const;
  int integer(const std::string& key, int fallback, int min, int max) const;
  std::vector<std::string> text_list(const std::string& key) const;  ///< missing -> empty

  // Through the table: its default, range and choices.
  std::string text_or(const std::string& key) const;           ///< the table's default_text
  /// The text (required unless the table has a default), one of the table's choices: else
  /// "'<value>' is not one of <choices>".
  std::string choice(const std::string& key) const;
  double number(const std::string& key) const;                  ///< the table's default and range
  double number(const std::string& key, double fallback) const;  ///< a computed default, the table's range
  double required_number(const std::string& key) const;         ///< the table's range
  int integer(const std::string& key) const;                     ///< the table's default and range
  int integer(const std::string& key, int fallback) const;       ///< a computed default, the table's range
  YAML::Node node(const std::string& key) const;                     ///< marks the key as known

  /// Throws InputError ("unknown key") for the first key that was never read or, with a table, that
  /// the table does not list.
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  int line_of(const std::string& key) const;

 private:
  std::string qualified(const std::string& key) const;
  /// The table's entry for `key` when there is a table (checked: listed, and of shape `type`).
  const KeySpec* spec(const std::string& key, std::optional<KeyType> type = std::nullopt) const;
  /// The same, for the reads that need a table (std::logic_error without one).
  const KeySpec& listed(const std::string& key, KeyType type) const;
  YAML::Node mapping_;
  std::string file_;
  std::string where_;
  const KeyTable* keys_ = nullptr;
  mutable std::set<std::string> read_;
};

int yaml_line(const YAML::Node& node);

/// The number rule of every YAML file (docs/scenario.md "Rules for every key"): a scalar that reads as
/// a finite double, and none of magnitude between 0 and 2.2e-308 (a subnormal such as 1e-308, which
/// SUMO's parser refuses: write 0). Else nullopt, and `reason` says why: "expected a number, got
/// '<text>'" or "value <text> is too small to be a number SUMO can read (below 2.2e-308); write 0".
std::optional<double> yaml_number(const YAML::Node& node, std::string& reason);

/// Reads a YAML file. Throws InputError: "<what> not found" for a missing file, "malformed YAML:
/// <reason>" at the parser's line for a syntax error.
YAML::Node load_yaml_file(const std::string& path, const std::string& what);

/// load_yaml_file for a file read many times in a process (parameter, country and vehicle_info
/// files): the same file with the same bytes gives the same tree, which callers must only read.
YAML::Node load_shared_yaml_file(const std::string& path, const std::string& what);

/// Throws InputError at the second occurrence of a key in a mapping (`where` prefixes the key).
void reject_duplicate_keys(const YAML::Node& mapping, const std::string& file, const std::string& where);

}  // namespace signalsim
