// build_route on nets built by netconvert 1.15 (tests/data/nets; sources and build.sh there).
#include "route/route_builder.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "test_nets.hpp"

namespace signalsim::sumo {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using testing::net_path;

const NetIndex& crossing() {
  static const NetIndex net = NetIndex::load(net_path("crossing.net.xml"));
  return net;
}
const NetIndex& roundabout() {
  static const NetIndex net = NetIndex::load(net_path("roundabout.net.xml"));
  return net;
}

std::vector<std::string> lane_ids(const RoutePlan& plan) {
  std::vector<std::string> ids;
  for (const Lanelet& l : plan.map.lanelets()) ids.push_back(l.lane_id);
  return ids;
}

std::string route_error(const NetIndex& net, const std::vector<std::string>& edges) {
  try {
    build_route(net, edges);
  } catch (const RouteError& e) {
    return e.what();
  }
  return "";
}

/// Lanelets start at 0, are contiguous, and each is as long as its SUMO lane's length attribute.
void expect_contiguous(const NetIndex& net, const RoutePlan& plan) {
  double s = 0.0;
  for (const Lanelet& l : plan.map.lanelets()) {
    EXPECT_DOUBLE_EQ(l.s_start, s) << l.lane_id;
    ASSERT_NE(net.lane(l.lane_id), nullptr) << l.lane_id;
    EXPECT_DOUBLE_EQ(l.length, net.lane(l.lane_id)->length) << l.lane_id;
    s += l.length;
  }
  EXPECT_DOUBLE_EQ(plan.map.length(), s);
}

// ---- crossing: turn lanelets ----------------------------------------------------------------------

TEST(RouteBuilderCrossing, StraightThrough) {
  const RoutePlan plan = build_route(crossing(), {"s_in", "n_out"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("s_in_0", ":C_11_0", "n_out_0"));
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(0, 0));
  EXPECT_EQ(plan.lane_changes, 0);
  expect_contiguous(crossing(), plan);

  const Lanelet& approach = plan.map.at(0);
  EXPECT_FALSE(approach.is_internal);
  EXPECT_EQ(approach.edge_id, "s_in");
  EXPECT_TRUE(approach.junction_id.empty());
  EXPECT_EQ(approach.turn_direction, TurnDirection::None);
  EXPECT_DOUBLE_EQ(approach.speed_limit, 13.89);
  EXPECT_DOUBLE_EQ(approach.width, 3.2);
  EXPECT_EQ(approach.shape.points().back(), (Vec2{204.80, 89.60}));
  ASSERT_TRUE(approach.traffic_light.has_value());
  EXPECT_EQ(approach.traffic_light->tls_id, "C");
  EXPECT_EQ(approach.traffic_light->link_index, 11);
  // s_in_0 leads straight on and right.
  EXPECT_THAT(approach.successor_turn_directions, ElementsAre(TurnDirection::Right, TurnDirection::Straight));

  const Lanelet& turn = plan.map.at(1);
  EXPECT_TRUE(turn.is_internal);
  EXPECT_EQ(turn.edge_id, ":C_11");
  EXPECT_EQ(turn.junction_id, "C");
  EXPECT_EQ(turn.turn_direction, TurnDirection::Straight);
  EXPECT_FALSE(turn.traffic_light.has_value());
  EXPECT_TRUE(turn.successor_turn_directions.empty());
  EXPECT_FALSE(plan.map.at(2).traffic_light.has_value());
}

TEST(RouteBuilderCrossing, LeftTurnHasTwoChainedInternalLanes) {
  // netconvert splits a left turn at the internal junction where it waits for oncoming traffic:
  // s_in_1 -> :C_13_0 -> :C_24_0 -> w_out_1, both internal lanes dir="l".
  const RoutePlan plan = build_route(crossing(), {"s_in", "w_out"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("s_in_1", ":C_13_0", ":C_24_0", "w_out_1"));
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(1, 1));  // the left turn needs the left lane
  EXPECT_EQ(plan.lane_changes, 0);
  expect_contiguous(crossing(), plan);

  EXPECT_EQ(plan.map.at(1).turn_direction, TurnDirection::Left);
  EXPECT_EQ(plan.map.at(2).turn_direction, TurnDirection::Left);
  EXPECT_EQ(plan.map.at(1).junction_id, "C");
  EXPECT_EQ(plan.map.at(2).junction_id, "C");  // not the internal junction ":C_24_0"
  EXPECT_EQ(plan.map.at(2).edge_id, ":C_24");
  // s_in_1: straight on, left, U-turn (left in a right-hand net).
  EXPECT_THAT(plan.map.at(0).successor_turn_directions, ElementsAre(TurnDirection::Straight, TurnDirection::Left));
  EXPECT_THAT(plan.map.at(1).successor_turn_directions, ElementsAre(TurnDirection::Left));
  EXPECT_TRUE(plan.map.at(2).successor_turn_directions.empty());
  ASSERT_TRUE(plan.map.at(0).traffic_light.has_value());
  EXPECT_EQ(plan.map.at(0).traffic_light->link_index, 13);
}

TEST(RouteBuilderCrossing, RightTurn) {
  const RoutePlan plan = build_route(crossing(), {"s_in", "e_out"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("s_in_0", ":C_10_0", "e_out_0"));
  EXPECT_EQ(plan.map.at(1).turn_direction, TurnDirection::Right);
  EXPECT_EQ(plan.map.at(0).turn_direction, TurnDirection::None);
  EXPECT_EQ(plan.map.at(2).turn_direction, TurnDirection::None);
}

TEST(RouteBuilderCrossing, UTurnIsLeftInRightHandNet) {
  const RoutePlan plan = build_route(crossing(), {"e_out", "e_in"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("e_out_1", ":E_0_0", "e_in_1"));
  EXPECT_EQ(plan.map.at(1).turn_direction, TurnDirection::Left);
  EXPECT_EQ(plan.map.at(1).junction_id, "E");
  EXPECT_FALSE(plan.map.at(0).traffic_light.has_value());  // E is unsignalised
}

// ---- params ---------------------------------------------------------------------------------------

TEST(RouteBuilderParams, LaneParamReachesTheTurnLanelets) {
  const RoutePlan plan = build_route(crossing(), {"s_in", "w_out"});
  const std::map<std::string, std::string> merged{{"origin", "lane"}, {"turn_signal_distance", "50"}};
  for (std::size_t i : {0u, 1u, 2u}) {
    EXPECT_EQ(plan.map.at(i).params, merged) << plan.map.at(i).lane_id;
    ASSERT_TRUE(plan.map.at(i).turn_signal_distance.has_value()) << plan.map.at(i).lane_id;
    EXPECT_DOUBLE_EQ(*plan.map.at(i).turn_signal_distance, 50.0);
  }
  EXPECT_TRUE(plan.map.at(3).params.empty());
  EXPECT_FALSE(plan.map.at(3).turn_signal_distance.has_value());
}

TEST(RouteBuilderParams, EdgeParamWithoutLaneParam) {
  const RoutePlan plan = build_route(crossing(), {"s_in", "e_out"});
  const std::map<std::string, std::string> edge_only{{"origin", "edge"}};
  EXPECT_EQ(plan.map.at(0).params, edge_only);
  EXPECT_EQ(plan.map.at(1).params, edge_only);  // the right turn leaves s_in_0
  EXPECT_FALSE(plan.map.at(1).turn_signal_distance.has_value());
}

TEST(RouteBuilderParams, NonNumericTurnSignalDistance) {
  // A defect of the edge at load: the error names the net's line, and inspect lists it.
  const std::string message = route_error(crossing(), {"n_in", "s_out"});
  EXPECT_THAT(message, HasSubstr("crossing.net.xml:137: edge 'n_in': param 'turn_signal_distance' is not a number: 'far'"));
}

TEST(RouteBuilderParams, StopOffset) {
  // e_in: edge stopOffset 3 m, lane 1 overrides with 1 m.
  const RoutePlan left = build_route(crossing(), {"e_in", "s_out"});
  EXPECT_EQ(left.map.at(0).lane_id, "e_in_1");
  EXPECT_DOUBLE_EQ(left.map.at(0).stop_offset, 1.0);
  EXPECT_DOUBLE_EQ(left.map.at(1).stop_offset, 0.0);
  const RoutePlan right = build_route(crossing(), {"e_in", "n_out"});
  EXPECT_EQ(right.map.at(0).lane_id, "e_in_0");
  EXPECT_DOUBLE_EQ(right.map.at(0).stop_offset, 3.0);
  EXPECT_DOUBLE_EQ(build_route(crossing(), {"s_in", "w_out"}).map.at(0).stop_offset, 2.5);
}

// ---- lane plan ------------------------------------------------------------------------------------

TEST(RouteBuilderLanePlan, LeftTurnAfterFeederNeedsOneLaneChange) {
  // w_far reaches only w_in_0 (crossing.con.xml); the left turn to n_out leaves from w_in_1.
  const RoutePlan plan = build_route(crossing(), {"w_far", "w_in", "n_out"});
  // Planned lanes (the lanelets): the ones with the connection onward; the ego enters w_in on lane 0.
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(0, 1, 1));
  EXPECT_THAT(plan.entry_lane_per_edge, ElementsAre(0, 0, 1));
  EXPECT_EQ(plan.lane_changes, 1);
  // The turn lanelets are those of the connection from the lane after the change.
  EXPECT_THAT(lane_ids(plan), ElementsAre("w_far_0", ":W_1_0", "w_in_1", ":C_18_0", ":C_26_0", "n_out_1"));
  expect_contiguous(crossing(), plan);
  ASSERT_TRUE(plan.map.at(2).traffic_light.has_value());
  EXPECT_EQ(plan.map.at(2).traffic_light->link_index, 18);
  EXPECT_EQ(plan.map.at(3).turn_direction, TurnDirection::Left);
  EXPECT_EQ(plan.map.at(4).turn_direction, TurnDirection::Left);
}

TEST(RouteBuilderLanePlan, StraightAfterFeederKeepsTheRightLane) {
  const RoutePlan plan = build_route(crossing(), {"w_far", "w_in", "e_out"});
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(0, 0, 0));
  EXPECT_EQ(plan.lane_changes, 0);
  EXPECT_THAT(lane_ids(plan), ElementsAre("w_far_0", ":W_1_0", "w_in_0", ":C_16_0", "e_out_0"));
}

TEST(RouteBuilderLanePlan, RequestedLaneChangeLeavesTheEdgeOnTheRequestedLane) {
  // Straight w_far -> w_in -> e_out keeps lane 0; a lane change requested on w_in to lane 1 makes the
  // ego enter w_in on lane 0 and leave it on lane 1 (the straight connection from w_in_1).
  const RoutePlan plan = build_route(crossing(), {"w_far", "w_in", "e_out"}, {-1, 1, -1});
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(0, 1, 1));
  EXPECT_THAT(plan.entry_lane_per_edge, ElementsAre(0, 0, 1));
  EXPECT_EQ(plan.lane_changes, 1);
  // On the last edge: entered on another lane, ends on the requested one.
  const RoutePlan last = build_route(crossing(), {"w_far", "w_in", "e_out"}, {-1, -1, 1});
  EXPECT_THAT(last.lane_per_edge, ElementsAre(0, 0, 1));
  EXPECT_THAT(last.entry_lane_per_edge, ElementsAre(0, 0, 0));
}

