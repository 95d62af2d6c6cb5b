// The bundled autoware_core decider through its exported C functions (dlopen of the built module):
// blinker on/off positions on synthetic routes (a left turn, a right turn, a straight junction before
// a turn, a roundabout) as autoware_core path_generator's get_turn_signal gives them
// (planning/autoware_path_generator/src/utils.cpp, commit 2d693b82; docs/autoware_core.md).
// Vehicle: base_link_to_front 3.7 m. Defaults: search_distance 30 m, search_time 3 s, 15 deg.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plugin_loader.hpp"
#include "route_sketch.hpp"

namespace signalsim::test {
namespace {

constexpr double kFront = 3.7;
constexpr double kTol = 0.011;  // the sweep's 0.01 m grid
const double kDeg = std::acos(-1.0) / 180.0;

// The chord of `step_deg` on a circle of `radius`: the spacing of an arc's centerline points.
double chord(double radius, double step_deg) { return 2.0 * radius * std::sin(step_deg * kDeg / 2.0); }

// A turn of 90 deg (r 10 m, 16 points, 6 deg apart) between two 100 m lanes, then a 10 m straight
// junction lane and a 100 m goal lane.
RouteSketch turn_route(double angle_deg, ss_turn_direction turn) {
  RouteSketch r;
  r.straight("A", 100.0).arc("J", 10.0, angle_deg, 16, turn).straight("B", 100.0);
  r.straight("K", 10.0, SS_TURN_STRAIGHT).straight("C", 100.0);
  return r;
}

// The required end of that turn (get_turn_signal_required_end_point): the first centerline point
// whose spline heading is within 15 deg of the terminal heading. The natural spline's headings at the
// points are 72.0, 77.9 deg (points 12, 13) and 88.3 deg at the end, so point 13.
double turn_required_end(double turn_start) { return turn_start + 13.0 * chord(10.0, 6.0); }

TEST(AutowareCorePlugin, AbiVersionAndName) {
  EXPECT_EQ(plugin().abi_version(), SIGNALSIM_PLUGIN_ABI_VERSION);
  EXPECT_EQ(std::string(plugin().name()), "autoware_core path_generator 2d693b82");
}

TEST(AutowareCorePlugin, NullInputsAreErrorsNotCrashes) {
  char error[128] = "";
  EXPECT_EQ(plugin().create(nullptr, error, sizeof error), nullptr);
  EXPECT_STRNE(error, "");
  ss_blinker b = SS_BLINKER_NONE;
  EXPECT_NE(plugin().step(nullptr, nullptr, &b, error, sizeof error), 0);
}

// Ahead of a turn lanelet the command is on once the front's distance to its start is at most
// search_distance + v * search_time (`arc_length_from_vehicle_front_to_lanelet_start >
// turn_signal_distance` gives NO_COMMAND); inside it, on while base_link's arc is at most the
// required end's; past it the next turn lanelet (the straight junction K, 86 m ahead) decides:
// NO_COMMAND, off. K itself is `straight`: DISABLE, off.
TEST(AutowareCorePlugin, LeftTurnOnAtSearchDistanceOffAtRequiredEnd) {
  const RouteSketch route = turn_route(90.0, SS_TURN_LEFT);
  const auto got = sections(route.run(kFront), 0.0, 300.0, 10.0);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].blinker, SS_BLINKER_LEFT);
  EXPECT_NEAR(got[0].on, 100.0 - kFront - 60.0, kTol);  // 36.3
  EXPECT_NEAR(got[0].off, turn_required_end(100.0), kTol);  // 113.61
}

TEST(AutowareCorePlugin, RightTurnMirrorsLeft) {
  const RouteSketch route = turn_route(-90.0, SS_TURN_RIGHT);
  const auto got = sections(route.run(kFront), 0.0, 300.0, 10.0);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].blinker, SS_BLINKER_RIGHT);
  EXPECT_NEAR(got[0].on, 36.3, kTol);
  EXPECT_NEAR(got[0].off, turn_required_end(100.0), kTol);
}

// Past the required end the turn's command is still the one set; with no turn lanelet ahead (only
// the goal lanelet, which get_next_lanelet_within_route excludes) the loop ends and returns it: the
// blinker stays on until base_link leaves the turn lanelet.
TEST(AutowareCorePlugin, TurnBeforeGoalStaysOnToTheLaneletsEnd) {
  RouteSketch route;
  route.straight("A", 100.0).arc("J", 10.0, 90.0, 16, SS_TURN_LEFT).straight("B", 100.0);
  const auto got = sections(route.run(kFront), 0.0, 200.0, 10.0);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_NEAR(got[0].on, 36.3, kTol);
  EXPECT_NEAR(got[0].off, route.s_start("B"), kTol);
}

