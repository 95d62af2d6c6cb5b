// The runs of a sweep (grid x zip expansion, checked against the scenarios) and of a suite (see run_list.hpp).
#include "batch/run_list.hpp"

#include <filesystem>
#include <set>
#include <utility>

#include "scenario/input_error.hpp"
#include "scenario/overrides.hpp"
#include "scenario/scenario.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

std::string describe_values(const RunSpec& run) {
  std::string out = fs::path(run.scenario).filename().string();
  for (const auto& [key, value] : run.values) out += " " + key + "=" + value;
  return out;
}

// An error of a run's scenario as a sweep message says it: a value the sweep gave (an override, named
// "--set <item>") by its reason alone, the sweep's line naming the value.
std::string sweep_detail(const InputError& e) { return e.file().rfind("--set ", 0) == 0 ? e.reason() : e.what(); }

}  // namespace

std::vector<RunSpec> expand_sweep(const Sweep& sweep) {
  // Factors: each grid axis, then each zip group; an option is a list of (key, value).
  using Option = std::vector<std::pair<std::string, std::string>>;
  std::vector<std::vector<Option>> factors;
  for (const SweepAxis& a : sweep.grid) {
    std::vector<Option> options;
    for (const std::string& v : a.values) options.push_back({{a.key, v}});
    factors.push_back(std::move(options));
  }
  for (const auto& group : sweep.zips) {
    std::vector<Option> options(group.front().values.size());
    for (std::size_t i = 0; i < options.size(); ++i)
      for (const SweepAxis& a : group) options[i].emplace_back(a.key, a.values[i]);
    factors.push_back(std::move(options));
  }
  double count = static_cast<double>(sweep.scenarios.size());
  for (const auto& options : factors) count *= static_cast<double>(options.size());
  if (count > 1e6)
    throw InputError(sweep.path, sweep.grid_line, "the sweep has " + std::to_string(static_cast<long long>(count)) +
                                                      " runs, more than 1000000");
  std::vector<RunSpec> runs;
  for (const std::string& scenario : sweep.scenarios) {
    std::vector<std::size_t> at(factors.size(), 0);
    while (true) {
      RunSpec run;
      run.index = runs.size();
      run.scenario = scenario;
      run.set = sweep.set;
      for (std::size_t f = 0; f < factors.size(); ++f)
        for (const auto& [key, value] : factors[f][at[f]]) {
          run.values.emplace_back(key, value);
          run.set.push_back(sweep_set_argument(sweep, key, value));
        }
      runs.push_back(std::move(run));
      // Odometer: the last factor turns fastest; done when the first one wraps around.
      std::size_t f = factors.size();
      bool wrapped = true;
      while (f > 0) {
        --f;
        if (++at[f] < factors[f].size()) {
          wrapped = false;
          break;
        }
        at[f] = 0;
      }
      if (wrapped) break;
    }
  }
  return runs;
}

void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs) {
  auto loads = [](const std::string& file, const std::vector<std::string>& set, std::string* error) {
    try {
      (void)load_scenario(file, ScenarioOverrides{set});
      return true;
    } catch (const InputError& e) {
      if (error) *error = sweep_detail(e);
      return false;
    }
  };
  auto line_of_value = [&](const std::string& key, const std::string& value) {
    for (const SweepAxis& a : sweep.grid)
      if (a.key == key)
        for (std::size_t i = 0; i < a.values.size(); ++i)
          if (a.values[i] == value) return std::make_pair(std::string("grid"), a.lines[i]);
    for (const auto& group : sweep.zips)
      for (const SweepAxis& a : group)
        if (a.key == key)
          for (std::size_t i = 0; i < a.values.size(); ++i)
            if (a.values[i] == value) return std::make_pair(std::string("zip"), a.lines[i]);
    return std::make_pair(std::string("grid"), sweep.grid_line);
  };
  std::set<std::string> good_scenarios;  // scenario files that load with the fixed set alone
  std::set<std::string> good_values;     // "key=value" that load alone (with the fixed set)
  for (RunSpec& run : runs) {
    try {
      run.name = load_scenario(run.scenario, ScenarioOverrides{run.set}).name;
      continue;
    } catch (const InputError& e) {
      // Find what is at fault: the scenario with the fixed set, one value alone, or the combination.
      std::string error = sweep_detail(e);
      if (!good_scenarios.count(run.scenario)) {
        if (!loads(run.scenario, sweep.set, &error)) {
          const int line = sweep.set.empty() ? sweep.scenarios_line : sweep.set_lines.front();
          throw InputError(sweep.path, line, (sweep.set.empty() ? "scenarios: " : "set: ") + error);
        }
        good_scenarios.insert(run.scenario);
      }
      for (const auto& [key, value] : run.values) {
        const std::string item = key + "=" + value;
        if (good_values.count(run.scenario + "\n" + item)) continue;
        std::vector<std::string> set = sweep.set;
        set.push_back(set_argument(key, value));
        if (!loads(run.scenario, set, &error)) {
          const auto [where, line] = line_of_value(key, value);
          throw InputError(sweep.path, line, where + "." + key + ": value " + value + ": " + error);
        }
        good_values.insert(run.scenario + "\n" + item);
      }
      throw InputError(sweep.path, sweep.zips.empty() ? sweep.grid_line : sweep.zip_line,
                       "run " + std::to_string(run.index) + " (" + describe_values(run) + "): " + sweep_detail(e));
    }
  }
}

std::vector<RunSpec> suite_runs(const std::vector<std::string>& files, const std::vector<std::string>& set) {
  std::vector<RunSpec> runs;
  for (const std::string& file : files) {
    RunSpec run;
    run.index = runs.size();
    run.scenario = file;
    run.set = set;
    try {
      run.name = load_scenario(file, ScenarioOverrides{set}).name;
    } catch (const InputError& e) {
      // The command's own input (--set, a --params file): every run would fail alike.
      if (is_override_input(e.file(), ScenarioOverrides{set})) throw;
      run.name = fs::path(file).stem().string();
      run.load_error = e.what();
    } catch (const std::exception& e) {  // a sumocfg the scenario names that does not read, ...
      run.name = fs::path(file).stem().string();
      run.load_error = e.what();
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

}  // namespace signalsim
