// signalsim command line: run a scenario, inspect a net.
// Exit codes: 0 all expectations hold, 1 an expectation failed, 2 bad input or a SUMO error.
#include <chrono>
#include <cstdio>
#include <iostream>

#include <CLI/CLI.hpp>

#include "app/inspect.hpp"
#include "scenario/expectations.hpp"
#include "scenario/input_error.hpp"
#include "scenario/outputs.hpp"
#include "scenario/scenario.hpp"
#include "scenario/step_loop.hpp"
#include "sumo/net_index.hpp"
#include "sumo/route_builder.hpp"
#include "sumo/sumo_session.hpp"

namespace {

constexpr int kExitFailedExpectation = 1;
constexpr int kExitBadInput = 2;

int fail(const std::string& message) {
  std::cerr << "signalsim: " << message << "\n";
  return kExitBadInput;
}

int run_command(const std::string& scenario_path, const std::string& out_dir, bool quiet) {
  using namespace signalsim;
  std::optional<Scenario> scenario;
  try {
    scenario = load_scenario(scenario_path);
    const sumo::NetIndex net = sumo::NetIndex::load(scenario->net);
    sumo::RoutePlan plan;
    try {
      plan = sumo::build_route(net, scenario->ego.route);
    } catch (const sumo::RouteError& e) {
      throw InputError(scenario_path, 0, std::string("ego.route: ") + e.what());
    }
    check_expectations_apply(*scenario, plan.map);

    const auto start = std::chrono::steady_clock::now();
    const RunRecord record = run_scenario(*scenario, plan);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const auto results = evaluate_expectations(*scenario, plan.map, record);
    bool all = true;
    for (const auto& r : results) all = all && r.passed;
    const RunStatus status = all ? RunStatus::Passed : RunStatus::Failed;
    write_run_outputs(out_dir, *scenario, plan, record, results, status);
    if (!quiet) {
      std::printf("%s: %s (%zu steps, %.1f s simulated, %zu blinker events, %.2f s wall)\n",
                  scenario->name.c_str(), std::string(to_string(status)).c_str(), record.rows.size(),
                  record.rows.empty() ? 0.0 : record.rows.back().time, record.events.size(), wall);
      for (const auto& r : results)
        std::printf("  [%s] %s: %s\n", r.passed ? "ok" : "FAIL", r.description.c_str(), r.detail.c_str());
    }
    return all ? 0 : kExitFailedExpectation;
  } catch (const InputError& e) {
    return fail(e.what());
  } catch (const sumo::NetError& e) {
    return fail(e.what());
  } catch (const sumo::SumoError& e) {
    const std::string message = scenario_path + ": " + e.what();
    try {
      write_error_summary(out_dir, scenario ? &*scenario : nullptr, message);
    } catch (const std::exception&) {
    }
    return fail(message);
  } catch (const std::exception& e) {
    return fail(scenario_path + ": " + e.what());
  }
}

int inspect_command(const std::string& net_path, const std::vector<std::string>& route) {
  try {
    const auto net = signalsim::sumo::NetIndex::load(net_path);
    signalsim::print_inspection(std::cout, net, route);
    return 0;
  } catch (const signalsim::sumo::RouteError& e) {
    return fail(net_path + ": --route: " + e.what());
  } catch (const std::exception& e) {
    return fail(e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"signalsim: Autoware's turn-signal decider and traffic-light judge on SUMO"};
  app.set_version_flag("--version", "signalsim 0.1.0");
  app.require_subcommand(1);

  std::string scenario_path, out_dir = "out";
  bool quiet = false;
  auto* run = app.add_subcommand("run", "Run one scenario and write timeline.csv, events.csv, summary.json");
  run->add_option("scenario", scenario_path, "Scenario YAML file")->required();
  run->add_option("--out", out_dir, "Output directory (created)")->capture_default_str();
  run->add_flag("--quiet", quiet, "Print nothing on success");

  std::string net_path;
  std::vector<std::string> route;
  auto* inspect = app.add_subcommand("inspect", "Show the lanelets along a route as the decider sees them");
  inspect->add_option("net", net_path, "SUMO .net.xml (plain or gzip)")->required();
  inspect->add_option("--route", route, "Edge ids of a route");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(std::string(e.what()) + " (see 'signalsim --help')");
  }
  if (*run) return run_command(scenario_path, out_dir, quiet);
  if (*inspect) return inspect_command(net_path, route);
  return kExitBadInput;
}
