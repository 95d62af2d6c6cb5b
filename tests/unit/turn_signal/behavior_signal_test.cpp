// docs/behaviour.md §T8.1 BEHAVIOR_SIGNAL: every branch, threshold and comparison strictness.
#include <gtest/gtest.h>

#include <cmath>

#include "behavior_test_helpers.hpp"
#include "turn_signal/behavior_signal.hpp"

namespace signalsim {
namespace {

using test::ego_front;
using test::is_empty;
using test::is_none;
using test::shift_input;

using test::kParams;

// ---- the signalling result ---------------------------------------------------------------------

TEST(BehaviorSignal, LeftShiftSignalsLeftWithEgoAsDesiredStartWhileTheStartIsAhead) {
  const auto in = shift_input(0.0, 2.0);
  const auto ego = ego_front(95.0);  // front 5 m before the shift start, prep = max(15, 10)
  const auto r = behavior_signal(in, ego, kParams);
  EXPECT_FALSE(r.is_ignore);
  EXPECT_EQ(r.info.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(r.info.hazard, HazardLights::NoCommand);
  EXPECT_EQ(r.info.source, RequestSource::Avoidance);
  EXPECT_EQ(r.info.desired_start, ego.s_base);  // front_to_start > 0 -> ego pose (base_link)
  EXPECT_EQ(r.info.required_start, 100.0);
  EXPECT_EQ(r.info.desired_end, 120.0);
  EXPECT_EQ(r.info.required_end, 120.0);
}

TEST(BehaviorSignal, DesiredStartIsTheShiftStartOncePassed) {
  const auto in = shift_input(0.0, 2.0);
  for (const double front : {100.0, 101.0}) {  // front_to_start 0 and -1: not > 0
    const auto r = behavior_signal(in, ego_front(front), kParams);
    EXPECT_EQ(r.info.turn, TurnIndicator::EnableLeft);
    EXPECT_EQ(r.info.desired_start, 100.0) << front;
  }
}

TEST(BehaviorSignal, DirectionComesFromTheSignOfTheRelativeShift) {
  EXPECT_EQ(behavior_signal(shift_input(0.0, -2.0), ego_front(95.0), kParams).info.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(behavior_signal(shift_input(2.0, 0.0), ego_front(95.0), kParams).info.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(behavior_signal(shift_input(-2.0, 0.0), ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
}

// ---- backward driving and path range ------------------------------------------------------------

TEST(BehaviorSignal, BackwardDrivingGivesHazardFromRouteStartToEgo) {
  auto in = shift_input(0.0, 2.0);
  in.is_driving_forward = false;
  in.route_start = 5.0;
  in.shift_line.s_end = 1e9;  // even an invalid line: the backward branch comes first
  const auto ego = ego_front(40.0, -1.0);
  const auto r = behavior_signal(in, ego, kParams);
  EXPECT_FALSE(r.is_ignore);
  EXPECT_EQ(r.info.hazard, HazardLights::Enable);
  EXPECT_EQ(r.info.turn, TurnIndicator::NoCommand);
  EXPECT_EQ(r.info.desired_start, 5.0);
  EXPECT_EQ(r.info.required_start, 5.0);
  EXPECT_EQ(r.info.desired_end, ego.s_base);
  EXPECT_EQ(r.info.required_end, ego.s_base);
}

TEST(BehaviorSignal, LineBeyondThePathIsEmptyAndIgnored) {
  auto in = shift_input(0.0, 2.0);
  in.path_back = 119.0;  // end index out of range
  auto r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_empty(r.info));
  in.path_back = 120.0;  // the last point itself is in range
  r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_EQ(r.info.turn, TurnIndicator::EnableLeft);
}

// ---- shift length thresholds -------------------------------------------------------------------

// A lane narrower than the car: the footprint always meets a bound, isolating the thresholds.
BehaviorSignalInput narrow(double a, double b) {
  auto in = shift_input(a, b);
  in.lane.left_half_width = in.lane.right_half_width = 0.5;
  return in;
}

TEST(BehaviorSignal, ShiftLengthThresholdIsStrict) {
  auto r = behavior_signal(narrow(0.0, 0.3), ego_front(95.0), kParams);  // |rel| == 0.3: signals
  EXPECT_EQ(r.info.turn, TurnIndicator::EnableLeft);
  EXPECT_FALSE(r.is_ignore);
  const auto in = narrow(0.0, 0.2999);
  r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));
  EXPECT_EQ(r.info.source, RequestSource::Avoidance);
  EXPECT_EQ(behavior_signal(narrow(0.0, -0.3), ego_front(95.0), kParams).info.turn, TurnIndicator::EnableRight);
}

TEST(BehaviorSignal, RemainingShiftThresholdIsStrict) {
  BehaviorSignalParameters p;
  p.turn_signal_remaining_shift_length_threshold = 0.125;  // exactly representable
  auto in = narrow(0.0, 2.0);
  in.current_shift_length = 1.875;  // |b - current| == 0.125: still signals
  auto r = behavior_signal(in, ego_front(95.0), p);
  EXPECT_EQ(r.info.turn, TurnIndicator::EnableLeft);
  in.current_shift_length = 1.9375;  // 0.0625 < 0.125: shift done
  r = behavior_signal(in, ego_front(95.0), p);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));
  in.current_shift_length = 2.0625;  // overshoot by 0.0625 is also "done"
  EXPECT_TRUE(behavior_signal(in, ego_front(95.0), p).is_ignore);
}

TEST(BehaviorSignal, DefaultRemainingThreshold) {
  auto in = narrow(0.0, 2.0);
  in.current_shift_length = 1.95;
  EXPECT_TRUE(behavior_signal(in, ego_front(95.0), kParams).is_ignore);
  in.current_shift_length = 1.85;
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
}

// ---- prepare distance max(v * 3, 10) vs front_to_start -----------------------------------------

TEST(BehaviorSignal, PrepareDistanceSpeedTerm) {
  const auto in = narrow(0.0, 2.0);
  // v = 5 -> prep = 15. front_to_start = 100 - s_front.
  auto r = behavior_signal(in, ego_front(85.0, 5.0), kParams);  // 15 == 15: not too early
  EXPECT_EQ(r.info.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(r.info.desired_start, 85.0 - test::kB2F);
  r = behavior_signal(in, ego_front(84.5, 5.0), kParams);  // 15.5 > 15: too early, not ignored
  EXPECT_FALSE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));
}

TEST(BehaviorSignal, PrepareDistanceFloor) {
  const auto in = narrow(0.0, 2.0);
  // v = 2 -> 3v = 6 < 10 -> prep = 10.
  EXPECT_EQ(behavior_signal(in, ego_front(90.0, 2.0), kParams).info.turn, TurnIndicator::EnableLeft);
  const auto r = behavior_signal(in, ego_front(89.5, 2.0), kParams);
  EXPECT_FALSE(r.is_ignore);
  EXPECT_EQ(r.info.turn, TurnIndicator::NoCommand);
  // Standstill and reversing speeds also use the 10 m floor.
  EXPECT_EQ(behavior_signal(in, ego_front(90.0, 0.0), kParams).info.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(behavior_signal(in, ego_front(90.0, -1.0), kParams).info.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(behavior_signal(in, ego_front(89.5, -1.0), kParams).info.turn, TurnIndicator::NoCommand);
}

TEST(BehaviorSignal, FrontToStartUsesTheFrontBumper) {
  const auto in = narrow(0.0, 2.0);
  // base_link 15 m before the start but front only 11.3 m: within the 15 m prep distance.
  EXPECT_EQ(behavior_signal(in, EgoOnRoute{.s_front = 88.7, .s_base = 85.0, .speed = 5.0}, kParams).info.turn,
            TurnIndicator::EnableLeft);
}

// ---- turn_signal_on_swerving (docs/behaviour.md §T12.1.1) --------------------------------------------------

TEST(BehaviorSignal, OnSwervingFalseDisablesEveryShiftBlinker) {
  BehaviorSignalParameters p;
  p.turn_signal_on_swerving = false;
  auto avoid = shift_input(0.0, 2.0);
  auto r = behavior_signal(avoid, ego_front(95.0), p);
  EXPECT_FALSE(r.is_ignore);  // NONE, not latched
  EXPECT_TRUE(is_none(r.info, avoid));

  auto lane_leaving = shift_input(0.0, 3.5);  // leaves the lane entirely: still no blinker
  EXPECT_EQ(behavior_signal(lane_leaving, ego_front(95.0), p).info.turn, TurnIndicator::NoCommand);

  auto pull_out = shift_input(-2.5, 0.0);
  pull_out.is_pull_out = true;
  pull_out.lane.left_half_width = 3.0;
  EXPECT_EQ(behavior_signal(pull_out, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(behavior_signal(pull_out, ego_front(95.0), p).info.turn, TurnIndicator::NoCommand);

  auto pull_over = shift_input(0.0, -2.5);
  pull_over.is_pull_over = true;
  EXPECT_EQ(behavior_signal(pull_over, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(behavior_signal(pull_over, ego_front(95.0), p).info.turn, TurnIndicator::NoCommand);
}

TEST(BehaviorSignal, TooEarlyTakesPrecedenceOverSwerving) {
  BehaviorSignalParameters p;
  p.turn_signal_on_swerving = false;
  const auto r = behavior_signal(shift_input(0.0, 2.0), ego_front(50.0), p);
  EXPECT_FALSE(r.is_ignore);
  EXPECT_EQ(r.info.turn, TurnIndicator::NoCommand);
}

// ---- route lanelet and hatched road markings ----------------------------------------------------

TEST(BehaviorSignal, NoRouteLaneletAtTheQueryPointIsIgnored) {
  auto in = shift_input(0.0, 2.0);
  in.route_lanelet_found = false;
  const auto r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));
}

TEST(BehaviorSignal, HatchedOnlySideSuppressesAvoidanceOnly) {
  auto in = shift_input(0.0, 2.0);
  in.left_hatched_road_marking_only = true;
  auto r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_EQ(r.info.turn, TurnIndicator::NoCommand);

  in.left_hatched_road_marking_only = false;
  in.right_hatched_road_marking_only = true;  // the other side does not matter for a left avoid
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);

  // Lane change / pull out / pull over skip the hatched test.
  in.left_hatched_road_marking_only = true;
  in.is_lane_change = true;
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
}

TEST(HatchedRoadMarking, AllFourShiftClasses) {
  const double th = 0.3;
  // Avoid shift (|a| < th, |b| > th).
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(0.0, 2.0, true, false, th));
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(0.0, 2.0, false, true, th));
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(0.0, -2.0, false, true, th));
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(0.0, -2.0, true, false, th));
  // Return shift (|a| > th, |b| < th): a return to the left comes from the right side.
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(-2.0, 0.0, false, true, th));
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(-2.0, 0.0, true, false, th));
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(2.0, 0.0, true, false, th));
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(2.0, 0.0, false, true, th));
  // Left middle (a > th, b > th): any direction with left hatching only.
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(1.0, 2.0, true, false, th));
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(2.0, 1.0, true, false, th));
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(2.0, 1.0, false, true, th));
  // Right middle is a *signed* comparison (a < th, b < th), as in the reference.
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(-1.0, -2.0, false, true, th));
  EXPECT_FALSE(is_adjacent_to_hatched_road_marking_ok(0.1, 0.2, false, true, th));
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(-1.0, -2.0, true, false, th));
  // Nothing hatched: always fine.
  EXPECT_TRUE(is_adjacent_to_hatched_road_marking_ok(0.0, 2.0, false, false, th));
  // Class predicates at the threshold: strict on both sides.
  EXPECT_FALSE(is_avoid_shift(0.3, 2.0, th));
  EXPECT_FALSE(is_avoid_shift(0.0, 0.3, th));
  EXPECT_FALSE(is_return_shift(0.3, 0.0, th));
  EXPECT_FALSE(is_return_shift(2.0, 0.3, th));
  EXPECT_FALSE(is_left_middle_shift(0.3, 2.0, th));
  EXPECT_FALSE(is_right_middle_shift(0.3, -2.0, th));
}

