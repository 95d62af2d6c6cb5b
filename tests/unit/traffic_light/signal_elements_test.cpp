// docs/behaviour.md §L1.3 (highest confidence per shape, Decision), §L1.4 (color and arrow matching), §L1.8.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "signal_element.hpp"
#include "traffic_light/signal_elements.hpp"

namespace signalsim {
namespace {

using test::el;

using C = SignalColor;
using S = SignalShape;
using D = LaneTurnDirection;

TEST(SignalElements, EnumValuesMatchAutowareMessage) {
  // docs/behaviour.md §L1.4 enum values of autoware_perception_msgs/TrafficLightElement.
  EXPECT_EQ(static_cast<int>(C::Unknown), 0);
  EXPECT_EQ(static_cast<int>(C::Red), 1);
  EXPECT_EQ(static_cast<int>(C::Amber), 2);
  EXPECT_EQ(static_cast<int>(C::Green), 3);
  EXPECT_EQ(static_cast<int>(C::White), 4);
  EXPECT_EQ(static_cast<int>(S::Circle), 1);
  EXPECT_EQ(static_cast<int>(S::LeftArrow), 2);
  EXPECT_EQ(static_cast<int>(S::RightArrow), 3);
  EXPECT_EQ(static_cast<int>(S::UpArrow), 4);
  EXPECT_EQ(static_cast<int>(S::Cross), 10);
  EXPECT_EQ(static_cast<int>(SignalStatus::SolidOff), 1);
  EXPECT_EQ(static_cast<int>(SignalStatus::SolidOn), 2);
  EXPECT_EQ(static_cast<int>(SignalStatus::Flashing), 3);
}

TEST(SignalElements, TurnDirectionFromString) {
  EXPECT_EQ(lane_turn_direction_from_string("left"), D::Left);
  EXPECT_EQ(lane_turn_direction_from_string("right"), D::Right);
  EXPECT_EQ(lane_turn_direction_from_string("straight"), D::Straight);
  EXPECT_EQ(lane_turn_direction_from_string("else"), D::Else);
  EXPECT_EQ(lane_turn_direction_from_string(""), D::Else);
  EXPECT_EQ(lane_turn_direction_from_string("Left"), D::Else);  // Autoware compares exactly
}

TEST(HighestConfidencePerShape, KeepsTheMostConfidentDetectionOfEachShape) {
  const auto best = highest_confidence_per_shape({
      el(C::Green, S::Circle, 0.6),
      el(C::Green, S::LeftArrow, 0.7),
      el(C::Red, S::Circle, 0.9),
      el(C::Amber, S::Circle, 0.3),
      el(C::Red, S::LeftArrow, 0.8),
  });
  ASSERT_EQ(best.size(), 2u);
  EXPECT_EQ(best[0], el(C::Red, S::Circle, 0.9));
  EXPECT_EQ(best[1], el(C::Red, S::LeftArrow, 0.8));
}

TEST(HighestConfidencePerShape, OutputSortedByShapeAndEmptyStaysEmpty) {
  EXPECT_TRUE(highest_confidence_per_shape({}).empty());
  const auto best = highest_confidence_per_shape(
      {el(C::Green, S::UpArrow), el(C::Red, S::Circle), el(C::Green, S::LeftArrow), el(C::Unknown, S::Unknown)});
  ASSERT_EQ(best.size(), 4u);
  EXPECT_EQ(best[0].shape, S::Unknown);
  EXPECT_EQ(best[1].shape, S::Circle);
  EXPECT_EQ(best[2].shape, S::LeftArrow);
  EXPECT_EQ(best[3].shape, S::UpArrow);
}

TEST(HighestConfidencePerShape, TieGoesToTheMoreCautiousColorWhateverTheOrder) {
  // Red > Unknown > Amber > White > Green at equal confidence.
  for (const auto& pair : {std::pair{C::Red, C::Green}, std::pair{C::Red, C::Amber}, std::pair{C::Unknown, C::Amber},
                           std::pair{C::Amber, C::Green}, std::pair{C::White, C::Green}, std::pair{C::Red, C::Unknown}}) {
    const auto [cautious, other] = pair;
    const auto ab = highest_confidence_per_shape({el(cautious, S::Circle, 0.8), el(other, S::Circle, 0.8)});
    const auto ba = highest_confidence_per_shape({el(other, S::Circle, 0.8), el(cautious, S::Circle, 0.8)});
    ASSERT_EQ(ab.size(), 1u);
    EXPECT_EQ(ab[0].color, cautious);
    EXPECT_EQ(ab, ba);
  }
  // Same color and confidence: the smaller status value.
  const auto st = highest_confidence_per_shape({el(C::Amber, S::Circle, 0.8, SignalStatus::Flashing),
                                                el(C::Amber, S::Circle, 0.8, SignalStatus::SolidOn)});
  EXPECT_EQ(st[0].status, SignalStatus::SolidOn);
}

TEST(HighestConfidencePerShape, NanConfidenceCountsAsLowest) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto best = highest_confidence_per_shape({el(C::Red, S::Circle, nan), el(C::Green, S::Circle, 0.01)});
  EXPECT_EQ(best[0].color, C::Green);
  const auto best2 = highest_confidence_per_shape({el(C::Green, S::Circle, 0.01), el(C::Red, S::Circle, nan)});
  EXPECT_EQ(best2[0].color, C::Green);
}

TEST(IsTrafficSignalStop, GreenCircleGoesForEveryDirection) {
  // docs/behaviour.md §L1.4 step 1.
  for (D d : {D::Else, D::Straight, D::Left, D::Right}) {
    EXPECT_FALSE(is_traffic_signal_stop(d, {el(C::Green)})) << to_string(d);
    EXPECT_FALSE(is_traffic_signal_stop(d, {el(C::Red, S::LeftArrow), el(C::Green)})) << to_string(d);
  }
}

TEST(IsTrafficSignalStop, EverythingElseStopsOnALaneWithoutTurnDirection) {
  // docs/behaviour.md §L1.4 step 2: arrows ignored on "else".
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {el(C::Red)}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {el(C::Amber)}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {el(C::Unknown, S::Unknown)}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {el(C::Red), el(C::Green, S::LeftArrow), el(C::Green, S::RightArrow),
                                               el(C::Green, S::UpArrow)}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {el(C::Green, S::Cross)}));  // green, but not a circle
}

