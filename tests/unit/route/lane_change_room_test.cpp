// The room of a lane change and whether it fits (route/lane_change_room.hpp): the one rule the lane
// plan and the lateral planner share. Numbers of bologna_acosta's edges.
#include <gtest/gtest.h>

#include <cmath>

#include "route/lane_change_room.hpp"

namespace signalsim::sumo {
namespace {

TEST(LaneChangeRoom, FrontStaysOnTheEdge) {
  const LaneChangeEgo ego;  // base_link_to_front 3.7, depart_pos 0
  EXPECT_DOUBLE_EQ(lane_change_room(211.92, false, ego), 208.22);  // 122
  EXPECT_DOUBLE_EQ(lane_change_room(0.54, false, ego), -3.16);     // 204[1][0]
  LaneChangeEgo departed = ego;
  departed.depart_pos = 10.0;
  EXPECT_DOUBLE_EQ(lane_change_room(48.5, true, departed), 38.5);  // base_link from depart_pos - 3.7
}

TEST(LaneChangeRoom, DefaultTimingShrinksOnAShortEdge) {
  EXPECT_DOUBLE_EQ(default_lane_change(208.22).lead, 20.0);
  EXPECT_DOUBLE_EQ(default_lane_change(208.22).length, 50.0);
  // 31 (11.38 m): 7.68 m of room, lead 1.536 m, 5.144 m of lateral motion.
  EXPECT_NEAR(default_lane_change(7.68).lead, 1.536, 1e-9);
  EXPECT_NEAR(default_lane_change(7.68).length, 5.144, 1e-9);
}

TEST(LaneChangeRoom, ShiftAcrossLanes) {
  EXPECT_DOUBLE_EQ(lane_shift({3.2, 3.2, 3.2}, 0, 1), 3.2);
  EXPECT_DOUBLE_EQ(lane_shift({3.2, 3.0, 3.2}, 2, 0), 6.2);
  EXPECT_DOUBLE_EQ(lane_shift({3.2, 3.0}, 1, 1), 0.0);
}

TEST(LaneChangeRoom, PhysicallySensibleLength) {
  const LaneChangeEgo ego;  // grip 9 m/s^2
  // At 13.89 m/s the grip limits: L = v sqrt((10 / sqrt 3) d / a).
  EXPECT_NEAR(min_lane_change_length(3.2, 13.89, ego), 13.89 * std::sqrt(10.0 / std::sqrt(3.0) * 3.2 / 9.0), 1e-9);
  EXPECT_NEAR(min_lane_change_length(3.2, 13.89, ego), 19.90, 0.01);
  // Slowly the steering limits (radius 3.31 m): L = sqrt((10 / sqrt 3) d R).
  EXPECT_NEAR(min_lane_change_length(3.2, 2.0, ego), std::sqrt(10.0 / std::sqrt(3.0) * 3.2 * kMinTurningRadius), 1e-9);
  EXPECT_DOUBLE_EQ(min_lane_change_length(0.1, 1.0, ego), kMinLaneChangeLength);
}

TEST(LaneChangeRoom, AShiftOf6point4MetresIn5MetresDoesNotFit) {
  const LaneChangeEgo ego;
  EXPECT_FALSE(lane_change_fits(7.68, 6.4, 13.89, ego));   // 31: 5.14 m, needs 28.15 m
  EXPECT_FALSE(lane_change_fits(7.68, 6.4, 1.0, ego));     // even crawling: sharper than a car steers
  EXPECT_FALSE(lane_change_fits(11.88, 3.2, 13.89, ego));  // 3 (15.58 m): 8.50 m, needs 19.90 m
  EXPECT_TRUE(lane_change_fits(208.22, 3.2, 13.89, ego));  // 122
  EXPECT_TRUE(lane_change_fits(208.22, 6.4, 13.89, ego));  // two lanes in 50 m: 28.15 m needed
}

TEST(LaneChangeRoom, TheFitIsCheckedAtTheSpeedTheTurnsOnEitherSideLeave) {
  LaneChangeEgo ego;  // accel and decel 1 m/s^2, base_link 3.7 m behind the front (defaults)
  // A 27.7 m edge (24 m of room) between two 8 m/s turns on 13.89 m/s lanes: the lateral motion
  // (front 8.5 .. 26.7 m) runs at most at sqrt(8^2 + 2 * 1 * 8.5 ...) < 10 m/s, where the 3.2 m
  // shift needs 14.3 m and has 18.2 m; at the lane limit it would need 19.9 m.
  const EdgeSpeeds turns{13.89, 8.0, 8.0};
  const double speed = lane_change_speed(27.7, false, turns, ego);
  EXPECT_LT(speed, 10.0);
  EXPECT_GT(speed, 8.0);
  EXPECT_TRUE(lane_change_fits(24.0, 3.2, speed, ego));
  EXPECT_FALSE(lane_change_fits(24.0, 3.2, 13.89, ego)) << "checked at the lane limit it was refused";
  // Without turns around it the lane limit (or max_speed) is the speed.
  EXPECT_DOUBLE_EQ(lane_change_speed(27.7, false, EdgeSpeeds{13.89}, ego), 13.89);
  ego.max_speed = 12.0;
  EXPECT_DOUBLE_EQ(lane_change_speed(27.7, false, EdgeSpeeds{13.89}, ego), 12.0);
  // On the first edge from the departure: 5 m/s at depart_pos 0 is still under 8 m/s 10 m on.
  ego.depart_speed = 5.0;
  EXPECT_LT(lane_change_speed(27.7, true, EdgeSpeeds{13.89}, ego), std::sqrt(25.0 + 2.0 * 27.7));
}

TEST(LaneChangeRoom, RoomNeededForALength) {
  EXPECT_NEAR(lane_change_room_needed(19.9), 20.9 / 0.8, 1e-9);   // lead 20 % of the room
  EXPECT_DOUBLE_EQ(lane_change_room_needed(50.0), 63.75);          // lead 12.75 m, margin 1 m
  EXPECT_TRUE(std::isinf(lane_change_room_needed(50.5)));          // longer than any default
  EXPECT_GE(default_lane_change(lane_change_room_needed(19.9)).length, 19.9 - 1e-9);
}

}  // namespace
}  // namespace signalsim::sumo
