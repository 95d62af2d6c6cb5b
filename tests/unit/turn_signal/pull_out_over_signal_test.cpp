// docs/behaviour.md §T8.2 "Start planner" / "Goal planner", §T8.3: pull out and pull over requests, the latched
// ignore by lanelet, the centre-line start case, hazard on backward driving, USE_PRIOR / OVERWRITE.
#include <gtest/gtest.h>

#include "behavior_test_helpers.hpp"
#include "turn_signal/behavior_modules.hpp"

namespace signalsim {
namespace {

using test::ego_front;
using test::request;
using test::same_info;

using test::kParams;

PullOutSignal::Input pull_out_input(double current = -2.5, std::size_t lanelet = 3) {
  PullOutSignal::Input in;
  in.pull_out_start = 100.0;
  in.pull_out_end = 130.0;
  in.shift_at_start = -2.5;  // parked at the road side, right of the lane centre
  in.shift_at_end = 0.0;
  in.closest_lanelet = lanelet;
  in.signal = test::shift_input();
  in.signal.lane.left_half_width = 1.6;
  in.signal.lane.right_half_width = 3.5;  // the road-side strip belongs to the lane
  in.signal.current_shift_length = current;
  return in;
}

// ---- pull out ----------------------------------------------------------------------------------------

TEST(PullOutSignal, SignalsTowardsTheLane) {
  PullOutSignal module;
  const auto ego = ego_front(95.0);
  const auto out = module.update(TurnSignalInfo{}, pull_out_input(), ego, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(out.source, RequestSource::PullOut);
  EXPECT_EQ(out.desired_start, ego.s_base);
  EXPECT_EQ(out.required_start, 100.0);
  EXPECT_EQ(out.desired_end, 130.0);
  EXPECT_FALSE(module.ignored_lanelet().has_value());
}

TEST(PullOutSignal, BackwardSegmentGivesHazard) {
  PullOutSignal module;
  auto in = pull_out_input();
  in.driving_forward = false;
  in.signal.route_start = 0.0;
  const auto ego = ego_front(95.0, -1.0);
  const auto out = module.update(TurnSignalInfo{}, in, ego, kParams);
  EXPECT_EQ(out.hazard, HazardLights::Enable);
  EXPECT_EQ(out.turn, TurnIndicator::NoCommand);
  EXPECT_EQ(out.desired_start, 0.0);
  EXPECT_EQ(out.desired_end, ego.s_base);
  EXPECT_EQ(out.source, RequestSource::PullOut);
}

TEST(PullOutSignal, NearlyMergedTurnsOffAndLatchesTheLanelet) {
  PullOutSignal module;
  const auto ego = ego_front(95.0);
  // Front-left corner at -0.5 + 0.9 = 0.4: 1.2 m from the left bound (< 1.3).
  auto out = module.update(TurnSignalInfo{}, pull_out_input(-0.5, 3), ego, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::NoCommand);
  EXPECT_EQ(module.ignored_lanelet(), std::optional<std::size_t>(3));
  // Same lanelet: the previous request passes through without evaluation.
  const auto previous = request(TurnIndicator::EnableRight, 0, 50, 10, 40, RequestSource::None);
  EXPECT_PRED2(same_info, module.update(previous, pull_out_input(-2.5, 3), ego, kParams), previous);
  // Another lanelet is evaluated and clears the latch.
  out = module.update(TurnSignalInfo{}, pull_out_input(-2.5, 4), ego, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_FALSE(module.ignored_lanelet().has_value());
}

TEST(PullOutSignal, TooEarlyDoesNotLatch) {
  PullOutSignal module;
  const auto out = module.update(TurnSignalInfo{}, pull_out_input(), ego_front(50.0), kParams);
  EXPECT_EQ(out.turn, TurnIndicator::NoCommand);
  EXPECT_FALSE(module.ignored_lanelet().has_value());
}

TEST(PullOutSignal, FinalMergeIsUsePriorInfo) {
  PullOutSignal module;
  // An earlier request whose required section contains the pull-out's: USE_PRIOR keeps it
  // (OVERWRITE would have replaced it).
  const auto previous = request(TurnIndicator::EnableRight, 10, 200, 20, 190, RequestSource::Avoidance);
  EXPECT_PRED2(same_info, module.update(previous, pull_out_input(), ego_front(95.0), kParams), previous);
  // A previous request not started yet: the pull out is returned.
  PullOutSignal other;
  const auto later = request(TurnIndicator::EnableRight, 150, 200, 160, 190, RequestSource::Avoidance);
  EXPECT_EQ(other.update(later, pull_out_input(), ego_front(95.0), kParams).source, RequestSource::PullOut);
}

TEST(PullOutSignal, CenterlineStartForcesTheConfiguredBlinker) {
  BehaviorSignalParameters p;
  p.th_distance_to_middle_of_the_road = 0.1;  // < minimum_shift_length (0.5)
  p.prepare_time_before_start = 2.0;
  auto in = pull_out_input(-0.25);
  in.shift_at_start = -0.25;  // |shift| < 0.5
  in.enable_back = false;
  in.time_since_first_engaged_forward = 1.0;  // < 2.0: blinker before departure
  ASSERT_TRUE(PullOutSignal::is_centerline_start(in, p));
  PullOutSignal module;
  const auto ego = ego_front(95.0, 0.0);
  auto out = module.update(TurnSignalInfo{}, in, ego, p);
  EXPECT_EQ(out.turn, TurnIndicator::EnableRight);  // default "RIGHT"
  EXPECT_EQ(out.source, RequestSource::PullOut);
  EXPECT_EQ(out.desired_start, ego.s_base);  // signalsim: span for an inactive previous request
  EXPECT_EQ(out.desired_end, 130.0);

  p.turn_signal_on_centerline_start = "LEFT";
  const auto previous = request(TurnIndicator::EnableRight, 10, 200, 20, 190, RequestSource::Avoidance);
  out = module.update(previous, in, ego, p);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);  // the previous info with the command forced
  EXPECT_EQ(out.desired_start, 10.0);
  EXPECT_EQ(out.required_end, 190.0);

  // Each condition is needed.
  auto c = in;
  c.time_since_first_engaged_forward = 2.0;  // not < 2.0
  EXPECT_FALSE(PullOutSignal::is_centerline_start(c, p));
  // Not engaged yet (no first engaged-forward time): the blinker is forced too, whatever the prepare
  // time. Autoware's StartPlannerModule::calcTurnSignalInfo, is_need_blinker =
  // !first_engaged_and_driving_forward_time || needToPrepareBlinkerBeforeStartDrivingForward()
  // (tier4/autoware_universe_planning fc41b8921, docs/behaviour.md §T8.2 "Pull out").
  c = in;
  c.time_since_first_engaged_forward.reset();
  EXPECT_TRUE(PullOutSignal::is_centerline_start(c, p));
  auto no_wait = p;
  no_wait.prepare_time_before_start = 0.0;
  EXPECT_TRUE(PullOutSignal::is_centerline_start(c, no_wait));
  c.time_since_first_engaged_forward = 0.0;  // engaged now, no prepare time: the generator decides
  EXPECT_FALSE(PullOutSignal::is_centerline_start(c, no_wait));
  c = in;
  c.enable_back = true;
  EXPECT_FALSE(PullOutSignal::is_centerline_start(c, p));
  c = in;
  c.shift_at_start = -0.5;  // |shift| == 0.5 not < 0.5
  EXPECT_FALSE(PullOutSignal::is_centerline_start(c, p));
  EXPECT_FALSE(PullOutSignal::is_centerline_start(in, kParams));  // defaults: 0.5 not < 0.5
}

TEST(PullOutSignal, OverrideStoppedCheck) {
  EXPECT_TRUE(PullOutSignal::override_stopped_check(false, false, 100.0));  // not yet departed
  EXPECT_FALSE(PullOutSignal::override_stopped_check(true, false, 0.0));
  EXPECT_TRUE(PullOutSignal::override_stopped_check(true, true, 0.99));
  EXPECT_TRUE(PullOutSignal::override_stopped_check(true, true, -0.5));
  EXPECT_FALSE(PullOutSignal::override_stopped_check(true, true, 1.0));
}

// ---- pull over ---------------------------------------------------------------------------------------

PullOverSignal::Input pull_over_input(double goal_offset = -2.5, std::size_t lanelet = 9) {
  PullOverSignal::Input in;
  in.pull_over_start = 100.0;
  in.pull_over_end = 130.0;
  in.shift_at_start = 0.0;
  in.shift_at_end = goal_offset;
  in.closest_lanelet = lanelet;
  in.signal = test::shift_input();
  in.signal.current_shift_length = 0.0;
  return in;
}

TEST(PullOverSignal, SignalsTowardsTheRoadSideEvenInsideTheLane) {
  PullOverSignal module;
  const auto ego = ego_front(95.0);
  auto out = module.update(TurnSignalInfo{}, pull_over_input(), ego, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(out.source, RequestSource::PullOver);
  EXPECT_EQ(out.required_start, 100.0);
  EXPECT_EQ(out.desired_end, 130.0);
  out = module.update(TurnSignalInfo{}, pull_over_input(-0.5), ego, kParams);  // no lane-bound test
  EXPECT_EQ(out.turn, TurnIndicator::EnableRight);
  out = module.update(TurnSignalInfo{}, pull_over_input(2.5), ego, kParams);  // left-side parking
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
}

TEST(PullOverSignal, LatchedIgnoreByLanelet) {
  PullOverSignal module;
  const auto ego = ego_front(95.0);
  auto in = pull_over_input();
  in.signal.route_lanelet_found = false;
  EXPECT_EQ(module.update(TurnSignalInfo{}, in, ego, kParams).turn, TurnIndicator::NoCommand);
  EXPECT_EQ(module.ignored_lanelet(), std::optional<std::size_t>(9));
  const auto previous = request(TurnIndicator::EnableLeft, 0, 50, 10, 40);
  EXPECT_PRED2(same_info, module.update(previous, pull_over_input(), ego, kParams), previous);
  EXPECT_EQ(module.update(TurnSignalInfo{}, pull_over_input(-2.5, 10), ego, kParams).turn,
            TurnIndicator::EnableRight);
  EXPECT_FALSE(module.ignored_lanelet().has_value());
}

TEST(PullOverSignal, PreemptiveRequestWhileDecelerating) {
  PullOverSignal::PreemptiveDecel decel{.decel_start = 80.0, .stop_path_end = 140.0, .stop_pose = 120.0,
                                        .parking_left = false};
  auto info = PullOverSignal::preemptive_signal(decel);
  EXPECT_EQ(info.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(info.source, RequestSource::PullOver);
  EXPECT_EQ(info.desired_start, 80.0);
  EXPECT_EQ(info.required_start, 120.0);  // the stop pose when known
  EXPECT_EQ(info.desired_end, 140.0);
  EXPECT_EQ(info.required_end, 140.0);
  decel.parking_left = true;
  decel.stop_pose.reset();
  info = PullOverSignal::preemptive_signal(decel);
  EXPECT_EQ(info.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(info.required_start, 80.0);

  PullOverSignal module;
  auto in = pull_over_input();
  in.path_decided = false;
  const auto ego = ego_front(95.0);
  const auto previous = request(TurnIndicator::EnableRight, 0, 50, 10, 40, RequestSource::Avoidance);
  EXPECT_PRED2(same_info, module.update(previous, in, ego, kParams), previous);  // nothing pre-emptive yet
  in.preemptive = decel;
  EXPECT_PRED2(same_info, module.update(TurnSignalInfo{}, in, ego, kParams), info);  // OVERWRITE(EMPTY, pre)
  // A previous request ending before the deceleration start is kept by OVERWRITE.
  EXPECT_PRED2(same_info, module.update(previous, in, ego, kParams), previous);
  const auto overlapping = request(TurnIndicator::EnableRight, 0, 100, 10, 90, RequestSource::Avoidance);
  EXPECT_PRED2(same_info, module.update(overlapping, in, ego, kParams), info);
}

TEST(PullOverSignal, OverrideStoppedCheck) {
  EXPECT_FALSE(PullOverSignal::override_stopped_check(true, 0.0));  // shift planner: never
  EXPECT_TRUE(PullOverSignal::override_stopped_check(false, 0.5));
  EXPECT_FALSE(PullOverSignal::override_stopped_check(false, 1.0));
}

}  // namespace
}  // namespace signalsim
