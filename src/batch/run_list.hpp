// The runs a batch makes: a sweep's (scenarios x grid x zip factors, see sweep_file.hpp for the
// order; checked by sweep_check.hpp) or a suite's (one per scenario file, each read by its own run).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "batch/run_spec.hpp"
#include "batch/sweep_file.hpp"

namespace signalsim {

/// The runs of a sweep, each made when asked for (a grid of a million runs is never held whole): run
/// `index` of size(), in the order of sweep_file.hpp (scenarios outermost, the last factor fastest).
class SweepRuns {
 public:
  /// `extra`: overrides after each run's own (the command line's --decider, ...). Throws InputError
  /// at the line of grid: above 1000000 runs.
  explicit SweepRuns(const Sweep& sweep, std::vector<std::string> extra = {});
  std::size_t size() const { return per_scenario_ * sweep_.scenarios.size(); }
  /// Run `index` < size(), its name left empty.
  RunSpec at(std::size_t index) const;
  /// The factors (each grid axis, then each zip group) and the choices of factor `f` (its values).
  std::size_t factors() const { return factors_.size(); }
  std::size_t choices(std::size_t f) const { return factors_[f].size(); }
  /// The run of scenario `scenario` with factor `f` at choice `c` and every other factor at its first.
  std::size_t index_of(std::size_t scenario, std::size_t f, std::size_t c) const;
  /// The choice of factor `f` in run `index`.
  std::size_t choice_of(std::size_t index, std::size_t f) const;
  const Sweep& sweep() const { return sweep_; }
  /// A run's overrides for the swept `items` ("key=value"): the sweep's set, `items`, then `extra`
  /// (with no items: the overrides every run has).
  std::vector<std::string> overrides(const std::vector<std::string>& items = {}) const;

 private:
  using Option = std::vector<std::pair<std::string, std::string>>;  // (key, value) of one factor's choice
  /// The runs between two choices of factor `f`: the product of the choices of the factors after it.
  std::size_t stride(std::size_t f) const;
  const Sweep& sweep_;
  std::vector<std::string> extra_;
  std::vector<std::vector<Option>> factors_;  // each grid axis, then each zip group
  std::size_t per_scenario_ = 1;
};

/// Every run of the sweep (names left empty), SweepRuns(sweep).at(0..size-1).
std::vector<RunSpec> expand_sweep(const Sweep& sweep);

/// The runs of a suite: one per scenario file with the same overrides, named by the file's stem. The
/// files are not read here (check_suite_overrides aside): each run's worker loads its own, and a file
/// that does not load (malformed, an unknown key, ...) is that run's error row while the others run.
std::vector<RunSpec> suite_runs(const std::vector<std::string>& files, const std::vector<std::string>& set);

/// Loads the suite's files in order until one loads with `set` (no SUMO): throws InputError for a bad
/// --set or --params file (scenario/overrides.hpp is_override_input), which every run would meet.
/// A file that does not load for its own reason is passed over (its run reports it).
void check_suite_overrides(const std::vector<std::string>& files, const std::vector<std::string>& set);

}  // namespace signalsim
