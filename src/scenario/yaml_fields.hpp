// Strict reading of YAML mappings: every key must be known, every value of the right type and range.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace signalsim {

/// Reads the fields of one mapping; `finish()` rejects keys nobody asked for.
class YamlFields {
 public:
  /// `where` names the mapping in messages ("ego", "params", ...); empty for the top level.
  YamlFields(const YAML::Node& mapping, std::string file, std::string where);

  bool has(const std::string& key) const;
  std::string text(const std::string& key) const;  ///< required
  std::string text_or(const std::string& key, const std::string& fallback) const;
  double number(const std::string& key, double fallback, double min, double max) const;
  double required_number(const std::string& key, double min, double max) const;
  int integer(const std::string& key, int fallback, int min, int max) const;
  std::vector<std::string> text_list(const std::string& key) const;  ///< missing -> empty
  YAML::Node node(const std::string& key) const;                     ///< marks the key as known

  /// Throws InputError for the first key that was never read.
  void finish() const;

  [[noreturn]] void fail(const std::string& key, const std::string& reason) const;
  int line_of(const std::string& key) const;

 private:
  std::string qualified(const std::string& key) const;
  YAML::Node mapping_;
  std::string file_;
  std::string where_;
  mutable std::set<std::string> read_;
};

int yaml_line(const YAML::Node& node);

/// Reads a YAML file. Throws InputError: "<what> not found" for a missing file, "malformed YAML:
/// <reason>" at the parser's line for a syntax error.
YAML::Node load_yaml_file(const std::string& path, const std::string& what);

/// Throws InputError at the second occurrence of a key in a mapping (`where` prefixes the key).
void reject_duplicate_keys(const YAML::Node& mapping, const std::string& file, const std::string& where);

}  // namespace signalsim
