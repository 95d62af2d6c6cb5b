// What the scenario says about the traffic lights: the perception model's faults (`perception:`),
// the V2I channel's (`perception.v2i:`) and program shifts (`light_offsets:`).
#pragma once

#include <string>

#include "scenario/scenario.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {

/// Reads `perception:` (with `v2i:`) and `light_offsets:` of the top-level mapping `top` of scenario
/// file `path` into s.perception, s.v2i_channel (both seeded with s.seed) and s.light_offsets.
/// Throws InputError (file, line, key) for a bad key, value or blackout pair.
void read_signal_inputs(const YamlFields& top, const std::string& path, Scenario& s);

/// `fleet:` (docs/fleet.md): the selection (an id_pattern that is no regular expression is refused at
/// its line) and the signals mode. Absent: fleet mode off.
void read_fleet(const YamlFields& top, const std::string& path, Scenario& s);

}  // namespace signalsim
