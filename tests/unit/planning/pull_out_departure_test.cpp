// The pull out's clock (docs/behaviour.md §T8.2 "Pull out"; Autoware's StartPlannerModule::updateData and
// needToPrepareBlinkerBeforeStartDrivingForward): engaged from the engage time, the first engaged
// forward step, and the hold before starting, strict at exactly prepare_time_before_start.
#include <gtest/gtest.h>

#include "planning/pull_out_departure.hpp"

namespace signalsim {
namespace {

TEST(PullOutDeparture, HoldsUntilEngagedThenForThePrepareTime) {
  PullOutDeparture d(1.3, 2.0);  // the run starts at 0.3 s, engage_delay 1 s
  d.observe(0.3, true);
  EXPECT_FALSE(d.engaged(0.3));
  EXPECT_TRUE(d.holds(0.3));
  EXPECT_FALSE(d.time_since_first_engaged_forward(0.3));  // not engaged: none
  d.observe(1.3, true);
  EXPECT_TRUE(d.engaged(1.3));
  EXPECT_DOUBLE_EQ(*d.time_since_first_engaged_forward(1.3), 0.0);
  EXPECT_TRUE(d.holds(1.3));
  d.observe(3.2, true);
  EXPECT_TRUE(d.holds(3.2));  // 1.9 s
  d.observe(3.3, true);
  // 3.3 - 1.3 is 1.9999999999999998 in doubles: whole nanoseconds give 2.0, which is not < 2.0 (the
  // start planner's centre-line test compares this value with prepare_time_before_start too).
  EXPECT_EQ(*d.time_since_first_engaged_forward(3.3), 2.0);
  EXPECT_FALSE(d.holds(3.3));
}

TEST(PullOutDeparture, WithoutAPrepareTimeOnlyEngagementHolds) {
  PullOutDeparture d(0.0, 0.0);
  d.observe(0.0, true);
  EXPECT_FALSE(d.holds(0.0));
  EXPECT_DOUBLE_EQ(*d.time_since_first_engaged_forward(0.5), 0.5);
}

TEST(PullOutDeparture, TheClockStartsWhenBackingUpEnds) {
  PullOutDeparture d(0.0, 1.0);
  d.observe(0.0, false);  // engaged, backing up: no forward time, no hold (the back-up drives)
  EXPECT_FALSE(d.time_since_first_engaged_forward(0.0));
  EXPECT_FALSE(d.holds(0.0));
  d.observe(3.0, false);
  d.observe(3.1, true);
  EXPECT_TRUE(d.holds(3.1));
  EXPECT_TRUE(d.holds(4.0));
  d.observe(4.1, true);
  EXPECT_FALSE(d.holds(4.1));
  d.observe(4.2, false);  // cleared whenever a condition fails, as updateData
  EXPECT_FALSE(d.time_since_first_engaged_forward(4.2));
}

}  // namespace
}  // namespace signalsim
