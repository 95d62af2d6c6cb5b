// The simulation keys of a scenario file and the user's SUMO files behind them (docs/sumo.md): `net:` or a
// `sumocfg:` (its net, route and additional files, step length, begin/end and seed; the scenario's own
// keys win and are recorded), `routes:` (route files, SUMO -r), `additional:`, `step_length:`,
// `seed:`, `duration:` and `sumo_args:` (SUMO options passed through; those signalsim sets are refused).
#pragma once

#include <optional>
#include <string>

#include "scenario/scenario.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {

/// Reads those keys of the top-level mapping `top` of scenario file `path` into `s`. Throws InputError
/// (file, line, key) for a missing file, a sumocfg without a net, a refused or malformed sumo_args
/// option, an out-of-range value; sumo::NetError for a malformed sumocfg ("<cfg>:<line>: ...").
void read_simulation_keys(const YamlFields& top, const std::string& path, Scenario& s);

/// The error of a SUMO that did not start because of one of the options the scenario passed on
/// (`message` is SUMO's, e.g. "While processing option 'lateral-resolution': 'x' is not a valid float"
/// or "Invalid Number Format (double) abc"): at the line of that `sumo_args` item (or the --set item
/// that gave it), or of that option in the sumocfg. nullopt when the message names none of them.
std::optional<InputError> sumo_option_error(const Scenario& s, const std::string& message);

}  // namespace signalsim
