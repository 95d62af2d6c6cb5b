// Autoware's own keys of the parameter files signalsim reads (data/autoware_keys.yaml, written by
// tools/autoware_key_tables from autoware_launch and autoware_universe): per file name, the keys
// Autoware knows and those it dropped. Strict parameters (--strict-params) check every key signalsim
// does not use against its file's entry (docs/parameters.md "Strict mode").
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace signalsim {

/// Where a key Autoware dropped was last removed.
struct DroppedKey {
  std::string repository;  ///< "tier4/autoware_universe_planning"
  std::string commit;      ///< the commit that dropped it (abbreviated)
  std::string date;        ///< its date, YYYY-MM-DD
};

/// The keys of one of Autoware's parameter files.
struct AutowareFileKeys {
  std::string file;                           ///< its name, e.g. "behavior_path_planner.param.yaml"
  std::vector<std::string> known;             ///< dotted names, in the file's order
  std::map<std::string, DroppedKey> dropped;  ///< dotted name -> where it was dropped

  bool knows(const std::string& key) const;
  /// Where `key` was dropped, or nullptr when it was not.
  const DroppedKey* dropped_key(const std::string& key) const;
  /// The known key fewest edits from `key` (the first in file order among equals).
  std::string nearest_known(const std::string& key) const;
};

/// The table: one entry per file name.
struct AutowareKeyTables {
  std::string path;                               ///< the table file, for messages
  std::map<std::string, AutowareFileKeys> files;  ///< file name -> its keys
};

/// Reads a table file (data/autoware_keys.yaml's form). Throws InputError naming the file and line
/// for a missing file, malformed YAML or an entry of another shape.
AutowareKeyTables read_autoware_key_tables(const std::string& path);

/// The data directory's data/autoware_keys.yaml (scenario/data_dir.hpp), read once per process.
/// Throws InputError as read_autoware_key_tables (then again on the next call).
const AutowareKeyTables& autoware_key_tables();

/// What strict parameters make of `key`, a key signalsim does not use, written at `line` of `file`,
/// which is Autoware's file `autoware_file` (a parameter file: its own name; a vehicle description:
/// "vehicle_info.param.yaml"); `noun` names the key in messages ("parameter", "key"). Returns
/// nothing for a key Autoware knows in that file (the caller lists it as unused), a warning line
/// for a key Autoware dropped from it ("<file>:<line>: ... was dropped from Autoware's <name> (...)").
/// Throws InputError for any other key: when the table has the file, naming its nearest known key
/// ("did you mean"); when not, because every key must then be one signalsim uses.
std::optional<std::string> strict_key_warning(const AutowareKeyTables& tables, const std::string& autoware_file,
                                              const std::string& file, int line, const std::string& key,
                                              const std::string& noun);

}  // namespace signalsim
