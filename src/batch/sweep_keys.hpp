// The key tables of a sweep file (scenario/key_table.hpp): the top level and each `plot:` mapping.
// load_sweep reads through them and `signalsim schema sweep` prints them. Keys of grid, zip and set
// are `--set` keys: the schema takes them from the scenario's tables and the parameter schema.
#pragma once

#include "scenario/key_table.hpp"

namespace signalsim {

const KeyTable& sweep_keys();       ///< the top-level mapping
const KeyTable& sweep_plot_keys();  ///< `plot:` (one mapping or each of a list)

}  // namespace signalsim
