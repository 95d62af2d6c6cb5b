// The plan stage's speed under the stops ahead (planning/stop/stop_speed_planner), closed loop on a
// point mass driven the way the step loop drives SUMO: the lane limits' speed (a constant limit,
// +-1 m/s^2 per step as plan_speed_under_limits), one stop point, Euler positions (SUMO's default)
// and the measured acceleration fed back as SUMO reports it, (v1 - v0) / dt.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "planning/stop/stop_speed_planner.hpp"

namespace signalsim {
namespace {

constexpr double kStepLength = 0.1;
constexpr double kLimit = 13.89;  // lane limit [m/s]

struct Trace {
  double rest_position = 0.0;  // where the point mass first came to rest after moving (or the end)
  double rest_time = -1.0;     // [s] of that rest; -1: never at rest after moving
  double peak_speed = 0.0;
  double peak_after = 0.0;     // the highest speed after `after_time`
  double min_accel = 0.0;      // strongest measured deceleration
  double max_brake_jerk = 0.0; // largest |measured jerk| while braking for the stop (see drive)
  bool only_normal = true;     // every constraining step at the normal level
  bool rested_early = false;   // that rest was more than 0.5 m before the stop point
};

// `cap(t)`: the fastest SUMO lets the ego go in the step starting at t (an artificial slow-down).
Trace drive(double v0, double stop_at, double after_time = 0.0,
            const std::function<std::optional<double>(double)>& cap = {}) {
  StopSpeedPlanner planner(StopPlannerParameters{}, 9.0);
  Trace r;
  double x = 0.0, v = v0, a = 0.0, prev_a = 0.0;
  bool moved = v0 > 0.0;
  for (int k = 0; k < 3000; ++k) {
    const double t = k * kStepLength;
    const double limits = std::clamp(kLimit, std::max(0.0, v - kStepLength), v + kStepLength);
    planner.begin_step(v, a, kStepLength);
    planner.set_cruise(limits, (limits - v) / kStepLength);
    const std::optional<StopLevel> level = planner.add_stop(stop_at - x);
    double v1 = planner.speed();
    planner.end_step(v1);
    if (cap) {
      if (const auto c = cap(t)) v1 = std::min(v1, *c);
    }
    prev_a = a;
    a = (v1 - v) / kStepLength;
    x += v1 * kStepLength;
    v = v1;
    if (level) {
      r.only_normal = r.only_normal && *level == StopLevel::Normal;
      // The braking ramp: decelerating before and after, above walking speed (the last steps of a
      // stop and the step into a held speed are not part of it).
      if (a < 0.0 && prev_a < 0.0 && v > 1.0) r.max_brake_jerk = std::max(r.max_brake_jerk, std::abs(a - prev_a) / kStepLength);
    }
    r.min_accel = std::min(r.min_accel, a);
    r.peak_speed = std::max(r.peak_speed, v);
    if (t >= after_time) r.peak_after = std::max(r.peak_after, v);
    moved = moved || v > 0.01;
    if (moved && v < 0.01) {
      r.rested_early = stop_at - x > 0.5;
      r.rest_position = x;
      r.rest_time = t + kStepLength;
      return r;
    }
  }
  r.rest_position = x;
  return r;
}

TEST(StopSpeedPlanner, FromRestTowardAFarStopSpeedsUpAndStopsAtTheNormalLevel) {
  // At rest 189.6 m before a red stop line.
  const Trace r = drive(0.0, 189.6);
  EXPECT_FALSE(r.rested_early);
  EXPECT_GE(r.peak_speed, 12.0) << "speeds up as far as a normal stop allows (before: crept at 0.2 m/s)";
  ASSERT_GT(r.rest_time, 0.0) << "never came to rest at the stop point";
  EXPECT_LT(r.rest_time, 30.0);
  EXPECT_NEAR(r.rest_position, 189.6, 0.3);
  EXPECT_TRUE(r.only_normal) << "no relaxed level was needed";
  EXPECT_GE(r.min_accel, -1.0 - 1e-9);
}

TEST(StopSpeedPlanner, AfterAnArtificialSlowDownItSpeedsUpAgainWhileAFarStopIsPending) {
  // SUMO brakes the ego at -4.5 m/s^2 down to 1 m/s from 2 s to 6 s (a leader, a junction), 350 m
  // before the stop. Afterwards the lane limits and the stop plan take over again.
  const auto slow_down = [](double t) -> std::optional<double> {
    if (t < 2.0 || t >= 6.0) return std::nullopt;
    return std::max(1.0, kLimit - 4.5 * (t - 2.0 + kStepLength));
  };
  const Trace r = drive(kLimit, 350.0, 6.0, slow_down);
  EXPECT_FALSE(r.rested_early) << "came to rest far before the stop point (the issue's stop in a junction)";
  EXPECT_GE(r.peak_after, kLimit - 1e-9) << "back to the lane limit before braking for the stop";
  ASSERT_GT(r.rest_time, 0.0);
  EXPECT_NEAR(r.rest_position, 350.0, 0.3);
  EXPECT_TRUE(r.only_normal);
}

TEST(StopSpeedPlanner, AShortRunFromRestBrakesAtTheNormalLevelWithTheNormalJerk) {
  // 40 m from rest (the next light of two, at a green one): the profile starts from its own previous
  // output, not from SUMO's step-mean acceleration, which lags a jerk ramp by J dt / 2 and used to
  // push the stop's end to the limit level.
  const Trace r = drive(0.0, 40.0);
  ASSERT_GT(r.rest_time, 0.0);
  EXPECT_NEAR(r.rest_position, 40.0, 0.3);
  EXPECT_TRUE(r.only_normal);
  EXPECT_GE(r.min_accel, -1.0 - 1e-9);
  EXPECT_LE(r.max_brake_jerk, 1.0 + 1e-6) << "the braking ramp at the normal jerk, no faster";
}

TEST(StopSpeedPlanner, AtSpeedTheStopBrakesAsLateAsTheNormalLevelAllows) {
  const Trace r = drive(kLimit, 150.0);
  EXPECT_NEAR(r.rest_position, 150.0, 0.3);
  EXPECT_TRUE(r.only_normal);
  EXPECT_GE(r.min_accel, -1.0 - 1e-9);
  EXPECT_LE(r.max_brake_jerk, 1.0 + 1e-6);
  EXPECT_DOUBLE_EQ(r.peak_speed, kLimit);
}

TEST(StopSpeedPlanner, WithoutStopsTheLaneLimitsSpeedIsCommanded) {
  StopSpeedPlanner planner(StopPlannerParameters{}, 9.0);
  planner.begin_step(5.0, 1.0, kStepLength);
  planner.set_cruise(5.1, 1.0);
  EXPECT_DOUBLE_EQ(planner.speed(), 5.1);
  EXPECT_DOUBLE_EQ(planner.start_acceleration(), 1.0) << "first step: the measured acceleration";
  planner.end_step(5.1);
  planner.begin_step(5.3, 0.0, kStepLength);  // SUMO did not follow: measured again
  EXPECT_DOUBLE_EQ(planner.start_acceleration(), 0.0);
  EXPECT_THROW(StopSpeedPlanner(StopPlannerParameters{}, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace signalsim
