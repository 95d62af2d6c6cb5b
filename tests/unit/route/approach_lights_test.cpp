// SUMO link states -> the signal elements the judge reads (docs/behaviour.md §S3).
#include <gtest/gtest.h>

#include "route/approach_lights.hpp"

namespace signalsim::sumo {
namespace {

// The cross net's south approach: links 8 right, 9 straight, 10 straight, 11 left.
ApproachLight south_approach(TurnDirection ego, int ego_link) {
  ApproachLight light;
  light.tls_id = "C";
  light.link_index = ego_link;
  light.lane_index = ego_link <= 9 ? 0 : 1;  // lane 0: right 8, straight 9; lane 1: straight 10, left 11
  light.direction = ego;
  light.links = {{TurnDirection::Right, 8, 0}, {TurnDirection::Straight, 9, 0}, {TurnDirection::Straight, 10, 1},
                 {TurnDirection::Left, 11, 1}};
  return light;
}

std::string elements(const std::string& state, const ApproachLight& light) {
  const auto e = signal_elements(state, light);
  return e ? describe_elements(*e) : "off";
}

TEST(SignalElements, CircleFollowsTheStraightLinks) {
  const ApproachLight straight = south_approach(TurnDirection::Straight, 9);
  EXPECT_EQ(elements("rrrrrrrrGGGgrrrr", straight), "green");
  EXPECT_EQ(elements("rrrrrrrryyyyrrrr", straight), "amber");
  EXPECT_EQ(elements("rrrrrrrrrrrrrrrr", straight), "red");
  EXPECT_EQ(elements("rrrrrrrruuuurrrr", straight), "red") << "red-yellow is still red";
}

TEST(SignalElements, AGreenTurnUnderARedCircleIsAnArrow) {
  const ApproachLight left = south_approach(TurnDirection::Left, 11);
  EXPECT_EQ(elements("rrrrrrrrrrrGrrrr", left), "red+green_left_arrow");
  EXPECT_EQ(elements("rrrrrrrrGGGgrrrr", left), "green") << "no arrow when the circle is green too";
  const ApproachLight straight = south_approach(TurnDirection::Straight, 9);
  EXPECT_EQ(elements("rrrrrrrrGrrrrrrr", straight), "red+green_right_arrow");
  EXPECT_EQ(elements("rrrrrrrrsrrrrrrr", straight), "red+green_right_arrow") << "'s' is a green arrow, stop first";
  EXPECT_EQ(elements("rrrrrrrrrrrGrrrr", straight), "red+green_left_arrow") << "the straight ego stops on it";
}

TEST(SignalElements, TheEgosRedOrAmberLinkIsNeverAGreenCircle) {
  // Found in review: straight links green, the left link red -> a left turner must see red.
  const ApproachLight left = south_approach(TurnDirection::Left, 11);
  EXPECT_EQ(elements("rrrrrrrrGGGrrrrr", left), "red+green_right_arrow");
  EXPECT_TRUE(is_traffic_signal_stop(LaneTurnDirection::Left, *signal_elements("rrrrrrrrGGGrrrrr", left)));
  EXPECT_EQ(elements("rrrrrrrrGGGyrrrr", left), "amber+green_right_arrow");
  // A straight ego on lane 1 follows its own lane's straight link, not lane 0's.
  const ApproachLight straight_lane1 = south_approach(TurnDirection::Straight, 10);
  EXPECT_EQ(elements("rrrrrrrrrGrrrrrr", straight_lane1), "red");
  EXPECT_EQ(elements("rrrrrrrrrrGrrrrr", straight_lane1), "green");
}

TEST(SignalElements, AnotherLinkOfTheEgosDirectionIsNoArrowForTheEgo) {
  // SUMO's pasubio net: one lane with two right turns to two edges; the other one green, the ego's red.
  ApproachLight light;
  light.link_index = 1;
  light.lane_index = 0;
  light.direction = TurnDirection::Right;
  light.links = {{TurnDirection::Right, 0, 0}, {TurnDirection::Right, 1, 0}, {TurnDirection::Straight, 2, 0}};
  EXPECT_EQ(elements("grr", light), "red");
  EXPECT_TRUE(is_traffic_signal_stop(LaneTurnDirection::Right, *signal_elements("grr", light)));
  EXPECT_EQ(elements("rgr", light), "red+green_right_arrow") << "its own link is its arrow";
  EXPECT_FALSE(is_traffic_signal_stop(LaneTurnDirection::Right, *signal_elements("rgr", light)));
  EXPECT_FALSE(shows_arrow({"grr", "rrG"}, light)) << "no arrow bulb for the ego from the other link";
  EXPECT_TRUE(shows_arrow({"rgr"}, light));
}

TEST(SignalElements, ArrowsMatchTheJudgesTurnDirection) {
  const auto arrow = signal_elements("rrrrrrrrrrrGrrrr", south_approach(TurnDirection::Left, 11));
  ASSERT_TRUE(arrow);
  EXPECT_FALSE(is_traffic_signal_stop(LaneTurnDirection::Left, *arrow)) << "left ego goes on its arrow";
  EXPECT_TRUE(is_traffic_signal_stop(LaneTurnDirection::Straight, *arrow)) << "straight ego stops";
  EXPECT_TRUE(is_traffic_signal_stop(LaneTurnDirection::Right, *arrow));
}

TEST(SignalElements, AnOffLinkTakesTheJudgeOut) {
  EXPECT_EQ(elements("ooooooooooooOOOO", south_approach(TurnDirection::Straight, 9)), "off");
  EXPECT_EQ(elements("rrrrrrrrrOrrrrrr", south_approach(TurnDirection::Straight, 9)), "off");
}

TEST(SignalElements, WithoutAStraightLinkTheEgosLinkIsTheCircle) {
  ApproachLight turn_only;
  turn_only.link_index = 0;
  turn_only.direction = TurnDirection::Left;
  turn_only.links = {{TurnDirection::Left, 0}};
  EXPECT_EQ(elements("G", turn_only), "green");
  EXPECT_EQ(elements("r", turn_only), "red");
}

TEST(JudgeTurnDirection, MapsEveryDirection) {
  EXPECT_EQ(judge_turn_direction(TurnDirection::Left), LaneTurnDirection::Left);
  EXPECT_EQ(judge_turn_direction(TurnDirection::Right), LaneTurnDirection::Right);
  EXPECT_EQ(judge_turn_direction(TurnDirection::Straight), LaneTurnDirection::Straight);
  EXPECT_EQ(judge_turn_direction(TurnDirection::None), LaneTurnDirection::Else);
}

}  // namespace
}  // namespace signalsim::sumo

namespace signalsim::sumo {
namespace {

TEST(ShowsArrow, OnlyATurnLitUnderANonGreenCircleIsAnArrowBulb) {
  const ApproachLight left = south_approach(TurnDirection::Left, 11);
  EXPECT_FALSE(shows_arrow({"GGGgrrrrGGGgrrrr", "yyyyrrrryyyyrrrr", "rrrrrrrrrrrrrrrr"}, left))
      << "a permissive left (g under a green circle) is no arrow";
  EXPECT_TRUE(shows_arrow({"rrrrrrrrGGGgrrrr", "rrrrrrrrrrrGrrrr"}, left));
  EXPECT_TRUE(shows_arrow({"rrrrrrrrsrrrrrrr"}, left));
}

}  // namespace
}  // namespace signalsim::sumo
