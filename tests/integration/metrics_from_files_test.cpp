// batch's fallback for a summary.json without metrics (app/run_outputs metrics_from_run_dir) must
// give the same metrics as the run itself, maneuver sections included: each bundled maneuver
// scenario runs on the real libsumo, its files are written, and the metrics are recomputed from them.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "batch/run_outputs.hpp"
#include "report/expectations.hpp"
#include "report/metrics.hpp"
#include "report/outputs.hpp"
#include "step/route_planning.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;

class MetricsFromFiles : public ::testing::TestWithParam<std::string> {};

TEST_P(MetricsFromFiles, MatchTheRunsOwn) {
  const std::string file = std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + GetParam() + ".yaml";
  const Scenario scenario = load_scenario(file);
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  const RunRecord record = run_scenario(scenario, plan, net);
  const nlohmann::ordered_json own = metrics_json(scenario, plan.map, record);
  const fs::path dir = fs::temp_directory_path() / ("signalsim_metrics_files_" + GetParam());
  fs::remove_all(dir);
  const auto results = evaluate_expectations(scenario, plan.map, record);
  write_run_outputs(dir.string(), scenario, plan, record, results, run_status(results));
  const nlohmann::ordered_json from_files = metrics_from_run_dir(dir.string(), file, {});
  EXPECT_EQ(from_files.dump(1), own.dump(1));
  // The maneuver sections are there (not only the route's turns).
  bool maneuver = false;
  for (const auto& section : own["sections"]) {
    const std::string kind = section["kind"];
    maneuver = maneuver || kind == "lane_change" || kind == "avoidance" || kind == "pull_out" || kind == "pull_over";
  }
  EXPECT_TRUE(maneuver);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Maneuvers, MetricsFromFiles,
                         ::testing::Values("two_lane_changes", "lane_change_waits_for_gap", "avoidance_left",
                                           "pull_out_left", "pull_over_right"));

}  // namespace
}  // namespace signalsim
