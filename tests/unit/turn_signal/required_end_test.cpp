// docs/behaviour.md §T7: required end point = backward scan over the lane resampled every 1 m (Akima in x/y).
#include "turn_signal/required_end.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace signalsim {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kThresholdDeg = 15.0;  // turn_signal_intersection_angle_threshold_deg default

// Circular arc of `radius` turning `sweep` rad (left if turn_sign = +1, right if -1), starting at
// `start` with heading `heading`, as `segments` chords.
std::vector<Vec2> arc(int segments, double radius, double sweep, double turn_sign, Vec2 start = {},
                      double heading = 0.0) {
  std::vector<Vec2> points;
  for (int i = 0; i <= segments; ++i) {
    const double theta = sweep * i / segments;
    const double along = radius * std::sin(theta);
    const double left = turn_sign * radius * (1.0 - std::cos(theta));
    points.push_back({start.x + along * std::cos(heading) - left * std::sin(heading),
                      start.y + along * std::sin(heading) + left * std::cos(heading)});
  }
  return points;
}

std::vector<Vec2> straight(Vec2 from, Vec2 to, int segments) {
  std::vector<Vec2> points;
  for (int i = 0; i <= segments; ++i) {
    const double t = static_cast<double>(i) / segments;
    points.push_back(from + t * (to - from));
  }
  return points;
}

std::vector<Vec2> concatenate(std::vector<Vec2> a, const std::vector<Vec2>& b) {
  a.insert(a.end(), b.begin() + 1, b.end());  // b starts where a ends
  return a;
}

const Polyline kDenseLeftArc{arc(900, 10.0, kPi / 2.0, +1.0)};  // 0.1 degree chords, length 15.708

// docs/behaviour.md §T7 table, row 1: 90° left arc, R = 10 m, from (0,0) heading +x.
TEST(RequiredEnd, DenseLeftArcEndsAtTwelveMetres) {
  const double s = required_end_arc_length(kDenseLeftArc, kThresholdDeg);
  EXPECT_DOUBLE_EQ(s, 12.0);
  const Vec2 p = kDenseLeftArc.point_at(s);
  EXPECT_NEAR(p.x, 9.32, 0.005);
  EXPECT_NEAR(p.y, 6.38, 0.005);
}

TEST(RequiredEnd, RightTurnMirrorGivesTheSameArcLength) {
  const Polyline right_arc{arc(900, 10.0, kPi / 2.0, -1.0)};
  const double s = required_end_arc_length(right_arc, kThresholdDeg);
  EXPECT_DOUBLE_EQ(s, 12.0);
  EXPECT_NEAR(right_arc.point_at(s).y, -6.38, 0.005);
}

// docs/behaviour.md §T7 table, row 2: a straight lane is required to its end (the old forward scan gave 0).
TEST(RequiredEnd, StraightLaneIsRequiredToItsEnd) {
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{straight({0, 0}, {20, 0}, 20)}, kThresholdDeg), 20.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{{{0, 0}, {20, 0}}}, kThresholdDeg), 20.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{straight({3, 4}, {-9, -12}, 7)}, kThresholdDeg), 20.0);
}

// docs/behaviour.md §T7 table, row 3: 10 m straight + the same arc + 10 m straight.
TEST(RequiredEnd, StraightArcStraightEndsTwelveMetresIntoTheArc) {
  const std::vector<Vec2> bend = arc(900, 10.0, kPi / 2.0, +1.0, {10.0, 0.0});
  const Vec2 bend_end = bend.back();
  const Polyline dense{concatenate(concatenate(straight({0, 0}, {10, 0}, 100), bend),
                                   straight(bend_end, bend_end + Vec2{0.0, 10.0}, 100))};
  EXPECT_DOUBLE_EQ(required_end_arc_length(dense, kThresholdDeg), 22.0);
  // Lanelet-style: the straights as single 10 m segments.
  const Polyline sparse_straights{concatenate(concatenate(straight({0, 0}, {10, 0}, 1), bend),
                                              straight(bend_end, bend_end + Vec2{0.0, 10.0}, 1))};
  EXPECT_DOUBLE_EQ(required_end_arc_length(sparse_straights, kThresholdDeg), 22.0);
}

