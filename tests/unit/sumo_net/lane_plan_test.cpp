// The lane plan: fewest lane changes, rightmost on ties, never a lane the ego may not use.
#include <gtest/gtest.h>

#include "sumo/lane_plan.hpp"

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

}  // namespace
}  // namespace signalsim::sumo
