// A fleet run without an ego (docs/fleet.md "Without an ego"): SUMO's traffic alone, fleet mode's pass
// over it every step from the first, until the scenario's duration is over or SUMO has no vehicle
// left to run.
#pragma once

#include "net/net_index.hpp"
#include "report/timeline.hpp"
#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"

namespace signalsim {

/// Starts SUMO for `scenario` (has_ego false, fleet on) on the context's back-end with no ego, shifts
/// the light programs by its light_offsets and steps until begin + duration or until
/// Simulation::getMinExpectedNumber() is 0, fleet mode's pass before every step. The record has no
/// rows or events: its fleet record and SUMO's fields only. Throws InputError (a scenario the
/// back-end cannot run), sumo::SumoError when SUMO fails.
RunRecord run_egoless(const Scenario& scenario, const sumo::NetIndex& net, const RunContext& context);

}  // namespace signalsim