// Heading at station k of the dense arc is about (k + 0.5) rad/10, the end heading about 88 degrees:
// the scan returns the last station whose heading differs by at least the threshold.
TEST(RequiredEnd, AngleThresholdMovesTheEndAlongTheArc) {
  EXPECT_DOUBLE_EQ(required_end_arc_length(kDenseLeftArc, 10.0), 13.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(kDenseLeftArc, 30.0), 9.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(kDenseLeftArc, 45.0), 6.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(kDenseLeftArc, 60.0), 4.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(kDenseLeftArc, 85.0), 0.0);  // only the first station
  // No station turns that much: the lane end.
  EXPECT_NEAR(required_end_arc_length(kDenseLeftArc, 89.0), kDenseLeftArc.length(), 1e-9);
  // A zero threshold is met by the last pose itself (|0| >= 0): the lane end.
  EXPECT_NEAR(required_end_arc_length(kDenseLeftArc, 0.0), kDenseLeftArc.length(), 1e-9);
}

// Sparse 5-point arc (22.5 degree chords, length 15.607 by chords). Akima's end slope is the last
// chord's direction, so the final heading is about 80 degrees instead of 88. Headings within 15
// degrees of it start after s = 10 (60.8 deg at s = 10, 66.6 deg at s = 11): the required end moves
// two metres back compared with the dense arc.
TEST(RequiredEnd, SparseFivePointArcEndsEarlierThanTheDenseArc) {
  const Polyline sparse{arc(4, 10.0, kPi / 2.0, +1.0)};
  EXPECT_DOUBLE_EQ(required_end_arc_length(sparse, kThresholdDeg), 10.0);
}

TEST(RequiredEnd, FewerThanTwoPointsGiveZero) {
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{}, kThresholdDeg), 0.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{{{1, 1}}}, kThresholdDeg), 0.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{{{1, 1}, {1, 1}}}, kThresholdDeg), 0.0);  // duplicates
}

// An "L" of two legs of length/2 each: right, then a 90 degree turn left.
Polyline l_shape(double length) { return Polyline{{{0, 0}, {length / 2, 0}, {length / 2, length / 2}}}; }

TEST(RequiredEnd, LaneShorterThanOneMetreIsRequiredToItsEnd) {
  // Stations {0, L}: both resampled poses share the one chord's heading.
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{{{0, 0}, {0.5, 0}}}, kThresholdDeg), 0.5);
  EXPECT_DOUBLE_EQ(required_end_arc_length(l_shape(0.5), kThresholdDeg), 0.5);
  EXPECT_DOUBLE_EQ(required_end_arc_length(l_shape(0.95), kThresholdDeg), 0.95);
}

// Terminal merge threshold 0.1 m: a last station closer than that to the end is replaced by the end.
TEST(RequiredEnd, TerminalStationMergeThreshold) {
  // 1.05 m: stations {0, 1.05}, one heading -> the end. 1.15 m: stations {0, 1, 1.15}; the first
  // resampled chord still points right while the last ones point up -> station 0.
  EXPECT_DOUBLE_EQ(required_end_arc_length(l_shape(1.05), kThresholdDeg), 1.05);
  EXPECT_DOUBLE_EQ(required_end_arc_length(l_shape(1.15), kThresholdDeg), 0.0);
}

// Below 0.1 m there is a single station, which motion_utils refuses to resample: the raw
// centerline poses are scanned instead (yaw towards the next raw point), so the L's corner counts.
TEST(RequiredEnd, LaneShorterThanTheMergeThresholdScansTheRawPoints) {
  EXPECT_DOUBLE_EQ(required_end_arc_length(l_shape(0.09), kThresholdDeg), 0.0);
  EXPECT_DOUBLE_EQ(required_end_arc_length(l_shape(0.11), kThresholdDeg), 0.11);  // resampled: {0, L}
  EXPECT_DOUBLE_EQ(required_end_arc_length(Polyline{{{0, 0}, {0.05, 0}}}, kThresholdDeg), 0.05);
}

}  // namespace
}  // namespace signalsim