// ---- lane-bound test -----------------------------------------------------------------------------

TEST(BehaviorSignal, ShiftInsideTheLaneDoesNotSignal) {
  const auto in = shift_input(0.0, 0.5);  // 0.5 + 0.9 + yaw term < 1.6
  const auto r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));
}

TEST(BehaviorSignal, PullOutAndPullOverSignalInsideTheLane) {
  auto out = shift_input(-0.5, 0.0);
  out.is_pull_out = true;
  out.lane.left_half_width = out.lane.right_half_width = 3.0;  // far bound well away (pull-out test)
  EXPECT_EQ(behavior_signal(out, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
  auto over = shift_input(0.0, -0.5);
  over.is_pull_over = true;
  EXPECT_EQ(behavior_signal(over, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableRight);
  // Lane change does run the lane-bound test.
  auto lc = shift_input(0.0, 0.5);
  lc.is_lane_change = true;
  EXPECT_TRUE(behavior_signal(lc, ego_front(95.0), kParams).is_ignore);
}

BehaviorSignalParameters square_car() {
  BehaviorSignalParameters p;
  p.vehicle_width = 2.0;  // half width 1.0: exact sums
  return p;
}

TEST(LaneBound, TouchingCountsWhollyBeyondDoesNot) {
  const auto p = square_car();
  BehaviorSignalInput in;
  in.lane.left_half_width = 1.5;
  in.lane.right_half_width = 1.5;
  in.shift_line = {0.0, 10.0, 0.5, 0.5};  // constant offset, yaw 0
  EXPECT_TRUE(straddles_lane_bound(in, p));  // left edge at exactly 1.5
  in.shift_line = {0.0, 10.0, 0.25, 0.25};
  EXPECT_FALSE(straddles_lane_bound(in, p));  // [-0.75, 1.25] inside
  in.shift_line = {0.0, 10.0, 3.0, 3.0};
  EXPECT_FALSE(straddles_lane_bound(in, p));  // [2.0, 4.0] wholly beyond the left bound
  in.shift_line = {0.0, 10.0, -0.5, -0.5};
  EXPECT_TRUE(straddles_lane_bound(in, p));  // right edge at exactly -1.5
}

TEST(LaneBound, SamplesFromStartToBeforeTheEnd) {
  const auto p = square_car();
  BehaviorSignalInput in;
  in.lane.left_half_width = in.lane.right_half_width = 1.5;
  in.path_shift_at = [](double s) { return s >= 10.0 ? 0.5 : 0.0; };  // reaches the bound only at the end
  in.path_heading_at = [](double) { return 0.0; };
  in.shift_line = {0.0, 10.0, 0.0, 0.5};
  EXPECT_FALSE(straddles_lane_bound(in, p));  // end point (end_idx) itself is not tested
  in.shift_line = {0.0, 10.5, 0.0, 0.5};
  EXPECT_TRUE(straddles_lane_bound(in, p));   // s = 10 is now a sample
  in.shift_line = {5.0, 5.0, 0.5, 0.5};
  EXPECT_FALSE(straddles_lane_bound(in, p));  // zero-length line: no samples
}

TEST(LaneBound, FootprintYawIsIncluded) {
  const auto p = square_car();
  BehaviorSignalInput in;
  in.lane.left_half_width = in.lane.right_half_width = 1.5;
  // 0 -> 0.4 over 2 m: offsets 0 and 0.2 (edge at 1.2 without yaw) but the slope 0.2 turns the
  // front corner out to 0.2 + 3.7 sin(0.197) + cos(0.197) = 1.91.
  in.shift_line = {0.0, 2.0, 0.0, 0.4};
  EXPECT_TRUE(straddles_lane_bound(in, p));
  in.path_heading_at = [](double) { return 0.0; };
  EXPECT_FALSE(straddles_lane_bound(in, p));
}

TEST(LaneBound, BoundsMayVaryAlongS) {
  const auto p = square_car();
  BehaviorSignalInput in;
  in.shift_line = {0.0, 20.0, 0.25, 0.25};
  in.lane.left_at = [](double s) { return s < 15.0 ? 2.0 : 1.25; };  // lane narrows ahead
  in.lane.right_half_width = 2.0;
  EXPECT_TRUE(straddles_lane_bound(in, p));
  in.shift_line = {0.0, 15.0, 0.25, 0.25};
  EXPECT_FALSE(straddles_lane_bound(in, p));
}

// ---- stopped test ---------------------------------------------------------------------------------

TEST(BehaviorSignal, StoppedInsideTheLaneDuringAReturnShiftTurnsOff) {
  auto in = shift_input(2.0, 0.0);  // return shift from the left
  in.current_shift_length = 1.0;    // already back inside the lane (|1.0| < 1.6)
  const auto stopped = ego_front(95.0, 0.0);
  auto r = behavior_signal(in, stopped, kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));

  in.override_ego_stopped_check = true;
  EXPECT_EQ(behavior_signal(in, stopped, kParams).info.turn, TurnIndicator::EnableRight);
  in.override_ego_stopped_check = false;

  EXPECT_EQ(behavior_signal(in, ego_front(95.0, 0.1), kParams).info.turn, TurnIndicator::EnableRight);  // 0.1 not < 0.1
  EXPECT_TRUE(behavior_signal(in, ego_front(95.0, 0.0999), kParams).is_ignore);
  EXPECT_TRUE(behavior_signal(in, ego_front(95.0, -0.5), kParams).is_ignore);  // reversing counts as stopped

  in.current_shift_length = 1.6;  // on the bound: not strictly inside (boost within)
  EXPECT_EQ(behavior_signal(in, stopped, kParams).info.turn, TurnIndicator::EnableRight);
  in.current_shift_length = 1.75;  // still outside the lane
  EXPECT_EQ(behavior_signal(in, stopped, kParams).info.turn, TurnIndicator::EnableRight);
}

TEST(BehaviorSignal, StoppedTestAppliesOnlyToReturnShifts) {
  auto in = shift_input(0.0, 2.0);  // an avoid shift
  in.current_shift_length = 0.5;
  EXPECT_EQ(behavior_signal(in, ego_front(95.0, 0.0), kParams).info.turn, TurnIndicator::EnableLeft);
}

// ---- pull-out distance to the far bound (PR #11519) ------------------------------------------------

TEST(BehaviorSignal, PullOutBoundDistanceThresholdIsStrict) {
  auto in = shift_input(-2.0, 0.0);
  in.is_pull_out = true;
  in.current_shift_length = -2.0;
  in.distance_to_bound = 1.3;  // |d| == 1.3: still signals
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
  in.distance_to_bound = 1.2999;
  auto r = behavior_signal(in, ego_front(95.0), kParams);
  EXPECT_TRUE(r.is_ignore);
  EXPECT_TRUE(is_none(r.info, in));
  in.distance_to_bound = -1.2;  // absolute value
  EXPECT_TRUE(behavior_signal(in, ego_front(95.0), kParams).is_ignore);
  in.distance_to_bound = -1.4;
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
  // A lane change flagged as pull out skips the bound test.
  in.distance_to_bound = 0.0;
  in.is_lane_change = true;
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
}

TEST(BehaviorSignal, PullOutBoundDistanceComputedFromTheFrontCorner) {
  const auto p = square_car();  // half width 1.0
  auto in = shift_input(-2.0, 0.0);
  in.is_pull_out = true;
  in.lane.left_half_width = in.lane.right_half_width = 1.5;
  const auto ego = ego_front(95.0);
  in.current_shift_length = -2.0;  // corner at -1.0: 2.5 m from the left bound
  EXPECT_DOUBLE_EQ(pull_out_distance_to_bound(in, ego, p, true), 2.5);
  EXPECT_EQ(behavior_signal(in, ego, p).info.turn, TurnIndicator::EnableLeft);
  in.current_shift_length = -0.75;  // corner at 0.25: 1.25 < 1.3 from the bound -> off, latched
  EXPECT_DOUBLE_EQ(pull_out_distance_to_bound(in, ego, p, true), 1.25);
  EXPECT_TRUE(behavior_signal(in, ego, p).is_ignore);
  // Right: front-right corner against the right bound.
  in.current_shift_length = 2.0;
  EXPECT_DOUBLE_EQ(pull_out_distance_to_bound(in, ego, p, false), 2.5);
  // Yaw turns the corner outwards.
  in.current_shift_length = -2.0;
  in.ego_relative_yaw = 0.2;
  EXPECT_NEAR(pull_out_distance_to_bound(in, ego, p, true), 1.5 - (-2.0 + 3.7 * std::sin(0.2) + std::cos(0.2)), 1e-12);
}

// ---- egos_lane_is_shifted = false (lane-change style, docs/behaviour.md §T12.1.12) ---------------------------

TEST(BehaviorSignal, EgosLaneNotShiftedSwapsAndNegates) {
  auto in = shift_input(0.0, 3.2);
  in.is_lane_change = true;
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
  in.egos_lane_is_shifted = false;  // (a, b) = (3.2, -0) -> rel = -3.2
  in.current_shift_length = 3.2;    // |b - current| = 3.2
  EXPECT_EQ(behavior_signal(in, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableRight);

  // Shift relative to the target lane: -3.2 -> 0 becomes (0, 3.2): LEFT; the remaining-shift test
  // uses the swapped end (3.2).
  auto target = shift_input(-3.2, 0.0);
  target.is_lane_change = true;
  target.egos_lane_is_shifted = false;
  target.current_shift_length = 0.0;
  EXPECT_EQ(behavior_signal(target, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
  target.current_shift_length = 3.2;
  EXPECT_TRUE(behavior_signal(target, ego_front(95.0), kParams).is_ignore);
  target.egos_lane_is_shifted = true;  // unswapped end 0: 3.2 m remain
  EXPECT_EQ(behavior_signal(target, ego_front(95.0), kParams).info.turn, TurnIndicator::EnableLeft);
}

TEST(BehaviorSignalParameters, CopiedFromTheDeciderParameters) {
  TurnSignalParameters d;
  d.turn_signal_shift_length_threshold = 0.4;
  d.turn_signal_remaining_shift_length_threshold = 0.2;
  d.turn_signal_search_time = 2.0;
  d.turn_signal_minimum_search_distance = 20.0;
  d.turn_signal_on_swerving = false;
  d.turn_signal_remaining_distance_to_bound_threshold = 1.0;
  d.base_link_to_front = 4.0;
  BehaviorSignalParameters base;
  base.max_prepare_time = 7.0;
  const auto p = behavior_signal_parameters(d, base);
  EXPECT_EQ(p.turn_signal_shift_length_threshold, 0.4);
  EXPECT_EQ(p.turn_signal_remaining_shift_length_threshold, 0.2);
  EXPECT_EQ(p.turn_signal_search_time, 2.0);
  EXPECT_EQ(p.turn_signal_minimum_search_distance, 20.0);
  EXPECT_FALSE(p.turn_signal_on_swerving);
  EXPECT_EQ(p.turn_signal_remaining_distance_to_bound_threshold, 1.0);
  EXPECT_EQ(p.base_link_to_front, 4.0);
  EXPECT_EQ(p.max_prepare_time, 7.0);
}

TEST(BehaviorSignalParameters, DefaultsAreSpecSection10) {
  const BehaviorSignalParameters p;
  EXPECT_EQ(p.turn_signal_shift_length_threshold, 0.3);
  EXPECT_EQ(p.turn_signal_remaining_shift_length_threshold, 0.1);
  EXPECT_EQ(p.turn_signal_search_time, 3.0);
  EXPECT_EQ(p.turn_signal_minimum_search_distance, 10.0);
  EXPECT_TRUE(p.turn_signal_on_swerving);
  EXPECT_EQ(p.turn_signal_remaining_distance_to_bound_threshold, 1.3);
  EXPECT_EQ(p.min_length_for_turn_signal_activation, 10.0);
  EXPECT_EQ(p.max_prepare_time, 3.0);
  EXPECT_EQ(p.turn_signal_on_centerline_start, "RIGHT");
  EXPECT_EQ(p.minimum_shift_length, 0.5);
  EXPECT_EQ(p.th_distance_to_middle_of_the_road, 0.5);
  EXPECT_EQ(p.prepare_time_before_start, 0.0);
}

}  // namespace
}  // namespace signalsim
