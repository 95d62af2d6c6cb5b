// The lane change's phases and the prepare segment (docs/behaviour.md §T8.2 "Lane change",
// calc_actual_prepare_duration): where the lateral motion starts, when it is approved, the
// target-lane check and the hold point.
#include <gtest/gtest.h>

#include "planning/lane_change_execution.hpp"
#include "turn_signal/behavior_modules.hpp"

namespace signalsim {
namespace {

LaneChangeTiming timing(double approval_delay = 0.0) {
  LaneChangeTiming t;
  t.earliest_start = 100.0;
  t.latest_start = 300.0;
  t.length = 50.0;
  t.shift_start = -3.2;
  t.approval_delay = approval_delay;
  return t;
}

LaneChangeExecution::Step step_at(double now, double s_base, double speed, std::optional<double> on_since,
                                  double prepare) {
  LaneChangeExecution::Step s;
  s.now = now;
  s.s_base = s_base;
  s.speed = speed;
  s.module_active = on_since.has_value();
  s.blinker_on_since = on_since;
  s.prepare_duration = prepare;
  return s;
}

TEST(LaneChangeExecution, PendingUntilTheModuleSignals) {
  LaneChangeExecution lc(timing(), {});
  EXPECT_FALSE(lc.update(step_at(0.0, 50.0, 10.0, std::nullopt, 4.0)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::Pending);
  EXPECT_FALSE(lc.approved_line());
  // The candidate keeps the original lane at base_link.
  EXPECT_DOUBLE_EQ(lc.line(step_at(0.0, 50.0, 10.0, std::nullopt, 4.0)).offset_at(50.0), -3.2);
}

TEST(LaneChangeExecution, ImmediateApprovalPreparesMaxPrepareDuration) {
  // Approved in the step the blinker comes on: prepare = 4 s -> start 40 m ahead at 10 m/s.
  LaneChangeExecution lc(timing(), {});
  EXPECT_TRUE(lc.update(step_at(5.0, 70.0, 10.0, 5.0, 4.0)));
  ASSERT_EQ(lc.phase(), LaneChangePhase::Running);
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 110.0);
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_end, 160.0);
  EXPECT_DOUBLE_EQ(*lc.approval_time(), 5.0);
}

TEST(LaneChangeExecution, NeverStartsBeforeEarliestStart) {
  LaneChangeExecution lc(timing(), {});
  lc.update(step_at(5.0, 40.0, 10.0, 5.0, 4.0));  // 40 + 40 = 80 < 100
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 100.0);
}

TEST(LaneChangeExecution, ApprovalDelayShortensThePrepareSegment) {
  // The module's own shortening (docs/behaviour.md §T8.2): prepare = max(4 - on_time, 2).
  BehaviorSignalParameters p;
  LaneChangeSignal module;
  // Blinker on at t = 10 s (the module outputs its own command in the waiting phase).
  LaneChangeSignal::Input in;
  in.phase = LaneChangeSignal::Phase::WaitingApproval;
  in.direction = TurnIndicator::EnableLeft;
  in.lane_changing_start = 100.0;
  in.lane_changing_end = 150.0;
  in.previous_path_end = 400.0;
  module.update({}, in, EgoOnRoute{93.7, 90.0, 10.0}, 10.0, p);
  ASSERT_TRUE(module.blinker_on_since());

  LaneChangeExecution lc(timing(1.5), {});
  lc.update(step_at(10.0, 90.0, 10.0, 10.0, module.actual_prepare_duration(10.0, 10.0, p)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);  // 0 s < 1.5 s
  lc.update(step_at(11.4, 104.0, 10.0, 10.0, module.actual_prepare_duration(11.4, 10.0, p)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);  // 1.4 s < 1.5 s
  const double prepare = module.actual_prepare_duration(11.5, 10.0, p);
  EXPECT_DOUBLE_EQ(prepare, 2.5);
  lc.update(step_at(11.5, 105.0, 10.0, 10.0, prepare));
  ASSERT_EQ(lc.phase(), LaneChangePhase::Running);
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 130.0);  // 105 + 10 * 2.5
}

TEST(LaneChangeExecution, LongWaitLeavesTheMinimumPrepare) {
  BehaviorSignalParameters p;
  LaneChangeSignal module;
  LaneChangeSignal::Input in;
  in.phase = LaneChangeSignal::Phase::WaitingApproval;
  in.direction = TurnIndicator::EnableRight;
  in.lane_changing_start = 100.0;
  in.lane_changing_end = 150.0;
  in.previous_path_end = 400.0;
  module.update({}, in, EgoOnRoute{93.7, 90.0, 10.0}, 0.0, p);
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(2.0, 10.0, p), 2.0);  // exactly at the floor
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(7.0, 10.0, p), 2.0);  // never below
  LaneChangeExecution lc(timing(7.0), {});
  lc.update(step_at(7.0, 160.0, 10.0, 0.0, module.actual_prepare_duration(7.0, 10.0, p)));
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 180.0);
}

