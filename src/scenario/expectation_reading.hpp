// The scenario's `expect:` list: one-key mappings `- <kind>: <value>` (scenario_keys expectation_kinds).
#pragma once

#include <string>

#include "scenario/scenario.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {

/// Reads `expect:` of the top-level mapping `top` of scenario file `path` into s.expect (the line of
/// each is in s.origins, "expect[i]"). Throws InputError: not a list, an item that is not a one-key mapping, an unknown
/// kind, a bad key or value.
void read_expectations(const YamlFields& top, const std::string& path, Scenario& s);

}  // namespace signalsim
