// Tables of the keys of an input file's mappings: per key its name, the shape of its value, unit,
// default, range, choices and description, and whether it is required. A loader reads a mapping
// through its table (YamlFields: a key given but not in the table is unknown; defaults and ranges
// come from the table) and `signalsim schema` prints the same tables as a JSON Schema
// (scenario/json_schema.hpp): one source for what a file may hold.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace signalsim {

/// The shape of a key's value.
enum class KeyType {
  Text,           ///< a scalar read as text; with `choices`, one of them
  Number,         ///< a number within [min, max]
  Integer,        ///< an integer within [min, max]
  Boolean,        ///< true or false
  TextList,       ///< a list of scalars (null: an empty list)
  Mapping,        ///< a mapping whose keys are `table`
  MappingList,    ///< a list of mappings whose keys are `table` (null: none)
  KindList,       ///< a list of one-key mappings `- <kind>: <value>`, the kinds are `table` (null: none)
  NumberMapping,  ///< a mapping of free names (ids) to numbers in `unit`
  Intervals,      ///< a list of [start, end] pairs of numbers, start <= end (null: none)
  Parameters,     ///< a mapping of parameters (parameter_schema: signalsim names or Autoware places)
  True,           ///< only `true`, a flag (`arrives: true`)
  // Sweep files: `--set` keys (scenario key paths such as `ego.max_speed`, or parameter names).
  TextOrTextList,      ///< one scalar or a non-empty list of scalars
  MappingOrList,       ///< a mapping whose keys are `table`, or a non-empty list of such mappings
  OverrideValues,      ///< a mapping of `--set` keys to one value each
  OverrideLists,       ///< a non-empty mapping of `--set` keys to non-empty lists of values
  OverrideListGroups,  ///< an OverrideLists mapping, or a non-empty list of them
};

struct KeyTable;

/// One key of a mapping.
struct KeySpec {
  std::string name;
  KeyType type = KeyType::Text;
  std::string description;               ///< one sentence, for the schema and documentation
  std::string unit;                      ///< "m", "m/s", "s", ...; empty for none
  bool required = false;                 ///< the mapping must give it
  bool may_be_null = false;              ///< Mapping: an empty value stands for the defaults
  std::optional<double> default_number;  ///< Number, Integer: the value when the key is not given
  std::optional<std::string> default_text;  ///< Text: the value when the key is not given
  std::optional<bool> default_boolean;      ///< Boolean: the value when the key is not given
  /// A default that is not a constant (from another key, a sumocfg), or what a sentinel default
  /// outside the range means; said in the schema's description.
  std::string default_note;
  double min = -std::numeric_limits<double>::infinity();  ///< Number, Integer: inclusive bounds
  double max = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;      ///< Text: the allowed values (empty: any)
  std::vector<std::string> needs;        ///< keys that must be given with this one
  const KeyTable* table = nullptr;       ///< Mapping, MappingList, KindList, MappingOrList: the inner keys
};

/// The keys of one mapping, in the order a reader meets them.
struct KeyTable {
  KeyTable(std::string where, std::string description, std::vector<KeySpec> keys,
           std::vector<std::vector<std::string>> one_of_required = {});

  std::string where;        ///< the mapping's place in the file, e.g. "ego", "maneuvers[].lane_change"
  std::string description;  ///< one sentence
  std::vector<KeySpec> keys;
  /// Groups of keys of which at least one must be given (`net` or `sumocfg`); a key of a group is
  /// not `required` itself.
  std::vector<std::vector<std::string>> one_of_required;

  /// The key named `name`, or nullptr.
  const KeySpec* find(const std::string& name) const;
  /// The key named `name`. Throws std::logic_error when there is none (a loader reading a key its
  /// table does not list: a programming error, not bad input).
  const KeySpec& at(const std::string& name) const;
  /// The inner table of key `name` (a kind of `maneuvers:`). Throws std::logic_error when it has none.
  const KeyTable& table_of(const std::string& name) const;
  /// The key names joined by ", " in table order ("lane_change, avoid, pull_out, pull_over").
  std::string names() const;
};

// Entries, one line each in a table (descriptions are one sentence; `unit` may be empty).
KeySpec text_key(std::string name, std::string description, std::vector<std::string> choices = {});
KeySpec required_text_key(std::string name, std::string description, std::vector<std::string> choices = {});
KeySpec text_key_or(std::string name, std::string fallback, std::string description,
                    std::vector<std::string> choices = {});
KeySpec number_key(std::string name, double fallback, double min, double max, std::string unit,
                   std::string description);
KeySpec required_number_key(std::string name, double min, double max, std::string unit, std::string description);
/// A number whose default is computed by the loader (`note` says from what).
KeySpec computed_number_key(std::string name, double min, double max, std::string unit, std::string note,
                            std::string description);
KeySpec integer_key(std::string name, int fallback, int min, int max, std::string description);
KeySpec required_integer_key(std::string name, int min, int max, std::string description);
KeySpec boolean_key(std::string name, bool fallback, std::string description);
KeySpec text_list_key(std::string name, std::string description);
KeySpec table_key(std::string name, KeyType type, const KeyTable& table, std::string description);
KeySpec shape_key(std::string name, KeyType type, std::string description);

/// `spec` with `note` as its default_note (a default that is not a constant).
KeySpec with_default_note(KeySpec spec, std::string note);
/// `spec` as a required key.
KeySpec as_required(KeySpec spec);
/// `spec` (a Mapping) with an empty value allowed, standing for the defaults.
KeySpec as_nullable(KeySpec spec);

}  // namespace signalsim
