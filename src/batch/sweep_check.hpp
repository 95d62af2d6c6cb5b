// A sweep's runs checked against their scenarios before any starts (scenarios loaded with overrides,
// no SUMO), and the name each run gets. Up to kCombinationsChecked runs, every run is loaded. A
// larger grid (up to a million runs) is checked on its first scenario file alone, which no other
// file is read for: its first run (every factor at its first value) and, for each factor, each of
// its values with the other factors at their first: the sum of the factors' values, not their
// product. Each of those is a run of the sweep, so what is refused is wrong; another scenario file
// that does not load, or a combination wrong only beyond them, is its run's error row (its worker
// reads its own file). A run is named by its scenario file's stem, or by its swept `name`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "batch/run_list.hpp"

namespace signalsim {

/// Up to this many runs, every run's scenario is loaded with all of its overrides before any starts.
inline constexpr std::size_t kCombinationsChecked = 500;

class SweepCheck {
 public:
  /// Loads the runs above. Throws InputError naming the sweep file and the line of what is at fault:
  /// `scenarios:` or `set:` for a scenario that does not load with the fixed overrides, a value's line
  /// for a value that is wrong (alone, or with the first values of the other factors), `grid:` or
  /// `zip:` for a combination. Throws BatchInterrupted on SIGINT or SIGTERM under an InterruptGuard.
  explicit SweepCheck(const SweepRuns& runs);

  /// The run's name: its swept `name` (as the scenario reads it), else its scenario file's stem.
  std::string name_of(const RunSpec& run) const;

 private:
  void check_every_run();
  void check_each_value();
  [[noreturn]] void refuse(const RunSpec& run, const std::string& error) const;

  const SweepRuns& runs_;
  // The name of each choice of the factor that sweeps `name`, when one does.
  std::map<std::size_t, std::string> swept_names_;
  std::size_t name_factor_ = SIZE_MAX;
};

/// SweepCheck(SweepRuns(sweep)) and each run's name filled in.
void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs);

}  // namespace signalsim
