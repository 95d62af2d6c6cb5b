// A sweep's runs checked against their scenarios before any starts (scenarios loaded with overrides,
// no SUMO), and the name each run gets. Up to kCombinationsChecked runs, every run is loaded. A
// larger grid (up to a million runs) is checked without loading a scenario per run: per scenario, its
// first run (every factor at its first value) and, for each factor, each of its values with the other
// factors at their first: the sum of the factors' values, not their product. Each of those is a run
// of the sweep, so what is refused is wrong; a combination wrong only beyond them is its run's error row.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "batch/run_list.hpp"

namespace signalsim {

/// Up to this many runs, every run's scenario is loaded with all of its overrides before any starts.
inline constexpr std::size_t kCombinationsChecked = 10000;

class SweepCheck {
 public:
  /// Loads the runs above. Throws InputError naming the sweep file and the line of what is at fault:
  /// `scenarios:` or `set:` for a scenario that does not load with the fixed overrides, a value's line
  /// for a value that is wrong (alone, or with the first values of the other factors), `grid:` or
  /// `zip:` for a combination. Throws BatchInterrupted on SIGINT or SIGTERM under an InterruptGuard.
  explicit SweepCheck(const SweepRuns& runs);

  /// The name the run's scenario gives it (its `name`, or a swept one).
  std::string name_of(const RunSpec& run) const;

 private:
  void check_every_run();
  void check_each_value();
  [[noreturn]] void refuse(const RunSpec& run, const std::string& error) const;

  const SweepRuns& runs_;
  std::vector<std::string> names_;  // every run's name, when every run is loaded
  // Otherwise: each scenario's first run's name, and the name of each choice of the factor that
  // sweeps `name` (scenario index, choice).
  std::map<std::size_t, std::string> first_names_;
  std::map<std::pair<std::size_t, std::size_t>, std::string> swept_names_;
  std::size_t name_factor_ = SIZE_MAX;
};

/// SweepCheck(SweepRuns(sweep)) and each run's name filled in.
void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs);

}  // namespace signalsim
