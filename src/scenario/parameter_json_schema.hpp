// The parameters (scenario/parameters.hpp parameter_schema) and the `--set` keys as JSON Schema
// definitions: a parameter mapping (`params.set`, a parameter file) accepts every spelling the loader
// accepts - signalsim's name or Autoware's place, nested or dotted at any depth - and a `--set` key
// is a scenario key path (`ego.max_speed`, `light_offsets.<tls>`, `params.set.<parameter>`) or a
// parameter name.
#pragma once

#include <string>

#include "scenario/json_schema.hpp"

namespace signalsim {

/// "#/definitions/<name>" for a definition of parameter_definitions() or override_definitions().
std::string definition_ref(const std::string& name);

/// Definitions: "parameter.<name>" (type, default, range or choices, unit and spec section) for
/// every parameter, and "parameters", the mapping of them.
SchemaJson parameter_definitions();

/// Definitions: "override_values" (a mapping of `--set` keys to a value each), "override_lists" (to
/// non-empty lists of values) and "setting.<path>" (the value of a scenario key path, from the
/// scenario's key tables); a parameter's value refers to parameter_definitions()' "parameter.<name>".
SchemaJson override_definitions();

}  // namespace signalsim