TEST(RouteBuilderLanePlan, TiesTakeTheRightmostLane) {
  const RoutePlan plan = build_route(crossing(), {"n_out"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("n_out_0"));
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(0));
  EXPECT_FALSE(plan.map.at(0).traffic_light.has_value());
}

TEST(RouteBuilderLanePlan, WideningEdgeFollowsTheOnlyConnection) {
  // line: ab (1 lane) -> bc (2 lanes), netconvert connects ab_0 to bc_1 only.
  const NetIndex net = NetIndex::load(net_path("line.net.xml"));
  const RoutePlan plan = build_route(net, {"ab", "bc"});
  EXPECT_THAT(plan.lane_per_edge, ElementsAre(0, 1));
  EXPECT_EQ(plan.lane_changes, 0);
}

// ---- U-turns and hand -----------------------------------------------------------------------------

TEST(RouteBuilderHand, UTurnIsRightInLeftHandNet) {
  const NetIndex net = NetIndex::load(net_path("line_lefthand.net.xml"));
  const RoutePlan plan = build_route(net, {"ab", "bc", "cb"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("ab_0", ":B_1_0", "bc_1", ":C_0_0", "cb_0"));
  EXPECT_EQ(plan.map.at(1).turn_direction, TurnDirection::Straight);
  EXPECT_EQ(plan.map.at(3).turn_direction, TurnDirection::Right);  // dir="T"
  EXPECT_THAT(plan.map.at(2).successor_turn_directions, ElementsAre(TurnDirection::Right));
}

TEST(RouteBuilderHand, SameUTurnIsLeftInRightHandNet) {
  const NetIndex net = NetIndex::load(net_path("line.net.xml"));
  const RoutePlan plan = build_route(net, {"ab", "bc", "cb"});
  EXPECT_EQ(plan.map.at(3).lane_id, ":C_0_0");
  EXPECT_EQ(plan.map.at(3).turn_direction, TurnDirection::Left);  // dir="t"
}

// ---- roundabout -----------------------------------------------------------------------------------

TEST(RouteBuilderRoundabout, EntryInternalExit) {
  const RoutePlan plan = build_route(roundabout(), {"in0", "r01", "r12", "out2"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("in0_0", ":R0_0_0", "r01_0", ":R1_2_0", "r12_0", ":R2_0_0", "out2_0"));
  expect_contiguous(roundabout(), plan);
  const std::vector<RoundaboutRole> roles{RoundaboutRole::None,     RoundaboutRole::Entry,    RoundaboutRole::Internal,
                                          RoundaboutRole::Internal, RoundaboutRole::Internal, RoundaboutRole::Exit,
                                          RoundaboutRole::None};
  for (std::size_t i = 0; i < roles.size(); ++i) {
    EXPECT_EQ(plan.map.at(i).roundabout_role, roles[i]) << plan.map.at(i).lane_id;
    EXPECT_EQ(plan.map.at(i).roundabout_id, roles[i] == RoundaboutRole::None ? "" : "0") << plan.map.at(i).lane_id;
  }
  // dir is "r" on the entry and exit and "s" around the ring: roles never come from dir.
  EXPECT_EQ(plan.map.at(1).turn_direction, TurnDirection::Right);
  EXPECT_EQ(plan.map.at(3).turn_direction, TurnDirection::Straight);
  EXPECT_EQ(plan.map.at(5).turn_direction, TurnDirection::Right);
  EXPECT_EQ(plan.map.at(1).junction_id, "R0");
}

TEST(RouteBuilderRoundabout, ParamsOfApproachAndRingLanes) {
  const RoutePlan plan = build_route(roundabout(), {"in0", "r01", "out1"});
  EXPECT_THAT(lane_ids(plan), ElementsAre("in0_0", ":R0_0_0", "r01_0", ":R1_1_0", "out1_0"));
  // The edge param of in0 reaches the entry lanelet; the ring lane's param reaches the exit lanelet.
  ASSERT_TRUE(plan.map.at(1).turn_signal_distance.has_value());
  EXPECT_DOUBLE_EQ(*plan.map.at(1).turn_signal_distance, 20.0);
  EXPECT_EQ(plan.map.at(2).params.at("ring"), "yes");
  EXPECT_EQ(plan.map.at(3).params.at("ring"), "yes");
  EXPECT_EQ(plan.map.at(3).roundabout_role, RoundaboutRole::Exit);
  EXPECT_FALSE(plan.map.at(4).turn_signal_distance.has_value());
}

// ---- errors ---------------------------------------------------------------------------------------

TEST(RouteBuilderErrors, UnknownEdge) {
  const std::string message = route_error(crossing(), {"s_in", "nope"});
  EXPECT_THAT(message, HasSubstr("route edge 'nope' is not in the net"));
}

TEST(RouteBuilderErrors, InternalEdge) {
  EXPECT_THAT(route_error(crossing(), {"s_in", ":C_11", "n_out"}), HasSubstr("route edge ':C_11' is an internal"));
}

TEST(RouteBuilderErrors, UnconnectedEdges) {
  const std::string message = route_error(crossing(), {"w_far", "n_out"});
  EXPECT_THAT(message, HasSubstr("route edges 'w_far' -> 'n_out' are not connected"));
}

TEST(RouteBuilderErrors, NetWithoutInternalLanes) {
  const NetIndex net = NetIndex::load(net_path("line_nointernal.net.xml"));
  const std::string message = route_error(net, {"ab", "bc"});
  EXPECT_THAT(message, HasSubstr("'ab' -> 'bc'"));
  EXPECT_THAT(message, HasSubstr("the net has no internal lanes"));
}

TEST(RouteBuilderErrors, EmptyRoute) { EXPECT_THAT(route_error(crossing(), {}), HasSubstr("no edges")); }

}  // namespace
}  // namespace signalsim::sumo
