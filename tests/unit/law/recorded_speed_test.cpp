// A run's recorded speeds as the law's rules read them (law/recorded_speed.hpp): the least speed of
// the steps around a position (0 where the ego stood), the greatest over a stretch.
#include "law/recorded_speed.hpp"

#include <gtest/gtest.h>

namespace signalsim::law {
namespace {

// Steps at s 0, 10, 20 (standing there twice), 30 with speeds 10, 8, 0 / 2, 12; given out of order.
RecordedSpeed sample() { return RecordedSpeed({{30.0, 12.0}, {0.0, 10.0}, {20.0, 0.0}, {10.0, 8.0}, {20.0, 2.0}}); }

TEST(RecordedSpeed, LowerIsTheLeastSpeedOfTheStepsAround) {
  const RecordedSpeed v = sample();
  EXPECT_DOUBLE_EQ(v.lower(5.0), 8.0);    // steps at 0 (10) and 10 (8)
  EXPECT_DOUBLE_EQ(v.lower(10.0), 8.0);   // exactly at a step
  EXPECT_DOUBLE_EQ(v.lower(15.0), 0.0);   // the ego stood at 20
  EXPECT_DOUBLE_EQ(v.lower(25.0), 0.0);
  EXPECT_DOUBLE_EQ(v.lower(-5.0), 10.0);  // before the first step: the first
  EXPECT_DOUBLE_EQ(v.lower(40.0), 12.0);  // beyond the last: the last
  EXPECT_EQ(v.lower_reason(5.0), "the least speed of the run's steps around it, 8.0 m/s");
}

TEST(RecordedSpeed, MaxPlannedIsTheGreatestSpeedInAndAroundTheStretch) {
  const RecordedSpeed v = sample();
  EXPECT_DOUBLE_EQ(v.max_planned(5.0, 15.0), 10.0);  // steps 0, 10, 20
  EXPECT_DOUBLE_EQ(v.max_planned(12.0, 18.0), 8.0);  // steps 10 and 20
  EXPECT_DOUBLE_EQ(v.max_planned(0.0, 30.0), 12.0);
  EXPECT_DOUBLE_EQ(RecordedSpeed({}).max_planned(0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(RecordedSpeed({}).lower(0.0), 0.0);
}

}  // namespace
}  // namespace signalsim::law
