// The metrics of a bundled roundabout run expect the blinker the decider gives: the entry of
// roundabout_exit_edge_tag_de_exit2 carries exit_turn_signal_left naming its exit by the edge it leads
// onto (out_N), so its section asks for left although the de preset asks for none on entry, and the
// run (real libsumo) serves it.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "net/net_index.hpp"
#include "report/expectations.hpp"
#include "report/metrics.hpp"
#include "step/route_planning.hpp"
#include "sim/step_loop.hpp"

namespace signalsim {
namespace {

TEST(RoundaboutMetrics, EntryTaggedByItsExitEdgeExpectsTheTaggedBlinker) {
  const std::string file = std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/roundabout_exit_edge_tag_de_exit2.yaml";
  const Scenario scenario = load_scenario(file);
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  const RunRecord record = run_scenario(scenario, plan, net);
  ASSERT_TRUE(record.arrived);
  for (const ExpectationResult& r : evaluate_expectations(scenario, plan.map, record))
    EXPECT_TRUE(r.passed) << r.description << ": " << r.detail;

  const nlohmann::ordered_json metrics = metrics_json(scenario, plan.map, record);
  ASSERT_EQ(metrics["sections"].size(), 2u) << metrics["sections"].dump(1);
  const auto& entry = metrics["sections"][0];
  EXPECT_EQ(entry["kind"], "roundabout_entry");
  EXPECT_EQ(entry["lanelets"], nlohmann::ordered_json::array({":RS_0_0"}));
  EXPECT_EQ(entry["blinker"], "left");
  EXPECT_EQ(entry["missed"], false);
  // On from 3 v + 30 before the entry, v the speed there: braking for the entry's limit has begun
  // (68.8 m; 71.7 m at 13.89 m/s).
  EXPECT_GT(entry["lead_distance"].get<double>(), 68.0);
  EXPECT_LT(entry["lead_distance"].get<double>(), 71.7);
  const auto& exit = metrics["sections"][1];
  EXPECT_EQ(exit["kind"], "roundabout_exit");
  EXPECT_EQ(exit["blinker"], "right");  // the de preset's on_exit
  EXPECT_EQ(exit["missed"], false);
  EXPECT_EQ(metrics["missed_signals"], 0);
}

}  // namespace
}  // namespace signalsim
