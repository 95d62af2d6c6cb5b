// `signalsim run SCENARIO --out DIR`: one scenario, one SUMO, the three output files.
#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

#include "app/command.hpp"
#include "app/plot_tool.hpp"
#include "scenario/expectations.hpp"
#include "scenario/input_error.hpp"
#include "scenario/outputs.hpp"
#include "scenario/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "scenario/step_loop.hpp"
#include "sumo/net_index.hpp"
#include "sumo/route_builder.hpp"
#include "sumo/sumo_session.hpp"

namespace signalsim::app {
namespace {

struct RunOptions {
  std::string scenario_path;
  std::string out_dir = "out";
  ScenarioOverrides overrides;
  bool quiet = false;
  bool plot = false;  ///< draw the run's pictures with tools/plot afterwards
};

// Every exit-2 path: the output directory must not keep a previous run's files that could pass for
// this run's, so they are replaced by a summary with status "error" and the message.
int fail(const RunOptions& options, const std::optional<Scenario>& scenario, const std::string& message) {
  try {
    write_error_summary(options.out_dir, scenario ? &*scenario : nullptr, message);
  } catch (const std::exception&) {  // an unwritable directory: the message below is what matters
  }
  return report_bad_input(message);
}

int run(const RunOptions& options) {
  std::optional<Scenario> scenario;
  try {
    scenario = load_scenario(options.scenario_path, options.overrides);
    const sumo::NetIndex net = sumo::NetIndex::load(scenario->net);
    const sumo::RoutePlan plan = plan_route(*scenario, net);
    check_expectations_apply(*scenario, plan.map);

    const auto start = std::chrono::steady_clock::now();
    const RunRecord record = run_scenario(*scenario, plan, net);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto results = evaluate_expectations(*scenario, plan.map, record);
    const RunStatus status = run_status(results);
    write_run_outputs(options.out_dir, *scenario, plan, record, results, status);
    if (!options.quiet) {
      std::printf("%s: %s (%zu steps, %.1f s simulated, %zu events, %.2f s wall)\n", scenario->name.c_str(),
                  std::string(to_string(status)).c_str(), record.rows.size(),
                  record.rows.empty() ? 0.0 : record.rows.back().time, record.events.size(), wall);
      for (const auto& r : results)
        std::printf("  [%s] %s: %s\n", r.passed ? "ok" : "FAIL", r.description.c_str(), r.detail.c_str());
      if (status == RunStatus::NoExpectations)
        std::printf("  the scenario has no expectations (expect:): nothing was checked\n");
    }
    if (options.plot) run_plot_tool({options.out_dir});  // a failed plot is reported, the run's verdict stands
    return status == RunStatus::Failed ? kExitFailed : 0;
  } catch (const InputError& e) {
    return fail(options, scenario, e.what());
  } catch (const sumo::NetError& e) {
    return fail(options, scenario, e.what());
  } catch (const sumo::SumoError& e) {
    return fail(options, scenario, options.scenario_path + ": " + e.what());
  } catch (const std::exception& e) {
    return fail(options, scenario, options.scenario_path + ": " + e.what());
  }
}

}  // namespace

Command add_run_command(CLI::App& app) {
  auto options = std::make_shared<RunOptions>();
  CLI::App* sub = app.add_subcommand("run", "Run one scenario and write timeline.csv, events.csv, summary.json");
  sub->add_option("scenario", options->scenario_path, "Scenario YAML file")->required();
  sub->add_option("--out", options->out_dir, "Output directory (created)")->capture_default_str();
  sub->add_option("--set", options->overrides.set,
                  "Override: a scenario key (seed=3, ego.max_speed=10, country=de) or a parameter "
                  "(turn_signal_search_time=2.5); repeatable");
  sub->add_flag("--quiet", options->quiet, "Print nothing on success");
  sub->add_flag("--plot", options->plot, "Draw PNGs of the run into OUT/plots with tools/plot");
  return {sub, [options] { return run(*options); }};
}

}  // namespace signalsim::app
