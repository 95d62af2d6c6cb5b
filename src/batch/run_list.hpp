// The runs a batch makes: a sweep's (scenarios x grid x zip factors, see sweep_file.hpp for the
// order) or a suite's (one per scenario file), each checked against its scenario before any starts.
#pragma once

#include <string>
#include <vector>

#include "batch/run_spec.hpp"
#include "batch/sweep_file.hpp"

namespace signalsim {

/// Every run of the sweep (names left empty); see sweep_file.hpp for the order. Throws InputError
/// above 1000000 runs.
std::vector<RunSpec> expand_sweep(const Sweep& sweep);

/// Loads every run's scenario with its overrides (no SUMO) and fills in its name. Throws InputError
/// naming the sweep file and the line of the value at fault (the grid/zip when only a combination
/// fails) for an unknown key, a bad value, an unknown country, ...
void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs);

/// The runs of a suite: one per scenario file with the same overrides. Loads each (no SUMO). A file
/// that does not load (malformed, an unknown key, ...) is a run with `load_error` set and its file
/// stem as name: it becomes an error row and the others run. Throws InputError for a bad --set or
/// --params file (scenario/overrides.hpp is_override_input).
std::vector<RunSpec> suite_runs(const std::vector<std::string>& files, const std::vector<std::string>& set);

}  // namespace signalsim