// Nothing is remembered: the search distance follows the speed of each step, so braking can switch
// the blinker off again; backing up shortens it (v is signed).
TEST(AutowareCorePlugin, SearchDistanceFollowsEachStepsSpeed) {
  const RouteSketch route = turn_route(90.0, SS_TURN_LEFT);
  Decider decider(route.run(kFront));
  EXPECT_EQ(decider.at(45.0, 10.0), SS_BLINKER_LEFT);  // 51.3 m <= 60 m
  EXPECT_EQ(decider.at(46.0, 3.0), SS_BLINKER_NONE);   // 50.3 m > 39 m
  EXPECT_EQ(decider.at(60.0, 3.0), SS_BLINKER_LEFT);   // 36.3 m <= 39 m
  EXPECT_EQ(decider.at(72.2, -2.0), SS_BLINKER_NONE);  // 24.1 m > 24 m
  EXPECT_EQ(decider.at(72.4, -2.0), SS_BLINKER_LEFT);
  EXPECT_EQ(decider.at(250.0, 10.0), SS_BLINKER_NONE);  // on the goal lanelet
  EXPECT_EQ(decider.at(-5.0, 10.0), SS_BLINKER_NONE);   // before the route: no lanelet contains it
}

// The lanelet's turn_signal_distance replaces the speed-based distance (attributeOr).
TEST(AutowareCorePlugin, TurnSignalDistanceAttribute) {
  RouteSketch route;
  route.straight("A", 100.0).arc("J", 10.0, 90.0, 16, SS_TURN_LEFT).turn_signal_distance(20.0);
  route.straight("B", 100.0).straight("K", 10.0, SS_TURN_STRAIGHT).straight("C", 100.0);
  const auto got = sections(route.run(kFront), 0.0, 300.0, 10.0);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_NEAR(got[0].on, 100.0 - kFront - 20.0, kTol);  // 76.3
}

// The first turn lanelet ahead decides and returns: a straight junction lane S ahead gives DISABLE
// (or NO_COMMAND beyond the distance) and hides the left turn L behind it. Once base_link is inside S
// (a straight lane: required end at its start) S is passed and L, 56.3 m ahead, is on at once.
// (signalsim's reference would be on at L's start - 3.7 - 60 = 96.3.)
TEST(AutowareCorePlugin, StraightJunctionAheadHidesTheNextTurn) {
  RouteSketch route;
  route.straight("A", 100.0).straight("S", 20.0, SS_TURN_STRAIGHT).straight("B", 40.0);
  route.arc("L", 10.0, 90.0, 16, SS_TURN_LEFT).straight("C", 100.0);
  route.straight("K", 10.0, SS_TURN_STRAIGHT).straight("D", 100.0);
  const auto got = sections(route.run(kFront), 0.0, 380.0, 10.0);
  ASSERT_EQ(got.size(), 1u);
  EXPECT_EQ(got[0].blinker, SS_BLINKER_LEFT);
  EXPECT_GT(got[0].on, 100.0);
  EXPECT_LE(got[0].on, 100.0 + kTol);
  EXPECT_NEAR(got[0].off, turn_required_end(160.0), kTol);
}

// A roundabout is lanelets like any other: the entry (right, 45 deg, r 10 m, 10 points 5 deg apart:
// required end at point 6, heading 30.0 deg vs 43.6 deg at the end) is on from 36.3 m; the
// ring-internal junction lane RI (straight) is DISABLE and hides the exit until base_link is in it;
// then the exit (right) is on, and, with no turn lanelet after it, stays on to its end. Roundabout
// roles are not read.
TEST(AutowareCorePlugin, RoundaboutEntryAndExitAreTurns) {
  RouteSketch route;
  route.straight("A", 100.0).arc("E", 10.0, -45.0, 10, SS_TURN_RIGHT, SS_ROUNDABOUT_ENTRY);
  route.arc("R1", 20.0, 90.0, 16, SS_TURN_NONE, SS_ROUNDABOUT_INTERNAL);
  route.arc("RI", 20.0, 10.0, 4, SS_TURN_STRAIGHT, SS_ROUNDABOUT_INTERNAL);
  route.arc("R2", 20.0, 60.0, 11, SS_TURN_NONE, SS_ROUNDABOUT_INTERNAL);
  route.arc("X", 10.0, -45.0, 10, SS_TURN_RIGHT, SS_ROUNDABOUT_EXIT).straight("B", 100.0).straight("G", 50.0);
  const auto got = sections(route.run(kFront), 0.0, 320.0, 10.0);
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].blinker, SS_BLINKER_RIGHT);
  EXPECT_NEAR(got[0].on, 36.3, kTol);
  EXPECT_NEAR(got[0].off, 100.0 + 6.0 * chord(10.0, 5.0), kTol);
  EXPECT_EQ(got[1].blinker, SS_BLINKER_RIGHT);
  EXPECT_GT(got[1].on, route.s_start("RI"));
  EXPECT_LE(got[1].on, route.s_start("RI") + kTol);
  EXPECT_NEAR(got[1].off, route.s_start("B"), kTol);

  const RouteSketch plain = route.without_roundabout_roles();
  const auto same = sections(plain.run(kFront), 0.0, 320.0, 10.0);
  ASSERT_EQ(same.size(), got.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(same[i].on, got[i].on);
    EXPECT_EQ(same[i].off, got[i].off);
  }
}

}  // namespace
}  // namespace signalsim::test
