#include "turn_signal/akima_spline.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

namespace signalsim {
namespace {

TEST(AkimaSpline, PassesThroughEveryKnot) {
  const std::vector<double> keys{0.0, 0.7, 1.5, 3.0, 3.2, 5.0};
  const std::vector<double> values{1.0, -2.0, 4.0, 0.5, 0.25, 3.0};
  const std::vector<double> result = akima_interpolate(keys, values, keys);
  ASSERT_EQ(result.size(), keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) EXPECT_NEAR(result[i], values[i], 1e-12) << "knot " << i;
}

TEST(AkimaSpline, LinearDataStaysLinear) {
  const std::vector<double> keys{0.0, 1.0, 2.5, 3.0, 7.0, 8.0};
  std::vector<double> values;
  for (double k : keys) values.push_back(2.0 * k - 1.0);
  const std::vector<double> queries{0.0, 0.3, 1.7, 2.75, 5.5, 7.9, 8.0};
  const std::vector<double> result = akima_interpolate(keys, values, queries);
  for (std::size_t i = 0; i < queries.size(); ++i) EXPECT_NEAR(result[i], 2.0 * queries[i] - 1.0, 1e-12);
}

TEST(AkimaSpline, TwoKnotsGiveAStraightLine) {
  const std::vector<double> result = akima_interpolate({0.0, 2.0}, {1.0, 5.0}, {0.5, 1.0, 1.5});
  EXPECT_NEAR(result[0], 2.0, 1e-12);
  EXPECT_NEAR(result[1], 3.0, 1e-12);
  EXPECT_NEAR(result[2], 4.0, 1e-12);
}

// Zigzag 0,1,0,1,0: knot slopes t = {1, 0, 0, 0, -1} (end secant, end-neighbour means, equal
// Akima weights at the middle). Piece 0: y = h + h^2 - h^3 -> 0.625 at 0.5; piece 1: 1 - 3h^2 + 2h^3.
TEST(AkimaSpline, MatchesHandComputedZigzag) {
  const std::vector<double> result =
      akima_interpolate({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, 1.0, 0.0, 1.0, 0.0}, {0.5, 1.5, 3.5});
  EXPECT_NEAR(result[0], 0.625, 1e-12);
  EXPECT_NEAR(result[1], 0.5, 1e-12);
  EXPECT_NEAR(result[2], 0.625, 1e-12);  // mirror image of piece 0
}

// Secants m = {1, 2, 1, 0, 2}. Knot 2: weights |m3-m2| = 1, |m1-m0| = 1 -> t2 = 1.5.
// Knot 3: weights |m4-m3| = 2, |m2-m1| = 1 -> t3 = (2*1 + 1*0) / 3 = 2/3.
// Piece 2: 3 + 1.5h - (2/3)h^2 + (1/6)h^3 -> 3 + 29/48 at h = 0.5.
TEST(AkimaSpline, MatchesHandComputedUnequalWeights) {
  const std::vector<double> result =
      akima_interpolate({0.0, 1.0, 2.0, 3.0, 4.0, 5.0}, {0.0, 1.0, 3.0, 4.0, 4.0, 6.0}, {2.5});
  EXPECT_NEAR(result[0], 3.0 + 29.0 / 48.0, 1e-12);
}

// Akima does not overshoot a step: the flat parts stay flat, the ramp is a smoothstep.
TEST(AkimaSpline, StepDoesNotOvershoot) {
  const std::vector<double> keys{0.0, 1.0, 2.0, 3.0, 4.0, 5.0};
  const std::vector<double> values{0.0, 0.0, 0.0, 1.0, 1.0, 1.0};
  const std::vector<double> result = akima_interpolate(keys, values, {0.5, 1.5, 2.5, 3.5, 4.5});
  EXPECT_DOUBLE_EQ(result[0], 0.0);
  EXPECT_DOUBLE_EQ(result[1], 0.0);
  EXPECT_NEAR(result[2], 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(result[3], 1.0);
  EXPECT_DOUBLE_EQ(result[4], 1.0);
}

TEST(AkimaSpline, ExtendsEndPiecesOutsideTheKeys) {
  // Piece 0 of the zigzag extended to h = -1: -1 + 1 + 1 = 1; last piece mirrored.
  const std::vector<double> result =
      akima_interpolate({0.0, 1.0, 2.0, 3.0, 4.0}, {0.0, 1.0, 0.0, 1.0, 0.0}, {-1.0, 5.0});
  EXPECT_NEAR(result[0], 1.0, 1e-12);
  EXPECT_NEAR(result[1], 1.0, 1e-12);
}

TEST(AkimaSpline, DegenerateInputs) {
  EXPECT_EQ(akima_interpolate({}, {}, {1.0, 2.0}), (std::vector<double>{0.0, 0.0}));
  EXPECT_EQ(akima_interpolate({3.0}, {7.0}, {1.0}), (std::vector<double>{7.0}));
  EXPECT_TRUE(akima_interpolate({0.0, 1.0}, {0.0, 1.0}, {}).empty());
  EXPECT_THROW(akima_interpolate({0.0, 1.0}, {0.0}, {0.5}), std::invalid_argument);
}

}  // namespace
}  // namespace signalsim
