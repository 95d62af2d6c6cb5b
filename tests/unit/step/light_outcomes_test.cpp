// What a rest before a light is (step/light_outcomes): the ego's own stop at the light, or a module's
// hold that happens to lie before it; and when the judge alone decides the next junction
// (light_decides_next_junction): on the approach lane, or within reach of the line of a light the ego
// stops for, whatever lanes lie between.
#include <gtest/gtest.h>

#include <vector>

#include "route_fixture.hpp"
#include "step/light_outcomes.hpp"
#include "step/light_stage.hpp"

namespace signalsim {
namespace {

// 100 m approach `a` to light C (its line at s = 100), a 0.2 m stub beyond a junction would be the
// same: the line is what counts.
RouteMap approach_route() {
  test::RouteFixture f;
  f.lane("a", 100.0);
  f.internal("C", 0, 10.0, TurnDirection::Straight, 13.89);
  f.lane("b", 100.0);
  return f.build();
}

sumo::ApproachLight light_c() {
  sumo::ApproachLight light;
  light.route_index = 0;
  light.tls_id = "C";
  light.s_stop_line = 100.0;
  return light;
}

LightStep stop_requested(const sumo::ApproachLight& light, double s_front) {
  LightStep step;
  step.light = &light;
  step.own_state = 'r';
  step.judged = true;
  step.front_to_stop_line = light.s_stop_line - s_front;
  step.result.decision = JudgeDecision::Stop;
  step.result.stop_point_distance = step.front_to_stop_line;
  return step;
}

TimelineRow at_rest(double s_front, const char* limited_by) {
  TimelineRow row;
  row.time = 20.0;
  row.s_front = s_front;
  row.speed = 0.0;
  row.speed_limited_by = limited_by;
  return row;
}

// The record after one row at rest at `s_front` while light C asks for a stop.
RunRecord rest_before_red(double s_front, const char* limited_by) {
  const RouteMap route = approach_route();
  const sumo::ApproachLight light = light_c();
  const std::vector<LightStep> lights = {stop_requested(light, s_front)};
  LightOutcomes outcomes(0.0);
  RunRecord record;
  outcomes.observe(at_rest(s_front, limited_by), lights, &lights[0], std::nullopt, route, record);
  return record;
}

TEST(LightOutcomes, ARestTheLightsStopSetsIsAStopAtTheLight) {
  const RunRecord record = rest_before_red(99.98, "light_stop");
  ASSERT_EQ(record.stops.size(), 1u);
  EXPECT_EQ(record.stops[0].tl_id, "C");
  EXPECT_NEAR(record.stops[0].error, -0.02, 1e-9);
}

TEST(LightOutcomes, ALaneChangeWaitingForAGapBeforeARedLightIsNoStopAtTheLight) {
  const RunRecord record = rest_before_red(60.0, "lane_change_hold");
  EXPECT_TRUE(record.stops.empty()) << "the hold point's rest, 40 m before the line";
  for (const char* hold : {"avoidance_hold", "pull_out_wait", "pull_over_goal"}) EXPECT_TRUE(held_by_module(hold));
  EXPECT_FALSE(held_by_module("light_stop"));
}

TEST(LightDecidesNextJunction, WithinReachOfTheLineOfALightTheEgoStopsForWhateverLanesLieBetween) {
  test::RouteFixture f;  // a tiny junction B 3 m before the light's line: the front is in B
  f.lane("in", 100.0);
  f.internal("B", 0, 6.8, TurnDirection::Straight, 13.89);
  f.lane("stub", 0.2);
  f.internal("C", 0, 10.0, TurnDirection::Straight, 13.89);
  f.lane("out", 100.0);
  const RouteMap route = f.build();
  sumo::ApproachLight light = light_c();
  light.route_index = 2;
  light.s_stop_line = 107.0;
  const double in_b = 104.0;  // 3 m before the line, inside B
  EXPECT_TRUE(light_decides_next_junction(route, in_b, {stop_requested(light, in_b)}));
  LightStep pass = stop_requested(light, in_b);
  pass.result.stop_point_distance.reset();  // the judge lets it pass: SUMO's right of way stays
  EXPECT_FALSE(light_decides_next_junction(route, in_b, {pass}));
  EXPECT_FALSE(light_decides_next_junction(route, 90.0, {stop_requested(light, 90.0)})) << "17 m before: B is SUMO's";
  LightStep green = stop_requested(light, in_b);
  green.own_state = 'G';
  EXPECT_FALSE(light_decides_next_junction(route, in_b, {green}));
}

}  // namespace
}  // namespace signalsim