TEST(LaneChangeExecution, ApprovalLateInTheEdgeCutsThePrepareShort) {
  LaneChangeExecution lc(timing(), {});
  lc.update(step_at(1.0, 290.0, 10.0, 1.0, 4.0));
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 300.0);  // latest_start, not 330
}

TEST(LaneChangeExecution, TargetLaneOccupiedAroundTheCandidateBlocksApproval) {
  LaneChangeExecution lc(timing(), LaneChangeGaps{10.0, 10.0});
  auto s = step_at(0.0, 120.0, 10.0, 0.0, 2.0);  // candidate 140..190; ego rear bumper at 119.2
  s.target_lane = {{195.0, 199.0}};              // rear 195 <= 190 + 3.7 + 10
  EXPECT_FALSE(lc.target_lane_clear(s));
  lc.update(s);
  EXPECT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);
  s.target_lane = {{204.0, 208.0}};  // just beyond 203.7
  EXPECT_TRUE(lc.target_lane_clear(s));
  s.target_lane = {{100.0, 109.3}};  // front inside the 10 m behind the rear bumper (119.2)
  EXPECT_FALSE(lc.target_lane_clear(s));
  s.target_lane = {{100.0, 109.1}};
  EXPECT_TRUE(lc.target_lane_clear(s));
  lc.update(s);
  EXPECT_EQ(lc.phase(), LaneChangePhase::Running);
}

TEST(LaneChangeExecution, HoldPointUntilApprovedThenDone) {
  LaneChangeExecution lc(timing(100.0), {});
  lc.update(step_at(0.0, 250.0, 5.0, 0.0, 2.0));
  ASSERT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);
  EXPECT_DOUBLE_EQ(*lc.distance_to_hold_point(250.0), 50.0);
  // Standing at the hold point: the candidate starts at base_link.
  auto standing = step_at(50.0, 300.0, 0.0, 0.0, 2.0);
  EXPECT_DOUBLE_EQ(lc.candidate_start(standing), 300.0);
  lc.update(step_at(100.0, 300.0, 0.0, 0.0, 2.0));
  ASSERT_EQ(lc.phase(), LaneChangePhase::Running);
  EXPECT_FALSE(lc.distance_to_hold_point(300.0));
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 300.0);
  EXPECT_FALSE(lc.update(step_at(110.0, 350.0, 5.0, 0.0, 2.0)));  // at the end, not past it
  EXPECT_TRUE(lc.update(step_at(110.1, 350.5, 5.0, 0.0, 2.0)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::Done);
}

TEST(LaneChangeExecution, TheFixedLineDoesNotMoveAfterApproval) {
  LaneChangeExecution lc(timing(), {});
  lc.update(step_at(0.0, 100.0, 10.0, 0.0, 4.0));
  const ShiftLine fixed = *lc.approved_line();
  lc.update(step_at(1.0, 110.0, 12.0, 0.0, 3.0));
  EXPECT_DOUBLE_EQ(lc.line(step_at(1.0, 110.0, 12.0, 0.0, 3.0)).s_start, fixed.s_start);
  EXPECT_DOUBLE_EQ(fixed.s_start, 140.0);
}

