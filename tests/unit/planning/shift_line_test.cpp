// Lateral shift profiles and the maneuver planners (planning/shift_line.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "planning/shift_line.hpp"

namespace signalsim {
namespace {

TEST(ShiftBlend, EndpointsAndSymmetry) {
  EXPECT_EQ(shift_blend(0.0), 0.0);
  EXPECT_EQ(shift_blend(1.0), 1.0);
  EXPECT_EQ(shift_blend(-0.5), 0.0);
  EXPECT_EQ(shift_blend(1.5), 1.0);
  EXPECT_DOUBLE_EQ(shift_blend(0.5), 0.5);
  for (double u = 0.0; u <= 1.0; u += 0.05) EXPECT_NEAR(shift_blend(u) + shift_blend(1.0 - u), 1.0, 1e-12);
  EXPECT_EQ(shift_blend_derivative(0.0), 0.0);
  EXPECT_EQ(shift_blend_derivative(1.0), 0.0);
  EXPECT_DOUBLE_EQ(shift_blend_derivative(0.5), 15.0 / 8.0);
}

TEST(ShiftLine, EndpointsAreExactAndConstantOutside) {
  const ShiftLine line{10.0, 30.0, -0.7, 2.3};
  EXPECT_EQ(line.offset_at(10.0), -0.7);
  EXPECT_EQ(line.offset_at(30.0), 2.3);
  EXPECT_EQ(line.offset_at(-100.0), -0.7);
  EXPECT_EQ(line.offset_at(9.999), -0.7);
  EXPECT_EQ(line.offset_at(30.001), 2.3);
  EXPECT_EQ(line.offset_at(1e6), 2.3);
  EXPECT_DOUBLE_EQ(line.offset_at(20.0), 0.8);  // midpoint = average
  EXPECT_DOUBLE_EQ(line.relative_shift(), 3.0);
  EXPECT_DOUBLE_EQ(line.length(), 20.0);
}

TEST(ShiftLine, ContinuousAndMonotoneLeft) {
  const ShiftLine line{0.0, 25.0, 0.0, 3.2};
  double previous = line.offset_at(-1.0);
  for (double s = -1.0; s <= 26.0; s += 0.01) {
    const double o = line.offset_at(s);
    EXPECT_GE(o, previous - 1e-15) << "s=" << s;
    EXPECT_LE(o - previous, 0.01 * line.heading_at(12.5) + 1e-9) << "jump at s=" << s;  // slope-bounded steps
    previous = o;
  }
}

TEST(ShiftLine, MonotoneRightAndHeadingMatchesDerivative) {
  const ShiftLine line{5.0, 20.0, 1.5, -1.5};
  double previous = line.offset_at(5.0);
  for (double s = 5.0; s <= 20.0; s += 0.05) {
    EXPECT_LE(line.offset_at(s), previous + 1e-15);
    previous = line.offset_at(s);
  }
  for (double s = 5.5; s < 19.6; s += 0.7) {
    const double h = 1e-5;
    const double numeric = (line.offset_at(s + h) - line.offset_at(s - h)) / (2 * h);
    EXPECT_NEAR(line.heading_at(s), numeric, 1e-6) << "s=" << s;
  }
  EXPECT_EQ(line.heading_at(5.0), 0.0);   // zero slope at both ends: C1 joints
  EXPECT_EQ(line.heading_at(20.0), 0.0);
  EXPECT_EQ(line.heading_at(0.0), 0.0);
  EXPECT_DOUBLE_EQ(line.heading_at(12.5), -3.0 * 15.0 / 8.0 / 15.0);  // peak 15/8 * rel / L
}

TEST(ShiftLine, HeadingContinuousNearTheEnds) {
  const ShiftLine line{0.0, 10.0, 0.0, 1.0};
  EXPECT_NEAR(line.heading_at(1e-4), 0.0, 1e-9);
  EXPECT_NEAR(line.heading_at(10.0 - 1e-4), 0.0, 1e-9);
}

TEST(ShiftLine, ZeroLengthLineJumpsAtItsStart) {
  const ShiftLine line{10.0, 10.0, 0.0, 1.0};
  EXPECT_EQ(line.offset_at(9.9), 0.0);
  EXPECT_EQ(line.offset_at(10.0), 1.0);
  EXPECT_EQ(line.heading_at(10.0), 0.0);
}

TEST(ShiftLine, SAtOffsetInvertsTheProfile) {
  const ShiftLine line{40.0, 60.0, 0.0, 3.2};
  const auto crossing = line.s_at_offset(1.6);
  ASSERT_TRUE(crossing.has_value());
  EXPECT_NEAR(*crossing, 50.0, 1e-9);  // half the shift at half the length
  const auto quarter = line.s_at_offset(0.8);
  ASSERT_TRUE(quarter.has_value());
  EXPECT_NEAR(line.offset_at(*quarter), 0.8, 1e-9);
  EXPECT_EQ(*line.s_at_offset(0.0), 40.0);
  EXPECT_NEAR(*line.s_at_offset(3.2), 60.0, 1e-9);
  EXPECT_FALSE(line.s_at_offset(3.3).has_value());
  EXPECT_FALSE(line.s_at_offset(-0.1).has_value());
  const ShiftLine right{0.0, 10.0, 0.0, -3.0};
  EXPECT_NEAR(right.offset_at(*right.s_at_offset(-1.0)), -1.0, 1e-9);
}

TEST(ShiftPlan, PiecewiseRules) {
  const ShiftPlan plan({ShiftLine{10.0, 20.0, 0.5, 2.0}, ShiftLine{30.0, 40.0, 2.0, -1.0}});
  EXPECT_EQ(plan.offset_at(0.0), 0.5);    // before the first: its start offset
  EXPECT_EQ(plan.offset_at(10.0), 0.5);
  EXPECT_DOUBLE_EQ(plan.offset_at(15.0), 1.25);
  EXPECT_EQ(plan.offset_at(20.0), 2.0);
  EXPECT_EQ(plan.offset_at(25.0), 2.0);   // between: the previous end offset
  EXPECT_EQ(plan.offset_at(30.0), 2.0);
  EXPECT_DOUBLE_EQ(plan.offset_at(35.0), 0.5);
  EXPECT_EQ(plan.offset_at(40.0), -1.0);
  EXPECT_EQ(plan.offset_at(99.0), -1.0);  // after the last: its end offset
  EXPECT_EQ(plan.heading_at(25.0), 0.0);
  EXPECT_LT(plan.heading_at(35.0), 0.0);
  EXPECT_GT(plan.heading_at(15.0), 0.0);
  EXPECT_EQ(ShiftPlan{}.offset_at(5.0), 0.0);
}

TEST(ShiftPlan, ContinuousAcrossTouchingLines) {
  const ShiftPlan plan({ShiftLine{0.0, 10.0, 0.0, 1.0}, ShiftLine{10.0, 20.0, 1.0, 3.0}});
  EXPECT_NEAR(plan.offset_at(10.0 - 1e-9), plan.offset_at(10.0), 1e-9);
  EXPECT_NEAR(plan.heading_at(10.0 - 1e-6), plan.heading_at(10.0 + 1e-6), 1e-6);
}

TEST(ShiftPlan, RejectsOverlapsAndBackwardLines) {
  EXPECT_THROW(ShiftPlan({ShiftLine{10.0, 5.0, 0.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(ShiftPlan({ShiftLine{0.0, 10.0, 0.0, 1.0}, ShiftLine{9.0, 20.0, 1.0, 0.0}}), std::invalid_argument);
  EXPECT_NO_THROW(ShiftPlan({ShiftLine{0.0, 10.0, 0.0, 1.0}, ShiftLine{10.0, 20.0, 1.0, 0.0}}));
}

TEST(ShiftLengthPolicy, FixedJerkAccelAndMinimum) {
  ShiftLengthPolicy fixed;
  fixed.fixed_length = 42.0;
  EXPECT_EQ(fixed.length_for(3.0, 20.0), 42.0);

  ShiftLengthPolicy jerk;
  jerk.lateral_jerk = 0.5;
  jerk.lateral_accel = 0.0;  // jerk only
  jerk.min_length = 0.0;
  const double t = shift_time_from_limits(3.2, 0.5, 0.0);
  EXPECT_NEAR(60.0 * 3.2 / (t * t * t), 0.5, 1e-12);  // the quintic's peak jerk is the limit
  EXPECT_NEAR(jerk.length_for(3.2, 10.0), 10.0 * t, 1e-9);
  EXPECT_NEAR(jerk.length_for(-3.2, -10.0), 10.0 * t, 1e-9);

  const double ta = shift_time_from_limits(3.2, 100.0, 0.2);  // acceleration binds
  EXPECT_NEAR(10.0 / std::sqrt(3.0) * 3.2 / (ta * ta), 0.2, 1e-12);

  ShiftLengthPolicy standstill;
  EXPECT_EQ(standstill.length_for(3.2, 0.0), standstill.min_length);
  EXPECT_EQ(shift_time_from_limits(0.0, 0.5, 0.5), 0.0);
}

TEST(PlanHelpers, LaneChange) {
  const ShiftPlan plan = plan_lane_change(100.0, -3.2, 50.0);
  ASSERT_EQ(plan.lines().size(), 1u);
  const ShiftLine& l = plan.lines().front();
  EXPECT_EQ(l.s_start, 100.0);
  EXPECT_EQ(l.s_end, 150.0);
  EXPECT_EQ(l.shift_start, 0.0);
  EXPECT_EQ(l.shift_end, -3.2);
}

TEST(PlanHelpers, AvoidanceShiftOutHoldBack) {
  AvoidanceRequest r;
  r.s_object_start = 100.0;
  r.s_object_end = 105.0;
  r.object_left = -0.5;   // a parked car on the right half of the lane
  r.object_right = -2.0;
  r.clearance = 1.0;
  r.vehicle_width = 1.8;
  r.base_link_to_front = 3.7;
  r.rear_overhang = 0.8;
  r.longitudinal_margin = 1.0;
  r.lengths.fixed_length = 20.0;
  EXPECT_DOUBLE_EQ(avoidance_offset(r), -0.5 + 1.0 + 0.9);  // Auto: obstacle right of centre -> pass left
  const ShiftPlan plan = plan_avoidance(r);
  ASSERT_EQ(plan.lines().size(), 2u);
  const ShiftLine& out = plan.lines()[0];
  const ShiftLine& back = plan.lines()[1];
  EXPECT_DOUBLE_EQ(out.s_end, 100.0 - 1.0 - 3.7);  // shifted before the front reaches the margin
  EXPECT_DOUBLE_EQ(out.s_start, out.s_end - 20.0);
  EXPECT_DOUBLE_EQ(back.s_start, 105.0 + 1.0 + 0.8);  // return after the rear passed
  EXPECT_DOUBLE_EQ(back.s_end, back.s_start + 20.0);
  EXPECT_EQ(out.shift_start, 0.0);
  EXPECT_DOUBLE_EQ(out.shift_end, 1.4);
  EXPECT_DOUBLE_EQ(back.shift_start, 1.4);
  EXPECT_EQ(back.shift_end, 0.0);
  EXPECT_DOUBLE_EQ(plan.offset_at(101.0), 1.4);  // hold beside the obstacle

  r.side = AvoidSide::Right;
  EXPECT_DOUBLE_EQ(avoidance_offset(r), -2.0 - 1.0 - 0.9);
  r.side = AvoidSide::Auto;
  r.object_left = 2.0;
  r.object_right = 0.5;  // obstacle left of centre -> pass right
  EXPECT_DOUBLE_EQ(avoidance_offset(r), 0.5 - 1.0 - 0.9);
}

TEST(PlanHelpers, PullOutAndPullOver) {
  const ShiftPlan out = plan_pull_out(5.0, -2.5, 30.0);
  EXPECT_EQ(out.offset_at(0.0), -2.5);
  EXPECT_EQ(out.offset_at(35.0), 0.0);
  EXPECT_EQ(out.lines().front().s_end, 35.0);
  const ShiftPlan over = plan_pull_over(200.0, -2.5, 30.0);
  EXPECT_EQ(over.lines().front().s_start, 170.0);
  EXPECT_EQ(over.lines().front().s_end, 200.0);
  EXPECT_EQ(over.offset_at(200.0), -2.5);
  EXPECT_EQ(over.offset_at(170.0), 0.0);
}

}  // namespace
}  // namespace signalsim
