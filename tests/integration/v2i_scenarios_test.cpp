// V2I (docs/behaviour.md §L1.7) end to end on the real libsumo: the bundled pair (the green that ends before
// the ego can pass: a normal stop at the line with V2I, the dilemma zone without), and the V2I
// channel's faults judged by what the ego does (a blackout or dropout takes the prediction away,
// latency delays it).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "step/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"

namespace signalsim {
namespace {

RunRecord run(const std::string& name, const ScenarioOverrides& overrides = {}) {
  const Scenario scenario =
      load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml", overrides);
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  return run_scenario(scenario, plan_route(scenario, net), net);
}

const TimelineRow* first_v2i_stop(const RunRecord& r) {
  for (const TimelineRow& row : r.rows)
    if (row.v2i_stop) return &row;
  return nullptr;
}

bool entered_dilemma_zone(const RunRecord& r) {
  for (const TimelineRow& row : r.rows)
    if (row.zone == JudgeZone::DilemmaZone) return true;
  return false;
}

// What every run without a usable V2I prediction does on this approach: the dilemma zone.
void expect_dilemma(const RunRecord& r) {
  EXPECT_TRUE(entered_dilemma_zone(r));
  ASSERT_EQ(r.stops.size(), 1u);
  EXPECT_EQ(r.stops[0].decision, JudgeDecision::EmergencyStop);
  EXPECT_EQ(first_v2i_stop(r), nullptr);
}

TEST(V2iScenarios, WithV2iTheEgoStopsNormallyAtTheLine) {
  const RunRecord r = run("tl_v2i_red_predicted_stop");
  const TimelineRow* first = first_v2i_stop(r);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->tl_state, 'G') << "V2I stops the ego while the light is still green";
  ASSERT_TRUE(first->stop_distance);
  EXPECT_GT(*first->stop_distance, 295.0) << "as soon as the light is judged, 300 m ahead";
  ASSERT_TRUE(first->v2i_time_to_red);
  EXPECT_NEAR(*first->v2i_time_to_red, 23.0 - first->time, 1e-6) << "red at 23 s: the end of the yellow";
  EXPECT_EQ(first->tl_decision, JudgeDecision::Stop);
  EXPECT_FALSE(entered_dilemma_zone(r));
  ASSERT_EQ(r.stops.size(), 1u);
  EXPECT_EQ(r.stops[0].decision, JudgeDecision::Stop);
  EXPECT_NE(r.stops[0].worst_level, StopLevel::Emergency);
  EXPECT_LE(std::abs(r.stops[0].error), 0.3);
  EXPECT_TRUE(r.red_violations.empty());
  EXPECT_TRUE(r.arrived);
  // The stop never lapses between the first V2I stop and the rest: the ego brakes once.
  for (const TimelineRow& row : r.rows)
    if (row.time >= first->time && row.time <= r.stops[0].time) {
      EXPECT_EQ(row.tl_decision, JudgeDecision::Stop) << "t=" << row.time;
    }
}

TEST(V2iScenarios, WithoutV2iTheEgoRunsIntoTheDilemmaZone) {
  const RunRecord r = run("tl_v2i_off_dilemma");
  expect_dilemma(r);
  for (const TimelineRow& row : r.rows)
    if (row.zone == JudgeZone::DilemmaZone) {
      EXPECT_EQ(row.tl_state, 'y') << "the yellow comes in the dilemma zone";
      break;
    }
  EXPECT_TRUE(r.red_violations.empty());
}

TEST(V2iScenarios, ABlackoutOverTheApproachTakesThePredictionAway) {
  expect_dilemma(run("tl_v2i_red_predicted_stop", {{"perception.v2i.blackouts=[[0, 60]]"}}));
}

TEST(V2iScenarios, FullDropoutTakesThePredictionAway) {
  expect_dilemma(run("tl_v2i_red_predicted_stop", {{"perception.v2i.dropout_probability=1.0"}}));
}

TEST(V2iScenarios, ABlackoutEndingInTimeLetsV2iStopLater) {
  // V2I is back at 12 s (d ~ 190 m), still far enough for a normal stop.
  const RunRecord r = run("tl_v2i_red_predicted_stop", {{"perception.v2i.blackouts=[[0, 12]]"}});
  const TimelineRow* first = first_v2i_stop(r);
  ASSERT_NE(first, nullptr);
  EXPECT_NEAR(first->time, 12.1, 1e-6) << "the first message after the blackout";
  EXPECT_FALSE(entered_dilemma_zone(r));
  ASSERT_EQ(r.stops.size(), 1u);
  EXPECT_EQ(r.stops[0].decision, JudgeDecision::Stop);
}

TEST(V2iScenarios, LatencyDelaysTheStopByItsLength) {
  const RunRecord prompt = run("tl_v2i_red_predicted_stop");
  const RunRecord late = run("tl_v2i_red_predicted_stop", {{"perception.v2i.latency=0.5"}});
  const TimelineRow* a = first_v2i_stop(prompt);
  const TimelineRow* b = first_v2i_stop(late);
  ASSERT_NE(a, nullptr);
  ASSERT_NE(b, nullptr);
  EXPECT_NEAR(b->time - a->time, 0.5, 1e-6);
  // The late message tells the same red: 0.5 s less left when it arrives.
  EXPECT_NEAR(*a->v2i_time_to_red - *b->v2i_time_to_red, 0.5, 1e-6);
  ASSERT_EQ(late.stops.size(), 1u);
  EXPECT_EQ(late.stops[0].decision, JudgeDecision::Stop);
}

TEST(V2iScenarios, TheCamerasFaultsApplyToV2iUnlessItHasItsOwn) {
  const RunRecord prompt = run("tl_v2i_red_predicted_stop");
  const RunRecord shared = run("tl_v2i_red_predicted_stop", {{"perception.latency=0.5"}});
  const RunRecord own = run("tl_v2i_red_predicted_stop", ScenarioOverrides{{"perception.latency=0.5", "perception.v2i.latency=0"}});
  ASSERT_NE(first_v2i_stop(prompt), nullptr);
  ASSERT_NE(first_v2i_stop(shared), nullptr);
  ASSERT_NE(first_v2i_stop(own), nullptr);
  EXPECT_NEAR(first_v2i_stop(shared)->time - first_v2i_stop(prompt)->time, 0.5, 1e-6);
  EXPECT_NEAR(first_v2i_stop(own)->time, first_v2i_stop(prompt)->time, 1e-6);
}

}  // namespace
}  // namespace signalsim
