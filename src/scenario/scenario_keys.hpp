// The key tables of a scenario file (scenario/key_table.hpp): the top level, `ego`, `perception`,
// `params`, `obstacles`, `maneuvers` and `expect`. The loader reads every mapping through them and
// `signalsim schema scenario` prints them; a key or default changes here, in one place.
#pragma once

#include "scenario/key_table.hpp"

namespace signalsim {

const KeyTable& scenario_keys();         ///< the top-level mapping
const KeyTable& ego_keys();              ///< `ego:`
const KeyTable& perception_keys();       ///< `perception:`
const KeyTable& v2i_channel_keys();      ///< `perception.v2i:`
const KeyTable& params_keys();           ///< `params:`
const KeyTable& obstacle_keys();         ///< each item of `obstacles:`
const KeyTable& maneuver_kinds();        ///< the kinds of `maneuvers:` items, each with its table
const KeyTable& fleet_keys();            ///< `fleet:`
const KeyTable& expectation_kinds();     ///< the kinds of `expect:` items, each with its table or value

/// The blinker values an expectation names, in the order messages list them.
const std::vector<std::string>& blinker_choices();

}  // namespace signalsim
