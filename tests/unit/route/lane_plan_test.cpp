// The lane plan: every lane change fits its edge, then the fewest lane changes, then the most room
// for the tightest one, then the rightmost; never on or across a lane the ego may not use.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "route/lane_plan.hpp"

namespace signalsim::sumo {
namespace {

NetConnection link(int from, int to) {
  NetConnection c;
  c.from_lane = from;
  c.to_lane = to;
  return c;
}

TEST(PassengerAllowed, FollowsAllowThenDisallow) {
  EXPECT_TRUE(passenger_allowed("", ""));
  EXPECT_TRUE(passenger_allowed("passenger bus", ""));
  EXPECT_TRUE(passenger_allowed("all", ""));
  EXPECT_FALSE(passenger_allowed("pedestrian", ""));
  EXPECT_FALSE(passenger_allowed("", "passenger truck"));
  EXPECT_FALSE(passenger_allowed("", "all"));
  EXPECT_TRUE(passenger_allowed("", "pedestrian bicycle"));
}

TEST(LanePlan, PrefersTheRightmostLaneOnATie) {
  const NetConnection a = link(0, 0), b = link(1, 1);
  const LanePlan plan = plan_lanes({{true, true}, {true, true}}, {{&a, &b}});
  ASSERT_EQ(plan.lanes.size(), 2u);
  EXPECT_EQ(plan.lanes[0], 0);
  EXPECT_EQ(plan.lane_changes, 0);
}

TEST(LanePlan, RequiredExitForcesALaneChangeOnThatEdge) {
  // Two 2-lane edges, straight connections 0->0 and 1->1; a lane change asked on the second edge to
  // lane 1: it is entered on lane 0 (never on the requested lane) and left on lane 1.
  const NetConnection a = link(0, 0), b = link(1, 1);
  const LanePlan plan = plan_lanes({{true, true}, {true, true}}, {{&a, &b}}, {-1, 1});
  ASSERT_EQ(plan.lanes.size(), 2u);
  EXPECT_EQ(plan.lanes[1], 0);
  EXPECT_EQ(plan.exit_lanes[1], 1);
  EXPECT_EQ(plan.exit_lanes[0], 0);
  EXPECT_EQ(plan.lane_changes, 1);
  // On the first edge: the exit lane is the required one, the connection leaves from it.
  const LanePlan first = plan_lanes({{true, true}, {true, true}}, {{&a, &b}}, {1, -1});
  ASSERT_EQ(first.lanes.size(), 2u);
  EXPECT_EQ(first.lanes[0], 0);
  EXPECT_EQ(first.exit_lanes[0], 1);
  EXPECT_EQ(first.links[0], &b);
  // Impossible: the only lane cannot be entered on another lane.
  EXPECT_TRUE(plan_lanes({{true}, {true}}, {{&a}}, {-1, 0}).lanes.empty());
}

TEST(LanePlan, NeverPlansALaneThePassengerCarMayNotUse) {
  // Lane 0 of both edges is a sidewalk, connected to the next sidewalk (nets without walking areas).
  const NetConnection walk = link(0, 0), drive = link(1, 1);
  const LanePlan plan = plan_lanes({{false, true}, {false, true}}, {{&walk, &drive}});
  ASSERT_EQ(plan.lanes.size(), 2u);
  EXPECT_EQ(plan.lanes[0], 1);
  EXPECT_EQ(plan.lanes[1], 1);
}

TEST(LanePlan, SingleEdgeRouteSkipsASidewalk) {
  const LanePlan plan = plan_lanes({{false, true, true}}, {});
  ASSERT_EQ(plan.lanes.size(), 1u);
  EXPECT_EQ(plan.lanes[0], 1);
}

TEST(LanePlan, CountsTheLaneChangesAConnectionNeeds) {
  // Only lane 1 turns onto the next edge: starting on lane 0 would need one change, so plan lane 1.
  const NetConnection turn = link(1, 0);
  const LanePlan plan = plan_lanes({{true, true}, {true}}, {{&turn}});
  ASSERT_EQ(plan.lanes.size(), 2u);
  EXPECT_EQ(plan.lanes[0], 1);
  EXPECT_EQ(plan.lane_changes, 0);
}

TEST(LanePlan, EmptyWhenOnlyForbiddenLanesConnect) {
  const NetConnection walk = link(0, 0);
  const LanePlan plan = plan_lanes({{false, true}, {false, true}}, {{&walk}});
  EXPECT_TRUE(plan.lanes.empty());
}

// ---- room: the tie-break between lane sequences by the room each lane change has -----------------

/// Edges of `lanes` lanes 3.2 m wide with this room, at 13.89 m/s.
std::vector<EdgeRoom> rooms(const std::vector<std::pair<int, double>>& lanes_and_room) {
  std::vector<EdgeRoom> out;
  for (const auto& [lanes, room] : lanes_and_room) out.push_back({room, std::vector<double>(lanes, 3.2), 13.89});
  return out;
}

// The shape of bologna_acosta's 201c -> 204a[0] -> 204b[0] -> 204[1][0] (0.54 m) -> 125: a one-lane
// feeder, a long two-lane edge, a short two-lane edge whose lane 1 alone leads on. One lane change
// either way; "rightmost on ties" put it on the short edge, where it does not fit.
struct ShortEdgeAhead {
  NetConnection feed = link(0, 0), stay0 = link(0, 0), stay1 = link(1, 1), on = link(1, 0);
  std::vector<std::vector<bool>> usable{{true}, {true, true}, {true, true}, {true}};
  std::vector<std::vector<const NetConnection*>> links{{&feed}, {&stay0, &stay1}, {&on}};
};

TEST(LanePlanRoom, ALaneChangeGoesWhereItFitsNotOnTheShortEdge) {
  const ShortEdgeAhead net;
  // Without rooms: the rightmost plan, the change on edge 2.
  const LanePlan rightmost = plan_lanes(net.usable, net.links);
  EXPECT_THAT(rightmost.lanes, ::testing::ElementsAre(0, 0, 0, 0));
  EXPECT_THAT(rightmost.exit_lanes, ::testing::ElementsAre(0, 0, 1, 0));
  // Edge 1 has 186.6 m of room, edge 2 0.54 - 3.7 m: the change goes on edge 1.
  const LanePlan plan = plan_lanes(net.usable, net.links, {}, rooms({{1, 100}, {2, 186.6}, {2, -3.16}, {1, 100}}));
  EXPECT_THAT(plan.lanes, ::testing::ElementsAre(0, 0, 1, 0));
  EXPECT_THAT(plan.exit_lanes, ::testing::ElementsAre(0, 1, 1, 0));
  EXPECT_EQ(plan.lane_changes, 1);
  EXPECT_EQ(plan.unfit, 0);
  EXPECT_DOUBLE_EQ(plan.tightest_room, 186.6);
}

TEST(LanePlanRoom, BothFitTheOneWithMoreRoomWinsEqualRoomKeepsTheRightmost) {
  const ShortEdgeAhead net;
  EXPECT_THAT(plan_lanes(net.usable, net.links, {}, rooms({{1, 1}, {2, 60}, {2, 100}, {1, 1}})).exit_lanes,
              ::testing::ElementsAre(0, 0, 1, 0));
  EXPECT_THAT(plan_lanes(net.usable, net.links, {}, rooms({{1, 1}, {2, 100}, {2, 60}, {1, 1}})).exit_lanes,
              ::testing::ElementsAre(0, 1, 1, 0));
  EXPECT_THAT(plan_lanes(net.usable, net.links, {}, rooms({{1, 1}, {2, 80}, {2, 80}, {1, 1}})).exit_lanes,
              ::testing::ElementsAre(0, 0, 1, 0));
}

TEST(LanePlanRoom, NothingFitsTheTightestRoomIsStillTheMost) {
  const ShortEdgeAhead net;
  const LanePlan plan = plan_lanes(net.usable, net.links, {}, rooms({{1, 1}, {2, 9.0}, {2, -3.16}, {1, 1}}));
  EXPECT_THAT(plan.exit_lanes, ::testing::ElementsAre(0, 1, 1, 0));
  EXPECT_EQ(plan.unfit, 1);
}

TEST(LanePlanRoom, AFittingPlanBeatsFewerLaneChangesThatDoNotFit) {
  // Edge 1 (3 lanes, long): lane 0 -> edge 2 lane 0, lane 2 -> edge 2 lane 1; edge 2 (2 lanes, short)
  // leads on from lane 1 only. One change on edge 2 (does not fit) or two on edge 1 (fit).
  const NetConnection feed = link(0, 0), low = link(0, 0), high = link(2, 1), on = link(1, 0);
  const LanePlan plan = plan_lanes({{true}, {true, true, true}, {true, true}, {true}}, {{&feed}, {&low, &high}, {&on}},
                                   {}, rooms({{1, 1}, {3, 200}, {2, -3.0}, {1, 1}}));
  EXPECT_THAT(plan.exit_lanes, ::testing::ElementsAre(0, 2, 1, 0));
  EXPECT_EQ(plan.lane_changes, 2);
  EXPECT_EQ(plan.unfit, 0);
}

// ---- lanes the ego may not use (its vClass) -------------------------------------------------------

TEST(LanePlanForbidden, NeverCrossesABusLaneAnotherSequenceIsTaken) {
  // Edge 1 (3 lanes) and edge 2 (3 lanes, lane 1 a bus lane); only lane 2 of edge 2 leads on. The
  // rightmost plan changed 0 -> 2 on edge 2, across the bus lane; the change is made on edge 1.
  const NetConnection feed = link(0, 0), s0 = link(0, 0), s1 = link(1, 1), s2 = link(2, 2), on = link(2, 0);
  const LanePlan plan = plan_lanes({{true}, {true, true, true}, {true, false, true}, {true}},
                                   {{&feed}, {&s0, &s1, &s2}, {&on}});
  EXPECT_THAT(plan.lanes, ::testing::ElementsAre(0, 0, 2, 0));
  EXPECT_THAT(plan.exit_lanes, ::testing::ElementsAre(0, 2, 2, 0));
}

TEST(LanePlanForbidden, NoOtherSequenceNoPlanUnlessCrossingIsAllowedToDiagnose) {
  // bologna_acosta 165 -> 31 -> 113: 31_1 is a bus lane, the turn onto 113 leaves from 31_2.
  const NetConnection r0 = link(0, 0), r1 = link(0, 1), left = link(2, 2);
  const std::vector<std::vector<bool>> usable{{true}, {true, false, true}, {true, true, true}};
  const std::vector<std::vector<const NetConnection*>> links{{&r0, &r1}, {&left}};
  EXPECT_TRUE(plan_lanes(usable, links).lanes.empty());
  const LanePlan crossing = plan_lanes(usable, links, {}, {}, {}, true);
  EXPECT_THAT(crossing.lanes, ::testing::ElementsAre(0, 0, 2));
  EXPECT_THAT(crossing.exit_lanes, ::testing::ElementsAre(0, 2, 2));
}

}  // namespace
}  // namespace signalsim::sumo
