// The speed the generator predicts (speed_profile.hpp): the step loop's planner rolled out, and the
// bounds the rules use.
#include "law/speed_profile.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "route_fixture.hpp"

namespace signalsim::generate {
using namespace law;  // the rules: sections, speeds, expectations (src/law)
namespace {

const SpeedLimits kEgoLimits{13.89, 1.0, 1.0};

// 200 m at 13.89 m/s, a 15 m internal lane at 8 m/s, 300 m at 13.89 m/s.
RouteMap slow_junction() {
  test::RouteFixture f;
  f.lane("a", 200.0);
  f.internal("J", 0, 15.0, TurnDirection::Left, 8.0);
  f.lane("b", 300.0);
  return f.build();
}

TEST(SpeedProfile, PlannedFollowsTheLaneLimitsWithTheComfortableDeceleration) {
  const RouteMap route = slow_junction();
  const SpeedProfile p(route, 0.0, 13.8, kEgoLimits, 0.1, {});
  EXPECT_NEAR(p.planned(50.0), 13.89, 1e-9);   // accelerated to the top speed (jerk-limited)
  // Braking for 8 m/s at 0.9 m/s^2 with the jerk ramps begins before 200 - (13.89^2 - 8^2) / 1.8 = 128.4.
  EXPECT_NEAR(p.planned(110.0), 13.89, 1e-9);
  EXPECT_LT(p.planned(128.0), 13.89);
  // Under the envelope of the ego's decel, v = sqrt(8^2 + 2 * 1.0 * (200 - s)), and not far below it.
  EXPECT_LE(p.planned(170.0), std::sqrt(64.0 + 2.0 * 30.0));
  EXPECT_GT(p.planned(170.0), std::sqrt(64.0 + 2.0 * 0.7 * 30.0));
  // At or below the limit where the front enters the slow lane, and all along it.
  for (double s = 200.0; s <= 215.0; s += 0.5) EXPECT_LE(p.planned(s), 8.0 + 1e-3) << "s " << s;
  EXPECT_GT(p.planned(200.0), 7.9);
  EXPECT_NEAR(p.upper(50.0), 13.89 + kSpeedSlack, 1e-9);
  EXPECT_NEAR(p.lower(50.0), 13.89 - kSpeedSlack, 1e-9);
  EXPECT_NEAR(p.max_planned(150.0, 210.0), p.planned(150.0), 1e-9);
  // 515 m: about 515 / 13.89 s plus what the slow lane costs; bounded, not exact.
  EXPECT_GT(p.travel_time(), 515.0 / 13.89);
  EXPECT_LT(p.travel_time(), 515.0 / 13.89 + 10.0);
}

TEST(SpeedProfile, LowerIsZeroWhereTheEgoMayBeBrakingAndARestartAfter) {
  const RouteMap route = slow_junction();
  const SpeedProfile p(route, 0.0, 13.8, kEgoLimits, 0.1, {{300.0, 100.0, "light X"}});
  EXPECT_EQ(p.lower(250.0), 0.0);
  EXPECT_EQ(p.lower(300.0), 0.0);
  // Restarting from rest: the jerk-limited start counts accel^3 / (3 jerk^2) = 1/3 m as ramp.
  EXPECT_NEAR(p.lower(350.0), std::sqrt(2.0 * kRestartShare * 1.0 * (50.0 - 1.0 / 3.0)), 1e-9);
  EXPECT_NEAR(p.lower(450.0), 13.89 - kSpeedSlack, 1e-3);  // back at the planned speed
  EXPECT_NEAR(p.lower(150.0), p.planned(150.0) - kSpeedSlack, 1e-9);                // before the zone
  EXPECT_EQ(p.lower_reason(250.0), "it may be braking for light X");
  EXPECT_EQ(p.lower_reason(350.0), "it may be restarting from rest at light X");
  EXPECT_EQ(p.lower_reason(150.0), "the planned speed less 0.3 m/s");
  ASSERT_NE(p.stop_zone_at(201.0), nullptr);
  EXPECT_EQ(p.stop_zone_at(199.0), nullptr);
}

TEST(SpeedProfile, BrakingDistances) {
  EXPECT_NEAR(light_braking_distance(13.89), 13.89 * 13.89 / 1.6 + 2.0 * 13.89 + 10.0, 1e-9);  // 158.4 m
  EXPECT_NEAR(yield_braking_distance(13.89), 13.89 * 13.89 / 6.0 + 15.0, 1e-9);                // 47.2 m
  // The normal stop of the judge (-0.9 m/s^2 once it brakes, planning/stop) needs v^2 / 1.8 + ramp:
  // the light's distance covers it with room.
  EXPECT_GT(light_braking_distance(13.89), 13.89 * 13.89 / 1.8 + 13.89);
}

}  // namespace
}  // namespace signalsim::generate
