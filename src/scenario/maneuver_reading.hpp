// The scenario's `obstacles:` and `maneuvers:` lists (lane_change, avoid, pull_out, pull_over).
#pragma once

#include <string>

#include "scenario/scenario.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {

/// Reads `obstacles:` of the top-level mapping `top` of scenario file `path` into s.obstacles.
/// Throws InputError: not a list, a bad key or value, an id declared twice.
void read_obstacles(const YamlFields& top, const std::string& path, Scenario& s);

/// Reads `maneuvers:` into s.lane_changes, s.avoids, s.pull_out and s.pull_over. Throws InputError:
/// not a list, an item that is not a one-key mapping, an unknown kind, a bad key or value, a second
/// pull_out or pull_over, a second lane_change on one edge.
void read_maneuvers(const YamlFields& top, const std::string& path, Scenario& s);

}  // namespace signalsim
