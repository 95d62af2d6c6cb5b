// The route locator (map/route_locator): where SUMO's (lane, edge, lane position) puts the front on
// the route, step after step, for both drivers. A synthetic route, no SUMO: a_0 | junction J with two
// chained internal lanes :J_0_0 (5 m) and :J_1_0 (10 m) | b_0.
#include <gtest/gtest.h>

#include <string>

#include "map/route_locator.hpp"

namespace signalsim {
namespace {

RouteMap junction_route() {
  const auto lanelet = [](const std::string& lane, const std::string& junction, double s, double length) {
    Lanelet l;
    l.lane_id = lane;
    l.edge_id = lane.substr(0, lane.rfind('_'));
    l.junction_id = junction;
    l.is_internal = !junction.empty();
    l.s_start = s;
    l.length = length;
    return l;
  };
  return RouteMap({lanelet("a_0", "", 0, 100), lanelet(":J_0_0", "J", 100, 5), lanelet(":J_1_0", "J", 105, 10),
                   lanelet("b_0", "", 115, 50)});
}

TEST(RouteLocator, APlannedLaneGivesItsRouteS) {
  const RouteMap route = junction_route();
  RouteLocator locator(route, 0.0);
  const RouteLocator::Place p = locator.locate("a_0", "a", 40.0);
  EXPECT_TRUE(p.on_plan);
  EXPECT_TRUE(p.on_route);
  EXPECT_DOUBLE_EQ(p.s_front, 40.0);
  EXPECT_EQ(p.index, 0u);
  const RouteLocator::Place inside = locator.locate(":J_1_0", ":J_1", 2.0);
  EXPECT_TRUE(inside.on_plan);
  EXPECT_DOUBLE_EQ(inside.s_front, 107.0);
  EXPECT_EQ(inside.index, 2u);
}

TEST(RouteLocator, AnotherLaneOfARouteEdgeIsOnTheRouteButOffThePlan) {
  const RouteMap route = junction_route();
  RouteLocator locator(route, 0.0);
  locator.locate("b_0", "b", 15.0);
  const RouteLocator::Place other = locator.locate("b_1", "b", 20.0);
  EXPECT_TRUE(other.on_route);
  EXPECT_FALSE(other.on_plan);
  EXPECT_DOUBLE_EQ(other.s_front, 135.0);  // b's route lanelet + the lane position
  EXPECT_EQ(other.index, 3u);
}

TEST(RouteLocator, OffTheRouteTheLastPositionIsHeld) {
  const RouteMap route = junction_route();
  RouteLocator locator(route, 12.0);
  RouteLocator::Place p = locator.locate("c_0", "c", 5.0);
  EXPECT_FALSE(p.on_route);
  EXPECT_DOUBLE_EQ(p.s_front, 12.0);  // the departure position: nothing located yet
  locator.locate("a_0", "a", 60.0);
  p = locator.locate("c_0", "c", 5.0);
  EXPECT_FALSE(p.on_route);
  EXPECT_DOUBLE_EQ(p.s_front, 60.0);
}

// Another connection of J (:J_5_0, 20 m long): placed from J's route lanelet the front is on (or the
// junction's first one ahead) plus the lane position, at most that lanelet's end, never behind the
// previous step's s.
TEST(RouteLocator, AnotherConnectionNeverGoesBackNorPastTheJunction) {
  const RouteMap route = junction_route();
  RouteLocator locator(route, 0.0);
  locator.locate("a_0", "a", 99.0);
  RouteLocator::Place p = locator.locate(":J_5_0", ":J_5", 3.0);
  EXPECT_TRUE(p.on_route);
  EXPECT_FALSE(p.on_plan);
  EXPECT_DOUBLE_EQ(p.s_front, 103.0);
  p = locator.locate(":J_5_0", ":J_5", 1.0);  // behind the last s: held there
  EXPECT_DOUBLE_EQ(p.s_front, 103.0);
  p = locator.locate(":J_5_0", ":J_5", 8.0);  // 108 lies beyond :J_0_0's end: at most 105
  EXPECT_DOUBLE_EQ(p.s_front, 105.0);
  p = locator.locate(":J_1_0", ":J_1", 7.0);  // back on the plan
  EXPECT_DOUBLE_EQ(p.s_front, 112.0);
  p = locator.locate(":J_5_0", ":J_5", 4.0);  // J's lanelet the front is on gives 109 < 112: held
  EXPECT_DOUBLE_EQ(p.s_front, 112.0);
  p = locator.locate(":J_5_0", ":J_5", 19.0);  // never past the junction, which ends at 115
  EXPECT_DOUBLE_EQ(p.s_front, 115.0);
  EXPECT_LE(p.s_front, route.at(2).s_end());
}


// Step after step on one lanelet the front is placed from that lanelet (its lane position capped at
// its length), and a lane the route drives twice is placed at its next visit, not its first.
TEST(RouteLocator, StepsOnOneLaneletAndALaneDrivenTwiceArePlacedOnTheLaneletReached) {
  const auto lanelet = [](const std::string& lane, double s, double length) {
    Lanelet l;
    l.lane_id = lane;
    l.edge_id = lane.substr(0, lane.rfind('_'));
    l.s_start = s;
    l.length = length;
    return l;
  };
  const RouteMap loop({lanelet("a_0", 0, 100), lanelet("b_0", 100, 50), lanelet("a_0", 150, 100)});
  RouteLocator locator(loop, 0.0);
  EXPECT_DOUBLE_EQ(locator.locate("a_0", "a", 10.0).s_front, 10.0);
  EXPECT_DOUBLE_EQ(locator.locate("a_0", "a", 20.0).s_front, 20.0);
  EXPECT_DOUBLE_EQ(locator.locate("a_0", "a", 120.0).s_front, 100.0);  // capped at the lanelet's end
  EXPECT_EQ(locator.locate("b_0", "b", 49.0).index, 1u);
  const RouteLocator::Place again = locator.locate("a_0", "a", 5.0);
  EXPECT_DOUBLE_EQ(again.s_front, 155.0);
  EXPECT_EQ(again.index, 2u);
  EXPECT_DOUBLE_EQ(locator.locate("a_0", "a", 6.0).s_front, 156.0);
}

// index_at with a hint answers as without one, on a boundary (the later lanelet), before the route,
// past its end and with a hint that is wrong.
TEST(RouteMap, IndexAtWithAHintAnswersAsWithout) {
  const RouteMap route = junction_route();
  for (const double s : {-1.0, 0.0, 50.0, 99.999, 100.0, 104.0, 105.0, 114.0, 115.0, 165.0, 500.0})
    for (std::size_t hint = 0; hint < 6; ++hint) EXPECT_EQ(route.index_at(s, hint), route.index_at(s)) << s << ' ' << hint;
}

}  // namespace
}  // namespace signalsim