TEST(LaneChangeExecution, NoHoldPointBeforeTheModuleSignals) {
  LaneChangeTiming t = timing(5.0);
  t.hold_margin = 3.86;
  LaneChangeExecution lc(t, {});
  EXPECT_FALSE(lc.distance_to_hold_point(250.0));  // pending: may still be approved at once
  lc.update(step_at(0.0, 250.0, 5.0, 0.0, 2.0));
  ASSERT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);
  EXPECT_DOUBLE_EQ(*lc.distance_to_hold_point(250.0), 300.0 - 3.86 - 250.0);
}

TEST(LaneChangeExecution, MissedPastTheLastStartWithoutApproval) {
  LaneChangeExecution lc(timing(10.0), {});
  lc.update(step_at(0.0, 290.0, 10.0, 0.0, 4.0));
  ASSERT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);
  lc.update(step_at(0.5, 300.0 + LaneChangeExecution::kLatestStartTolerance, 10.0, 0.0, 4.0));
  EXPECT_EQ(lc.phase(), LaneChangePhase::WaitingApproval);  // within the stopping tolerance
  EXPECT_TRUE(lc.update(step_at(0.6, 300.06, 10.0, 0.0, 4.0)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::Missed);
  EXPECT_FALSE(lc.distance_to_hold_point(300.06));
  // Terminal: approval conditions later change nothing, and no line was ever fixed.
  EXPECT_FALSE(lc.update(step_at(20.0, 310.0, 10.0, 0.0, 2.0)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::Missed);
  EXPECT_FALSE(lc.approved_line());
  EXPECT_DOUBLE_EQ(*lc.blinker_on_since(), 0.0);
}

TEST(LaneChangeExecution, PendingPastTheLastStartIsMissedToo) {
  LaneChangeExecution lc(timing(), {});
  EXPECT_TRUE(lc.update(step_at(0.0, 301.0, 10.0, std::nullopt, 4.0)));
  EXPECT_EQ(lc.phase(), LaneChangePhase::Missed);
}

TEST(LaneChangeExecution, PrepareDistanceFollowsSpeedAndAcceleration) {
  EXPECT_DOUBLE_EQ(LaneChangeExecution::prepare_distance(10.0, 0.0, 20.0, 4.0), 40.0);
  EXPECT_DOUBLE_EQ(LaneChangeExecution::prepare_distance(10.0, 1.0, 20.0, 4.0), 48.0);  // v t + a t^2 / 2
  // Capped at the maximum speed: 2 s to reach 12, then 12 m/s.
  EXPECT_DOUBLE_EQ(LaneChangeExecution::prepare_distance(10.0, 1.0, 12.0, 4.0), 22.0 + 24.0);
  // Braking to rest within the duration: v^2 / 2|a|.
  EXPECT_DOUBLE_EQ(LaneChangeExecution::prepare_distance(4.0, -2.0, 20.0, 4.0), 4.0);
  EXPECT_DOUBLE_EQ(LaneChangeExecution::prepare_distance(0.0, 1.0, 20.0, 2.0), 2.0);
  EXPECT_DOUBLE_EQ(LaneChangeExecution::prepare_distance(5.0, 1.0, 20.0, 0.0), 0.0);
}

TEST(LaneChangeExecution, AcceleratingEgoPreparesFurther) {
  LaneChangeExecution lc(timing(), {});
  auto s = step_at(5.0, 70.0, 10.0, 5.0, 4.0);
  s.accel = 1.0;
  s.max_speed = 30.0;
  lc.update(s);
  EXPECT_DOUBLE_EQ(lc.approved_line()->s_start, 70.0 + 48.0);
}

}  // namespace
}  // namespace signalsim
