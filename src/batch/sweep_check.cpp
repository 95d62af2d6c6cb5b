// A sweep's runs checked against their scenarios before any starts, and their names (sweep_check.hpp).
#include "batch/sweep_check.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>

#include "batch/interrupt_guard.hpp"
#include "scenario/input_error.hpp"
#include "scenario/scenario.hpp"

namespace signalsim {
namespace {

// An error of a run's scenario as a sweep message says it: a value the sweep gave (an override, named
// "--set <item>") by its reason alone, the sweep's line naming the value.
std::string sweep_detail(const InputError& e) { return e.file().rfind("--set ", 0) == 0 ? e.reason() : e.what(); }

// The name of the scenario `file` loaded with `set`, or nullopt and why it does not load.
std::optional<std::string> loaded_name(const std::string& file, const std::vector<std::string>& set, std::string& error) {
  InterruptGuard::throw_if_interrupted();
  try {
    return load_scenario(file, ScenarioOverrides{set}).name;
  } catch (const InputError& e) {
    error = sweep_detail(e);
    return std::nullopt;
  }
}

std::string describe_values(const RunSpec& run) {
  std::string out = std::filesystem::path(run.scenario).filename().string();
  for (const auto& [key, value] : run.values) out += " " + key + "=" + value;
  return out;
}

// Where a swept key is written: "grid" or "zip", and the line of its value `value`.
std::pair<std::string, int> line_of_value(const Sweep& sweep, const std::string& key, const std::string& value) {
  for (const SweepAxis& a : sweep.grid)
    if (a.key == key)
      for (std::size_t i = 0; i < a.values.size(); ++i)
        if (a.values[i] == value) return {"grid", a.lines[i]};
  for (const auto& group : sweep.zips)
    for (const SweepAxis& a : group)
      if (a.key == key)
        for (std::size_t i = 0; i < a.values.size(); ++i)
          if (a.values[i] == value) return {"zip", a.lines[i]};
  return {"grid", sweep.grid_line};
}

}  // namespace

SweepCheck::SweepCheck(const SweepRuns& runs) : runs_(runs) {
  // The factor that sweeps `name`: a grid axis, or a zip group (the factors' order, run_list.hpp).
  const Sweep& sweep = runs.sweep();
  for (std::size_t f = 0; f < sweep.grid.size(); ++f)
    if (sweep.grid[f].key == "name") name_factor_ = f;
  for (std::size_t g = 0; g < sweep.zips.size(); ++g)
    for (const SweepAxis& a : sweep.zips[g])
      if (a.key == "name") name_factor_ = sweep.grid.size() + g;
  if (runs.size() <= kCombinationsChecked) check_every_run();
  else check_each_value();
}

// What is at fault in `run`, which does not load: the scenario with the fixed overrides, one value
// alone, or the combination. Throws InputError at its line.
void SweepCheck::refuse(const RunSpec& run, const std::string& error) const {
  const Sweep& sweep = runs_.sweep();
  std::string why;
  if (!loaded_name(run.scenario, runs_.overrides(), why)) {
    const int line = sweep.set.empty() ? sweep.scenarios_line : sweep.set_lines.front();
    throw InputError(sweep.path, line, (sweep.set.empty() ? "scenarios: " : "set: ") + why);
  }
  for (const auto& [key, value] : run.values)
    if (!loaded_name(run.scenario, runs_.overrides({sweep_set_argument(sweep, key, value)}), why)) {
      const auto [where, line] = line_of_value(sweep, key, value);
      throw InputError(sweep.path, line, where + "." + key + ": value " + value + ": " + why);
    }
  throw InputError(sweep.path, sweep.zips.empty() ? sweep.grid_line : sweep.zip_line,
                   "run " + std::to_string(run.index) + " (" + describe_values(run) + "): " + error);
}

void SweepCheck::check_every_run() {
  std::string error;
  for (std::size_t i = 0; i < runs_.size(); ++i) {
    const RunSpec run = runs_.at(i);
    const auto name = loaded_name(run.scenario, run.set, error);
    if (!name) refuse(run, error);
    if (name_factor_ != SIZE_MAX) swept_names_[runs_.choice_of(i, name_factor_)] = *name;
  }
}

void SweepCheck::check_each_value() {
  std::string error;
  const RunSpec first = runs_.at(runs_.index_of(0, 0, 0));
  const auto name = loaded_name(first.scenario, first.set, error);
  if (!name) refuse(first, error);
  if (name_factor_ != SIZE_MAX) swept_names_[0] = *name;
  for (std::size_t f = 0; f < runs_.factors(); ++f)
    for (std::size_t c = 1; c < runs_.choices(f); ++c) {
      const RunSpec run = runs_.at(runs_.index_of(0, f, c));
      const auto named = loaded_name(run.scenario, run.set, error);
      if (!named) refuse(run, error);
      if (f == name_factor_) swept_names_[c] = *named;
    }
}

std::string SweepCheck::name_of(const RunSpec& run) const {
  if (name_factor_ != SIZE_MAX) return swept_names_.at(runs_.choice_of(run.index, name_factor_));
  return std::filesystem::path(run.scenario).stem().string();
}

void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs) {
  const SweepRuns all(sweep);
  const SweepCheck check(all);
  for (RunSpec& run : runs) run.name = check.name_of(run);
}

}  // namespace signalsim
