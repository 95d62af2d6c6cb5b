// The avoidance's phases (docs/behaviour.md §T8.2 "Avoidance"; Autoware's updateEgoBehavior and
// stillStopAndOutputTurnSignal): waiting at the wait point until the approval delay has passed,
// stop_on_approval's hold only after a stop at the wait point, released at exactly the hold duration.
#include <gtest/gtest.h>

#include "planning/avoidance_execution.hpp"

namespace signalsim {
namespace {

constexpr double kWait = 99.0;  // base_link s of the wait point

AvoidanceExecution execution(double approval_delay, bool stop_on_approval, double hold = 3.0) {
  return AvoidanceExecution({.wait_point = kWait, .approval_delay = approval_delay}, stop_on_approval, hold);
}

AvoidanceExecution::Step at(double now, double s_base, bool stopped) { return {now, s_base, stopped}; }

TEST(AvoidanceExecution, ApprovedAtOnceWithoutADelay) {
  AvoidanceExecution a = execution(0.0, true);
  EXPECT_EQ(a.phase(), AvoidancePhase::Pending);
  EXPECT_FALSE(a.distance_to_hold_point(50.0));
  EXPECT_TRUE(a.update(at(3.0, 50.0, false)));
  EXPECT_EQ(a.phase(), AvoidancePhase::Running);  // no hold: it never waited
  EXPECT_TRUE(a.approved());
  EXPECT_FALSE(a.distance_to_hold_point(50.0));
}

TEST(AvoidanceExecution, WaitsAtTheWaitPointUntilTheDelayHasPassed) {
  AvoidanceExecution a = execution(2.0, false);
  EXPECT_TRUE(a.update(at(1.3, 60.0, false)));
  EXPECT_EQ(a.phase(), AvoidancePhase::WaitingApproval);
  EXPECT_FALSE(a.approved());
  EXPECT_DOUBLE_EQ(*a.distance_to_hold_point(60.0), kWait - 60.0);
  EXPECT_FALSE(a.update(at(3.2, 98.0, true)));  // 1.9 s
  EXPECT_EQ(a.phase(), AvoidancePhase::WaitingApproval);
  EXPECT_TRUE(a.update(at(3.3, 99.0, true)));  // 3.3 - 1.3 = 1.9999999999999998 s in doubles, 2 s in ns
  EXPECT_EQ(a.phase(), AvoidancePhase::Running);  // not stop_on_approval: no hold
  EXPECT_FALSE(a.distance_to_hold_point(99.0));
}

TEST(AvoidanceExecution, StopOnApprovalHoldsForExactlyTheHoldDuration) {
  AvoidanceExecution a = execution(2.0, true, 3.0);
  a.update(at(1.0, 90.0, false));
  a.update(at(2.9, 98.6, true));  // stopped 0.4 m before the wait point: "at" it (< 0.5)
  EXPECT_TRUE(a.update(at(3.0, 98.6, true)));
  ASSERT_EQ(a.phase(), AvoidancePhase::Holding);
  EXPECT_TRUE(a.approved());
  EXPECT_DOUBLE_EQ(*a.distance_to_hold_point(98.6), 0.0);  // stop where it stands
  EXPECT_FALSE(a.update(at(5.9, 98.6, true)));
  EXPECT_EQ(a.phase(), AvoidancePhase::Holding);
  EXPECT_TRUE(a.update(at(6.0, 98.6, true)));  // 3.0 s: >= releases
  EXPECT_EQ(a.phase(), AvoidancePhase::Running);
  EXPECT_FALSE(a.distance_to_hold_point(98.6));
}

TEST(AvoidanceExecution, NoHoldWhenApprovedWhileRollingOrAwayFromTheWaitPoint) {
  AvoidanceExecution rolling = execution(1.0, true);
  rolling.update(at(0.0, 80.0, false));
  rolling.update(at(0.9, 95.0, false));
  rolling.update(at(1.0, 96.0, true));  // the flag of the step before counts: it was rolling
  EXPECT_EQ(rolling.phase(), AvoidancePhase::Running);

  AvoidanceExecution short_of_it = execution(1.0, true);
  short_of_it.update(at(0.0, 80.0, false));
  short_of_it.update(at(0.9, 98.5, true));  // 0.5 m before: not < 0.5
  short_of_it.update(at(1.0, 98.5, true));
  EXPECT_EQ(short_of_it.phase(), AvoidancePhase::Running);
}

TEST(AvoidanceExecution, AHoldDurationOfZeroReleasesAtApproval) {
  AvoidanceExecution a = execution(1.0, true, 0.0);
  a.update(at(0.0, 99.0, true));
  a.update(at(0.5, 99.0, true));
  EXPECT_TRUE(a.update(at(1.0, 99.0, true)));
  EXPECT_EQ(a.phase(), AvoidancePhase::Running);
}

TEST(AvoidanceExecution, PhaseNames) {
  EXPECT_STREQ(to_string(AvoidancePhase::Pending), "pending");
  EXPECT_STREQ(to_string(AvoidancePhase::WaitingApproval), "waiting_approval");
  EXPECT_STREQ(to_string(AvoidancePhase::Holding), "holding");
  EXPECT_STREQ(to_string(AvoidancePhase::Running), "running");
}

}  // namespace
}  // namespace signalsim
