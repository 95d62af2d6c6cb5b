// Lane choice in the real libsumo on real nets:
//  - connections: where a lane has several connections to the next route edge, the lane plan takes the
//    one SUMO takes (route/sumo_lane_choice.hpp), so the ego arrives on bologna_acosta's route through
//    85_1 (two links to 72[0]); a divergence SUMO makes anyway is recorded (step/plan_watch.hpp):
//    off_plan stretches, and a run ending off the plan says so, never "held by light";
//  - permissions: lane permissions are the ego's own vClass (a taken-over bus may use a bus lane; a
//    truck is never planned onto a lane that forbids trucks);
//  - lights: every light gets its own state at the line and decision, also one crossed while a
//    later light is braked for (two_lights_antiphase: A crossed on green while B is red).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "report/expectations.hpp"
#include "report/metrics.hpp"
#include "step/plan_watch.hpp"
#include "step/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"
#include "route/sumo_lane_choice.hpp"

namespace signalsim {
namespace {

std::string source(const std::string& rel) { return std::string(SIGNALSIM_SOURCE_DIR) + "/" + rel; }
std::string scenario_path(const std::string& name) { return source("tests/data/scenarios/" + name + ".yaml"); }

bool on_route(const sumo::RoutePlan& plan, const std::string& lane) { return plan.map.find_lane(lane).has_value(); }

TEST(LaneChoice, SumoTakesTheLinkToItsBestContinuationTheRightmostOfEquals) {
  const Scenario s = load_scenario(scenario_path("acosta_junction_lane_choice"));
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  std::vector<const sumo::NetEdge*> route;
  for (const std::string& e : s.ego.route) route.push_back(net.edge(e));
  const auto next = sumo::sumo_next_lanes(net, route, {});
  ASSERT_EQ(next.size(), route.size() - 1);
  EXPECT_EQ(next[0][1], 1);  // 85_1 -> 72[0]_1 (via :9_12_1): 134 lies beyond SUMO's look-ahead
  EXPECT_EQ(next[8][0], 0);  // 202 -> 34: straight on each lane
  EXPECT_EQ(next[9][2], 0);  // 34_2 -> 134_0, the only link
  EXPECT_EQ(next[9][0], -1);  // 34_0 has none: SUMO would stop there
}

TEST(LaneChoice, ThePlanTakesSumosConnectionAndTheEgoArrives) {
  const Scenario s = load_scenario(scenario_path("acosta_junction_lane_choice"));
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  const sumo::RoutePlan plan = plan_route(s, net);
  EXPECT_TRUE(on_route(plan, ":9_12_1"));   // was :9_12_2: SUMO took :9_12_1 and never arrived
  EXPECT_FALSE(on_route(plan, ":9_12_2"));
  EXPECT_TRUE(on_route(plan, "34_2"));
  const RunRecord record = run_scenario(s, plan, net);
  EXPECT_TRUE(record.arrived);
  EXPECT_FALSE(record.not_arrived.has_value());
  EXPECT_EQ(record.off_route_steps, 0);
  EXPECT_TRUE(record.off_plan.empty()) << record.off_plan.front().lane << " for " << record.off_plan.front().planned_lane;
  for (const ExpectationResult& r : evaluate_expectations(s, plan.map, record))
    EXPECT_TRUE(r.passed) << r.description << ": " << r.detail;
}

// The divergence report, from the observations SUMO gave on the old plan (SUMO-free).
TEST(PlanWatch, ADivergenceIsRecordedAndARunEndingOffThePlanSaysWhere) {
  const Scenario s = load_scenario(scenario_path("acosta_junction_lane_choice"));
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  const sumo::RoutePlan plan = plan_route(s, net);
  const LateralPlan none;
  PlanWatch watch(plan.map, none);
  RunRecord record;
  const std::size_t on_85 = *plan.map.find_lane("85_1");
  EXPECT_FALSE(watch.observe("85_1", "85", on_85, 10.0, 1.0, record));
  const std::size_t junction = on_85 + 1;  // :9_12_1 in the plan; SUMO on the other connection
  const double s_junction = plan.map.at(junction).s_start + 1.0;
  EXPECT_TRUE(watch.observe(":9_12_2", ":9_12", junction, s_junction, 2.0, record));
  const std::size_t on_72 = *plan.map.find_edge("72[0]");
  EXPECT_TRUE(watch.observe("72[0]_2", "72[0]", on_72, plan.map.at(on_72).s_start + 1.0, 3.0, record));
  EXPECT_TRUE(watch.observe("72[0]_2", "72[0]", on_72, plan.map.at(on_72).s_start + 2.0, 3.1, record));
  ASSERT_EQ(record.off_plan.size(), 2u);
  EXPECT_EQ(record.off_plan[0].lane, ":9_12_2");
  EXPECT_EQ(record.off_plan[1].lane, "72[0]_2");
  EXPECT_EQ(record.off_plan[1].planned_lane, plan.map.at(on_72).lane_id);
  EXPECT_EQ(record.off_plan[1].steps, 2);

  NotArrived n;
  n.reason = "duration";
  n.edge = "72[0]";
  n.lane = "72[0]_2";
  n.held_by = "stopped for light 210";
  watch.explain(n, record);
  EXPECT_EQ(n.reason, "off_plan");
  EXPECT_EQ(n.held_by, "");
  EXPECT_NE(n.detail.find("route edge '72[0]'"), std::string::npos) << n.detail;
  EXPECT_NE(n.detail.find("lane '72[0]_2'"), std::string::npos) << n.detail;
  EXPECT_NE(n.detail.find("the plan's lane is '" + plan.map.at(on_72).lane_id + "'"), std::string::npos) << n.detail;

  // Back on the plan: nothing to explain.
  EXPECT_FALSE(watch.observe(plan.map.at(on_72).lane_id, "72[0]", on_72, plan.map.at(on_72).s_start + 3.0, 3.2, record));
  NotArrived later;
  later.reason = "duration";
  watch.explain(later, record);
  EXPECT_EQ(later.reason, "duration");
}

TEST(LanePermissions, ATakenOverBusMayUseABusLane) {
  const Scenario s = load_scenario(scenario_path("acosta_bus_takeover"));
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  const PlannedRun planned = plan_run(s, net);  // was: exit 2, "which a passenger car may not use"
  EXPECT_EQ(planned.scenario.ego.vclass, "bus");
  EXPECT_TRUE(on_route(planned.plan, "31_1"));  // the bus lane
  const StartedRun run = start_run(planned, net, {});
  EXPECT_EQ(run.scenario.ego.vclass, "bus");
  const RunRecord record = drive(run, net);
  EXPECT_TRUE(record.arrived);
  EXPECT_TRUE(record.off_plan.empty());
}

TEST(LanePermissions, ATruckIsNeverPlannedOntoALaneThatForbidsTrucks) {
  const sumo::NetIndex net = sumo::NetIndex::load(source("tests/data/nets/truck_lanes.net.xml"));
  sumo::LaneChangeEgo car, truck;
  truck.vclass = "truck";
  const sumo::RoutePlan for_car = sumo::build_route(net, {"ab", "bc"}, {}, car);
  EXPECT_EQ(for_car.lane_per_edge[0], 0);  // the rightmost lane
  const sumo::RoutePlan for_truck = sumo::build_route(net, {"ab", "bc"}, {}, truck);
  EXPECT_EQ(for_truck.entry_lane_per_edge[0], 1);  // ab_0 disallows trucks
  EXPECT_EQ(for_truck.lane_per_edge[0], 1);
  EXPECT_EQ(for_truck.lane_per_edge[1], 1);
}

TEST(LightMetricsPerLight, ALightCrossedWhileALaterOneIsBrakedForKeepsItsStateAtTheLine) {
  const Scenario s = load_scenario(scenario_path("two_lights_antiphase"));
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  const sumo::RoutePlan plan = plan_route(s, net);
  const RunRecord record = run_scenario(s, plan, net);
  const RunMetrics m = compute_metrics(s, plan.map, record);
  ASSERT_EQ(m.lights.size(), 2u);
  EXPECT_EQ(m.lights[0].id, "A");
  EXPECT_TRUE(m.lights[0].reached);
  // A turned green, then the ego crossed it while braking for B (red): the rows show B.
  EXPECT_TRUE(m.lights[0].state_at_line == "G" || m.lights[0].state_at_line == "g") << m.lights[0].state_at_line;
  EXPECT_EQ(m.lights[0].red_light_violation, std::optional<bool>(false));
  EXPECT_EQ(m.lights[0].decision, std::optional<std::string>("stop"));  // it stopped at A while red
  EXPECT_EQ(m.lights[1].id, "B");
}

// The review's case (TAVF-Hamburg seed 3), on two_lights: A turned green, and while the ego crosses
// it a judge brakes for B (red), so every row shows B. A's own judge saw green at its line.
TEST(LightMetricsPerLight, EachLightHasItsOwnStateAtTheLineWhateverTheRowsShow) {
  const Scenario s = load_scenario(scenario_path("two_lights_antiphase"));
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  const sumo::RoutePlan plan = plan_route(s, net);
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < plan.map.size(); ++i)
    if (!plan.map.at(i).is_internal && plan.map.at(i).traffic_light) (plan.map.at(i).traffic_light->tls_id == "A" ? a : b) = i;
  const double line_a = plan.map.at(a).stop_line_s();
  RunRecord record;
  for (int k = 0; k * 1.0 < line_a + 5.0; ++k) {
    TimelineRow row;
    row.time = 0.1 * k;
    row.s_front = 1.0 * k;
    const bool early = row.s_front < line_a - 30.0;  // A red and shown; later A green, B braked for
    row.tl_id = early ? "A" : "B";
    row.tl_state = 'r';
    row.tl_decision = JudgeDecision::Stop;
    record.light_log.push_back({record.rows.size(), a, early ? 'r' : 'G', early ? JudgeDecision::Stop : JudgeDecision::Pass,
                                JudgeZone::None});
    record.light_log.push_back({record.rows.size(), b, 'r', JudgeDecision::Stop, JudgeZone::None});
    record.rows.push_back(row);
  }
  const RunMetrics m = compute_metrics(s, plan.map, record);
  ASSERT_EQ(m.lights.size(), 2u);
  EXPECT_EQ(m.lights[0].id, "A");
  EXPECT_EQ(m.lights[0].state_at_line, "G");  // was "": the row before the line showed B
  EXPECT_EQ(m.lights[0].red_light_violation, std::optional<bool>(false));
  EXPECT_EQ(m.lights[0].decision, std::optional<std::string>("stop"));  // its judge's most restrictive
  EXPECT_FALSE(m.lights[1].reached);
}

}  // namespace
}  // namespace signalsim
