// The runs of a sweep (grid x zip expansion, one run at a time) and of a suite (see run_list.hpp).
#include "batch/run_list.hpp"

#include <filesystem>
#include <utility>

#include "batch/interrupt_guard.hpp"
#include "scenario/input_error.hpp"
#include "scenario/overrides.hpp"
#include "scenario/scenario.hpp"

namespace signalsim {
namespace fs = std::filesystem;

SweepRuns::SweepRuns(const Sweep& sweep, std::vector<std::string> extra) : sweep_(sweep), extra_(std::move(extra)) {
  for (const SweepAxis& a : sweep.grid) {
    std::vector<Option> options;
    for (const std::string& v : a.values) options.push_back({{a.key, v}});
    factors_.push_back(std::move(options));
  }
  for (const auto& group : sweep.zips) {
    std::vector<Option> options(group.front().values.size());
    for (std::size_t i = 0; i < options.size(); ++i)
      for (const SweepAxis& a : group) options[i].emplace_back(a.key, a.values[i]);
    factors_.push_back(std::move(options));
  }
  double count = static_cast<double>(sweep.scenarios.size());
  for (const auto& options : factors_) count *= static_cast<double>(options.size());
  if (count > 1e6)
    throw InputError(sweep.path, sweep.grid_line, "the sweep has " + std::to_string(static_cast<long long>(count)) +
                                                      " runs, more than 1000000");
  for (const auto& options : factors_) per_scenario_ *= options.size();
}

RunSpec SweepRuns::at(std::size_t index) const {
  RunSpec run;
  run.index = index;
  run.scenario = sweep_.scenarios[index / per_scenario_];
  // The choice of each factor: the digits of the index within the scenario, the last factor fastest.
  std::vector<std::size_t> choice(factors_.size());
  std::size_t rest = index % per_scenario_;
  for (std::size_t f = factors_.size(); f-- > 0;) {
    choice[f] = rest % factors_[f].size();
    rest /= factors_[f].size();
  }
  std::vector<std::string> items;
  for (std::size_t f = 0; f < factors_.size(); ++f)
    for (const auto& [key, value] : factors_[f][choice[f]]) {
      run.values.emplace_back(key, value);
      items.push_back(sweep_set_argument(sweep_, key, value));
    }
  run.set = overrides(items);
  return run;
}

std::size_t SweepRuns::stride(std::size_t f) const {
  std::size_t out = 1;
  for (std::size_t g = f + 1; g < factors_.size(); ++g) out *= factors_[g].size();
  return out;
}

std::size_t SweepRuns::index_of(std::size_t scenario, std::size_t f, std::size_t c) const {
  return scenario * per_scenario_ + c * stride(f);
}

std::size_t SweepRuns::choice_of(std::size_t index, std::size_t f) const {
  return (index % per_scenario_) / stride(f) % factors_[f].size();
}

std::vector<std::string> SweepRuns::overrides(const std::vector<std::string>& items) const {
  std::vector<std::string> out = sweep_.set;
  out.insert(out.end(), items.begin(), items.end());
  out.insert(out.end(), extra_.begin(), extra_.end());
  return out;
}

std::vector<RunSpec> expand_sweep(const Sweep& sweep) {
  const SweepRuns runs(sweep);
  std::vector<RunSpec> out;
  out.reserve(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (i % 4096 == 0) InterruptGuard::throw_if_interrupted();
    out.push_back(runs.at(i));
  }
  return out;
}

void check_suite_overrides(const std::vector<std::string>& files, const std::vector<std::string>& set) {
  for (const std::string& file : files) {
    InterruptGuard::throw_if_interrupted();
    try {
      load_scenario(file, ScenarioOverrides{set});
      return;  // the overrides apply to a scenario: the other files are their runs' business
    } catch (const InputError& e) {
      // The command's own input (--set, a --params file): every run would fail alike.
      if (is_override_input(e.file(), ScenarioOverrides{set})) throw;
    } catch (const std::exception&) {  // a sumocfg the scenario names that does not read, ...
    }
  }
}

std::vector<RunSpec> suite_runs(const std::vector<std::string>& files, const std::vector<std::string>& set) {
  check_suite_overrides(files, set);
  std::vector<RunSpec> runs(files.size());
  for (std::size_t i = 0; i < files.size(); ++i) {
    runs[i].index = i;
    runs[i].scenario = files[i];
    runs[i].name = fs::path(files[i]).stem().string();
    runs[i].set = set;
  }
  return runs;
}

}  // namespace signalsim
