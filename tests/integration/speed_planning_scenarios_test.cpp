// Speed planning under a pending stop, end to end on the real libsumo: a stop far ahead
// never holds the ego's speed down; it drives at the lane limits and brakes when the normal
// jerk-limited profile says so, from rest, at a green light with a red one behind it, and after
// slowing down for a bend.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "step/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"

namespace signalsim {
namespace {

RunRecord run(const std::string& path, const ScenarioOverrides& overrides = {}) {
  const Scenario scenario = load_scenario(path, overrides);
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  return run_scenario(scenario, plan, net);
}

std::string source(const std::string& relative) { return std::string(SIGNALSIM_SOURCE_DIR) + "/" + relative; }

// The highest speed from `from` s (inclusive) until `until` s of simulated time.
double peak_speed(const RunRecord& r, double from, double until, const std::string& edge = "") {
  double peak = 0.0;
  for (const TimelineRow& row : r.rows)
    if (row.time >= from && row.time < until && (edge.empty() || row.edge == edge)) peak = std::max(peak, row.speed);
  return peak;
}

TEST(SpeedPlanning, FromRestTwoHundredMetresBeforeARedLineItSpeedsUpAndStopsAtTheNormalLevel) {
  // Red until 40 s, the line at s = 389.6 m, the ego at rest at s = 200 m.
  const RunRecord r = run(source("scenarios/tl_red_stop_then_go.yaml"), {{"ego.depart_speed=0", "ego.depart_pos=200"}});
  ASSERT_EQ(r.stops.size(), 1u) << "before: it crept at 0.2 m/s and never reached the line while red";
  const LightStop& stop = r.stops[0];
  EXPECT_EQ(stop.tl_id, "C");
  EXPECT_EQ(stop.decision, JudgeDecision::Stop);
  EXPECT_LT(stop.time, 30.0) << "at the line well before the green at 40 s";
  EXPECT_LE(std::abs(stop.error), 0.3);
  EXPECT_EQ(stop.worst_level, StopLevel::Normal) << "no harsher level than the normal one";
  EXPECT_GE(peak_speed(r, 0.0, stop.time), 12.0) << "as fast as a normal stop at the line allows";
  EXPECT_TRUE(r.red_violations.empty());
  EXPECT_TRUE(r.arrived);
}

TEST(SpeedPlanning, AGreenLightWithARedOneBehindItDoesNotHoldTheEgo) {
  // A and B 40 m apart in antiphase (80 s cycle): A red until 40 s while B is green, then A green
  // while B is red until 80 s. The ego waits at A; at A's green it drives on and stops at B.
  const RunRecord r = run(source("tests/data/scenarios/two_lights_antiphase.yaml"));
  ASSERT_EQ(r.stops.size(), 2u);
  EXPECT_EQ(r.stops[0].tl_id, "A");
  EXPECT_EQ(r.stops[1].tl_id, "B");
  EXPECT_GE(peak_speed(r, 40.0, 43.0), 2.0) << "pulls away at A's green (before: 0.2 m/s, held by B's stop)";
  EXPECT_LT(r.stops[1].time, 60.0) << "at rest at B long before B's green";
  for (const LightStop& s : r.stops) {
    EXPECT_LE(std::abs(s.error), 0.3) << s.tl_id;
    EXPECT_EQ(s.worst_level, StopLevel::Normal) << s.tl_id;
  }
  EXPECT_TRUE(r.red_violations.empty());
  EXPECT_TRUE(r.arrived);
}

TEST(SpeedPlanning, AfterSlowingForABendItSpeedsUpAgainWhileAFarRedLightIsPending) {
  // A 3.9 m/s bend 250 m before light C (red until 60 s): C's stop is pending through the bend.
  const RunRecord r = run(source("tests/data/scenarios/bend_then_red.yaml"));
  bool pending_in_bend = false;
  for (const TimelineRow& row : r.rows)
    pending_in_bend = pending_in_bend || (row.edge == ":K_0" && row.tl_decision == JudgeDecision::Stop);
  ASSERT_TRUE(pending_in_bend) << "the scenario must brake for the bend with the stop already requested";
  ASSERT_EQ(r.stops.size(), 1u);
  EXPECT_LE(std::abs(r.stops[0].error), 0.3) << "before: at rest right after the bend, 248.6 m short";
  EXPECT_EQ(r.stops[0].worst_level, StopLevel::Normal);
  EXPECT_LT(r.stops[0].time, 60.0);
  EXPECT_GE(peak_speed(r, 0.0, r.stops[0].time, "mid"), 13.0) << "back to the lane limit after the bend";
  EXPECT_TRUE(r.red_violations.empty());
  EXPECT_TRUE(r.arrived);
}

}  // namespace
}  // namespace signalsim
