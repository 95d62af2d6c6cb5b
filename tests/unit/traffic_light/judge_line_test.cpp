// docs/behaviour.md §L2.2 exact math and quirks; §L5.4 shared-helper vectors.
#include <gtest/gtest.h>

#include "planning/stop/jerk_limited_stop.hpp"
#include "traffic_light/judge_line.hpp"

namespace signalsim {
namespace {

constexpr double kAs = -2.8;  // max_accel
constexpr double kJs = -5.0;  // max_jerk
constexpr double kTd = 0.5;   // delay_response_time

TEST(JudgeLine, AccLimitUpstreamVector) {
  // docs/behaviour.md §L5.4: calcJudgeLineDistWithAccLimit(10, -3, 1) -> 26.67 +- 0.01 (= 100/6 + 10).
  EXPECT_NEAR(calc_judge_line_dist_with_acc_limit(10.0, -3.0, 1.0), 26.67, 0.01);
  EXPECT_DOUBLE_EQ(calc_judge_line_dist_with_acc_limit(10.0, -3.0, 1.0), 100.0 / 6.0 + 10.0);
}

TEST(JudgeLine, JerkLimitUpstreamVectorCaseA) {
  // docs/behaviour.md §L5.4: v=10, a0=0, a_s=-3, j_s=-1, t_d=1 -> > 0; exactly 40.5417
  // (t2 = 3, v2 = 5.5, x1 = 10, x2 = 25.5, x3 = 5.0417).
  const double d = calc_judge_line_dist_with_jerk_limit(10.0, 0.0, -3.0, -1.0, 1.0);
  EXPECT_GT(d, 0.0);
  EXPECT_NEAR(d, 40.5417, 1e-4);
  EXPECT_NEAR(d, 10.0 + 25.5 + 5.5 * 5.5 / 6.0, 1e-12);
}

TEST(JudgeLine, CaseBQuirkUsesAsInsteadOfA0) {
  // docs/behaviour.md §L2.2 quirk 1: v=0.5, a0=0 -> 0.1948 m as coded (t2 = -0.113 s), 0.399 m physically.
  const double d = calc_judge_line_dist_with_jerk_limit(0.5, 0.0, kAs, kJs, kTd);
  EXPECT_NEAR(d, 0.1948, 1e-4);
  const double physical = 0.5 * kTd + stopping_distance(0.5, 0.0, kAs, 5.0);
  EXPECT_NEAR(physical, 0.399, 1e-3);
}

TEST(JudgeLine, NegativeT2QuirkWhenAlreadyBrakingHarder) {
  // docs/behaviour.md §L2.2 quirk 2: v=10, a0=-3 < a_s -> 22.872 m.
  EXPECT_NEAR(calc_judge_line_dist_with_jerk_limit(10.0, -3.0, kAs, kJs, kTd), 22.872, 1e-3);
}

TEST(JudgeLine, PositiveAccelerationLengthensTheDistance) {
  // docs/behaviour.md §L2.2 quirk 3: a0 not clamped.
  EXPECT_GT(calc_judge_line_dist_with_jerk_limit(10.0, 1.0, kAs, kJs, kTd),
            calc_judge_line_dist_with_jerk_limit(10.0, 0.0, kAs, kJs, kTd));
}

TEST(JudgeLine, ZeroOrNegativeSpeedGivesZero) {
  EXPECT_EQ(calc_judge_line_dist_with_jerk_limit(0.0, 0.0, kAs, kJs, kTd), 0.0);
  EXPECT_EQ(calc_judge_line_dist_with_jerk_limit(-1.0, -5.0, kAs, kJs, kTd), 0.0);
}

TEST(JudgeLine, CaseAEqualsThePhysicalStoppingDistancePlusDeadTime) {
  // Case A is the physical three-phase model: check it against the stop planner's profile.
  for (double v : {2.0, 5.0, 10.0, 16.7}) {
    for (double a0 : {0.0, -1.0, 0.5}) {
      EXPECT_NEAR(calc_judge_line_dist_with_jerk_limit(v, a0, kAs, kJs, kTd), v * kTd + stopping_distance(v, a0, kAs, 5.0),
                  1e-9)
          << v << " " << a0;
    }
  }
}

TEST(JudgeLine, DilemmaZoneAppearsAboveAbout11MetresPerSecond) {
  // docs/behaviour.md §L2.6: with defaults and a0 = 0, judge_dist(v) > v * 2.75 once v >~ 11.05 m/s.
  EXPECT_LT(calc_judge_line_dist_with_jerk_limit(11.0, 0.0, kAs, kJs, kTd), 11.0 * 2.75);
  EXPECT_GT(calc_judge_line_dist_with_jerk_limit(11.1, 0.0, kAs, kJs, kTd), 11.1 * 2.75);
}

}  // namespace
}  // namespace signalsim
