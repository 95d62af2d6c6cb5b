// Where each key of a scenario came from: its line in the scenario file, or the `--set` item that gave
// it. A message about a key at fault names that place, "s.yaml:7: ..." or "--set ego.route=[a, b]: ...",
// also for the checks made after loading (the route against the net, the maneuvers, light_offsets).
#pragma once

#include <map>
#include <string>

#include <yaml-cpp/yaml.h>

#include "scenario/input_error.hpp"

namespace signalsim {

struct KeyOrigins {
  /// Key path ("ego.route", "ego.route[1]", "obstacles[0].pos", "light_offsets.C") -> its line in the
  /// scenario file (0: an override made it).
  std::map<std::string, int> lines;
  /// Key path -> the `--set` item that gave it ("ego.max_speed=10"; "params.files[2]" for an item
  /// `params.files+=x.yaml` appended).
  std::map<std::string, std::string> set;
};

/// Every key path of `root` with its line: a mapping's keys "a.b", a list's items "a[2]".
std::map<std::string, int> key_lines(const YAML::Node& root);

/// The error `reason` about `key` of the scenario at `file`: at the `--set` item that gave the key
/// or a mapping or list holding it (file "--set <item>", no line), else at the line of the key or of
/// the nearest key holding it.
InputError key_error(const std::string& file, const KeyOrigins& origins, const std::string& key,
                     const std::string& reason);

/// `error`, thrown while reading the scenario at `file`, blamed on the `--set` item that gave its key
/// when one did; else `error` as it is.
InputError attributed(const InputError& error, const std::string& file, const KeyOrigins& origins);

}  // namespace signalsim
