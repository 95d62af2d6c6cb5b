// The scenario's `ego:` mapping: signalsim's own ego or a taken-over vehicle (`id`), its route,
// footprint (the keys, or Autoware's vehicle_info file) and departure.
#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

#include "scenario/scenario.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {

/// Reads `ego:` of the top-level mapping `top` (the tree `root`, overrides applied) of scenario file
/// `path` into s.ego, and params.strict into s.strict_params (it applies to ego.vehicle_info too).
/// Notes vehicle_info values the keys replace in s.notes (and keys Autoware dropped in s.warnings). Throws InputError (file, line, key): a
/// missing ego or route, a value out of range or of the wrong type, base_link_to_front beyond the
/// length, depart keys beside ego.id, a bad vehicle_info file or footprint.
/// Without `ego:` but with `fleet:` it reads nothing and sets s.has_ego false (an egoless fleet run).
void read_ego(const YamlFields& top, const YAML::Node& root, const std::string& path, Scenario& s);

/// For a scenario without an ego: throws InputError at the first key that is about the ego
/// (obstacles, maneuvers, perception, decider, light_judge, expect).
void refuse_ego_only_keys(const YamlFields& top);

}  // namespace signalsim
