// The stuck rule (step/stuck_watch): a run whose ego cannot arrive ends early as a
// clear failure with the reason, while every rest signalsim itself asks for (a red light, a lane
// change's hold point, the pull-over goal) never counts. Real libsumo on real nets, plus the watch
// alone.
#include <gtest/gtest.h>

#include <string>

#include "report/expectations.hpp"
#include "report/outputs.hpp"
#include "step/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "sim/step_loop.hpp"
#include "step/stuck_watch.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"

namespace signalsim {
namespace {

struct Outcome {
  RunRecord record;
  std::vector<ExpectationResult> results;
};

Outcome run(const std::string& relative, const ScenarioOverrides& overrides = {}) {
  const Scenario scenario = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/" + relative, overrides);
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  Outcome r{run_scenario(scenario, plan, net), {}};
  r.results = evaluate_expectations(scenario, plan.map, r.record);
  return r;
}

// The first row of the rest the run ended in.
double rest_start(const RunRecord& r) {
  double start = r.rows.back().time;
  for (auto it = r.rows.rbegin(); it != r.rows.rend() && it->speed < 0.01; ++it) start = it->time;
  return start;
}

TEST(StuckRun, BehindAVehicleThatNeverMovesTheRunEndsAsAFailureWithTheReason) {
  const Outcome r = run("tests/data/scenarios/stuck_behind_obstacle.yaml");  // duration 300 s
  EXPECT_FALSE(r.record.arrived);
  ASSERT_TRUE(r.record.not_arrived.has_value());
  const NotArrived& n = *r.record.not_arrived;
  EXPECT_EQ(n.reason, "stuck");
  // The light 'C' after the parked car is red part of the time: while a judge asks for a stop the
  // stuck clock pauses (a queue at a long red is no deadlock), so the run ends once the rests
  // without a stop request add up to stuck_rest_time.
  double unheld = 0.0, paused = 0.0;
  const double start = rest_start(r.record);
  for (std::size_t i = 1; i < r.record.rows.size(); ++i) {
    const TimelineRow& row = r.record.rows[i];
    if (row.time <= start) continue;
    (r.record.rows[i - 1].stop_s ? paused : unheld) += row.time - r.record.rows[i - 1].time;
  }
  EXPECT_NEAR(unheld, 60.0, 0.15) << "after stuck_rest_time at rest without a stop request";
  EXPECT_GT(paused, 1.0) << "the red phases paused the clock";
  EXPECT_LT(r.record.rows.back().time, 150.0) << "long before the 300 s duration";
  EXPECT_EQ(n.edge, "mid");
  EXPECT_EQ(n.lane, "mid_0");
  EXPECT_NEAR(n.s_front, 152.58 + 100.0 - 4.5 - 2.5, 0.05) << "the parked car's rear less SUMO's minGap";
  EXPECT_TRUE(n.held_by.empty());
  ASSERT_TRUE(n.leader.has_value());
  EXPECT_EQ(n.leader->id, "parked");
  EXPECT_NEAR(n.leader->gap, 2.5, 0.05);
  EXPECT_NE(n.detail.find("behind vehicle 'parked'"), std::string::npos) << n.detail;
  ASSERT_FALSE(r.results.empty());
  EXPECT_EQ(r.results.back().description, "ego arrives (not stuck)");
  EXPECT_FALSE(r.results.back().passed);
  EXPECT_EQ(run_status(r.results), RunStatus::Failed);
}

TEST(StuckRun, ZeroSwitchesTheRuleOffAndTheDurationEndRecordsWhy) {
  const Outcome r = run("tests/data/scenarios/stuck_behind_obstacle.yaml", {{"stuck_rest_time=0"}});
  ASSERT_TRUE(r.record.not_arrived.has_value());
  EXPECT_EQ(r.record.not_arrived->reason, "duration");
  EXPECT_NEAR(r.record.rows.back().time, 300.0, 0.15);
  ASSERT_TRUE(r.record.not_arrived->leader.has_value()) << "at rest, not held: SUMO's reason is looked up";
  EXPECT_EQ(r.record.not_arrived->leader->id, "parked");
  for (const ExpectationResult& e : r.results) EXPECT_NE(e.description, "ego arrives (not stuck)");
}

TEST(StuckRun, WaitingAtARedLightIsNotStuck) {
  // At rest at C from 36.4 s until the green at 40 s, longer than 2 s.
  const Outcome r = run("scenarios/tl_red_stop_then_go.yaml", {{"stuck_rest_time=2"}});
  ASSERT_EQ(r.record.stops.size(), 1u);
  EXPECT_LT(r.record.stops[0].time, 40.0 - 2.0);
  EXPECT_TRUE(r.record.arrived);
  EXPECT_FALSE(r.record.not_arrived.has_value());
  EXPECT_EQ(run_status(r.results), RunStatus::Passed);
}

TEST(StuckRun, WaitingAtALaneChangeHoldPointIsNotStuck) {
  // At rest at the hold point from about 18.6 s until the approval at 21.0 s.
  const Outcome r = run("scenarios/lane_change_hold_until_approved.yaml", {{"stuck_rest_time=1"}});
  EXPECT_TRUE(r.record.arrived);
  EXPECT_EQ(run_status(r.results), RunStatus::Passed);
}

TEST(StuckRun, AtThePullOverGoalTheRunEndsAtItsDurationHeldBySignalsim) {
  const Outcome r = run("scenarios/pull_over_right.yaml", {{"stuck_rest_time=5"}});  // at rest from 44.5 s
  ASSERT_TRUE(r.record.not_arrived.has_value());
  EXPECT_EQ(r.record.not_arrived->reason, "duration");
  EXPECT_EQ(r.record.not_arrived->held_by, "the pull-over goal");
  EXPECT_FALSE(r.record.not_arrived->leader.has_value());
  EXPECT_EQ(run_status(r.results), RunStatus::Passed) << "the goal is where the scenario wants it";
}

TEST(StuckWatch, OnlyAnUnheldRestRunsTheClock) {
  StuckWatch w(1.0);
  EXPECT_FALSE(w.observe(0.0, 0.0, ""));
  EXPECT_FALSE(w.observe(0.5, 0.0, "stopped for light C"));  // held: the clock restarts
  EXPECT_FALSE(w.observe(0.6, 0.0, ""));
  EXPECT_FALSE(w.observe(1.5, 0.0, ""));
  EXPECT_TRUE(w.observe(1.6, 0.0, ""));
  EXPECT_DOUBLE_EQ(w.at_rest_for(), 1.6);
  EXPECT_NEAR(w.stuck_for(), 1.0, 1e-12);
  EXPECT_FALSE(w.observe(1.7, 0.5, ""));  // moving
  EXPECT_FALSE(w.at_rest());
  EXPECT_FALSE(w.observe(1.8, -0.3, ""));  // backing up is not a rest
  StuckWatch off(0.0);
  for (int k = 0; k < 100; ++k) EXPECT_FALSE(off.observe(k, 0.0, ""));
}

TEST(StuckWatch, AQueueBeforeARedLightPausesTheClockWithoutRestartingIt) {
  StuckWatch w(1.0);
  EXPECT_FALSE(w.observe(0.0, 0.0, ""));
  EXPECT_FALSE(w.observe(0.6, 0.0, ""));        // 0.6 s counted
  EXPECT_FALSE(w.observe(0.7, 0.0, "", true));  // queued: paused
  EXPECT_FALSE(w.observe(5.0, 0.0, "", true));  // a long red: still paused
  EXPECT_NEAR(w.stuck_for(), 0.6, 1e-12);
  EXPECT_FALSE(w.observe(5.1, 0.0, ""));        // green again: counting resumes from here
  EXPECT_FALSE(w.observe(5.4, 0.0, ""));
  EXPECT_TRUE(w.observe(5.5, 0.0, ""));         // 0.6 + 0.4 s
  EXPECT_NEAR(w.stuck_for(), 1.0, 1e-12);
  EXPECT_NEAR(w.at_rest_for(), 5.5, 1e-12);
}

TEST(StuckWatch, WithoutALeaderTheJunctionTheEgoWaitsAtIsNamed) {
  RouteMap route;
  Lanelet approach;
  approach.lane_id = "in_0";
  approach.edge_id = "in";
  approach.s_start = 0.0;
  approach.length = 100.0;
  Lanelet inside;
  inside.lane_id = ":K_0_0";
  inside.edge_id = ":K_0";
  inside.junction_id = "K";
  inside.is_internal = true;
  inside.s_start = 100.0;
  inside.length = 5.0;
  route = RouteMap({approach, inside});
  StuckWatch w(10.0);
  w.observe(0.0, 0.0, "");
  w.observe(10.0, 0.0, "");
  TimelineRow row;
  row.time = 10.0;
  row.s_front = 95.0;
  row.edge = "in";
  row.lane = "in_0";
  const std::optional<LeaderInfo> none;
  const NotArrived n = not_arrived("stuck", 60.0, row, w, none, route);
  EXPECT_EQ(n.junction, "K");
  EXPECT_NE(n.detail.find("held by SUMO at junction K"), std::string::npos) << n.detail;
  row.s_front = 50.0;  // 50 m before it: no reason SUMO tells
  EXPECT_EQ(not_arrived("stuck", 60.0, row, w, none, route).junction, "");
}

}  // namespace
}  // namespace signalsim