TEST(IsTrafficSignalStop, GreenArrowMatchedToTurnDirection) {
  // docs/behaviour.md §L1.4 steps 3-5: red circle plus a green arrow for the lane's turn (docs/behaviour.md §S3).
  const std::vector<std::pair<D, S>> matches = {{D::Left, S::LeftArrow}, {D::Right, S::RightArrow},
                                                {D::Straight, S::UpArrow}};
  const std::vector<S> arrows = {S::LeftArrow, S::RightArrow, S::UpArrow, S::UpLeftArrow, S::UpRightArrow};
  for (const auto& [dir, match] : matches) {
    EXPECT_EQ(matching_arrow_shape(dir), match);
    for (S arrow : arrows) {
      const bool go = arrow == match;
      EXPECT_EQ(is_traffic_signal_stop(dir, {el(C::Red), el(C::Green, arrow)}), !go)
          << to_string(dir) << " " << to_string(arrow);
    }
  }
  EXPECT_EQ(matching_arrow_shape(D::Else), std::nullopt);
}

TEST(IsTrafficSignalStop, ArrowMustBeGreen) {
  // Decision (docs/behaviour.md §L1.4 details, §L10): an amber or red arrow of the right shape does not count.
  EXPECT_TRUE(is_traffic_signal_stop(D::Left, {el(C::Red), el(C::Red, S::LeftArrow)}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Left, {el(C::Red), el(C::Amber, S::LeftArrow)}));
  EXPECT_TRUE(is_traffic_signal_stop(D::Left, {el(C::Red), el(C::Unknown, S::LeftArrow)}));
  EXPECT_FALSE(is_traffic_signal_stop(D::Left, {el(C::Red), el(C::Green, S::LeftArrow)}));
  // The arrow alone (no circle detected) is enough.
  EXPECT_FALSE(is_traffic_signal_stop(D::Right, {el(C::Green, S::RightArrow)}));
}

TEST(IsTrafficSignalStop, StatusIsIgnored) {
  EXPECT_TRUE(is_traffic_signal_stop(D::Else, {el(C::Amber, S::Circle, 1.0, SignalStatus::Flashing)}));
  EXPECT_FALSE(is_traffic_signal_stop(D::Else, {el(C::Green, S::Circle, 1.0, SignalStatus::Flashing)}));
  EXPECT_FALSE(is_traffic_signal_stop(D::Else, {el(C::Green, S::Circle, 1.0, SignalStatus::SolidOff)}));
}

TEST(IsYellow, AmberSolidOnOrUnknownStatusAnyShape) {
  // docs/behaviour.md §L1.8 "yellow now".
  EXPECT_TRUE(is_yellow({el(C::Amber)}));
  EXPECT_TRUE(is_yellow({el(C::Amber, S::Circle, 1.0, SignalStatus::Unknown)}));
  EXPECT_TRUE(is_yellow({el(C::Red), el(C::Amber, S::LeftArrow)}));
  EXPECT_FALSE(is_yellow({el(C::Amber, S::Circle, 1.0, SignalStatus::Flashing)}));
  EXPECT_FALSE(is_yellow({el(C::Amber, S::Circle, 1.0, SignalStatus::SolidOff)}));
  EXPECT_FALSE(is_yellow({el(C::Red), el(C::Green)}));
  EXPECT_FALSE(is_yellow({}));
  EXPECT_TRUE(has_green_circle({el(C::Red), el(C::Green)}));
  EXPECT_FALSE(has_green_circle({el(C::Green, S::LeftArrow)}));
}

}  // namespace
}  // namespace signalsim
