// The systems under test a scenario names (docs/decider.md): one home for turning `decider:` and
// `light_judge:` into the adapters that run them.
#pragma once

#include "scenario/scenario.hpp"
#include "sut/system_under_test.hpp"

namespace signalsim {

/// The scenario's decider and light judge under test; empty pointers for "reference". Loads a lib:
/// library and checks its ABI, or finds an exec: command, before SUMO starts: throws InputError
/// naming the key for a library or command that cannot be used.
SystemsUnderTest make_systems_under_test(const Scenario& scenario);

/// Loads and checks the scenario's plugins and finds its exec: commands (and lets them go): called
/// before SUMO starts, so that a SUT that cannot be used is bad input of the run. Throws InputError
/// naming the scenario file and the key (`decider`, `light_judge`).
void check_systems_under_test(const Scenario& scenario);

}  // namespace signalsim
