// FleetRoutes on sumo_nets/cross: one route per vClass and edge list, shared; its signal stretches;
// a route that cannot be built is remembered with its reason.
#include "fleet/fleet_routes.hpp"

#include <gtest/gtest.h>

namespace signalsim {
namespace {

const sumo::NetIndex& cross() {
  static const sumo::NetIndex net = sumo::NetIndex::load(std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/cross/cross.net.xml");
  return net;
}

TEST(FleetRoutes, OneRoutePerVclassAndEdgesIsBuiltOnceAndShared) {
  FleetRoutes routes(cross(), TurnSignalParameters{});
  const auto a = routes.route({"in_N", "out_E"}, "passenger");
  const auto b = routes.route({"in_N", "out_E"}, "passenger");
  EXPECT_EQ(a.get(), b.get());
  EXPECT_NE(routes.route({"in_N", "out_E"}, "delivery").get(), a.get());  // another class may use other lanes
  EXPECT_EQ(routes.distinct(), 2);
  EXPECT_TRUE(a->understood());
}

TEST(FleetRoutes, ATurnIsOneSignalStretchAndAStraightRouteHasNone) {
  FleetRoutes routes(cross(), TurnSignalParameters{});
  const auto left = routes.route({"in_N", "out_E"}, "passenger");
  ASSERT_EQ(left->stretches.size(), 1u);
  // the turn's internal lanes: from the end of in_N (189.60 m) to the start of out_E
  EXPECT_NEAR(left->stretches[0].start, 189.60, 0.01);
  EXPECT_EQ(left->stretches[0].end, left->map.at(left->map.size() - 1).s_start);
  EXPECT_TRUE(routes.route({"in_N", "out_S"}, "passenger")->stretches.empty());
}

TEST(FleetRoutes, QuietOnlyWhileEveryStretchIsPassedOrBeyondReach) {
  FleetRoutes routes(cross(), TurnSignalParameters{});
  const auto left = routes.route({"in_N", "out_E"}, "passenger");
  const double reach = 3.0 * 13.89 + 30.0;  // 71.67 m
  EXPECT_TRUE(left->quiet_at(100.0, 96.3, reach));    // 89.6 m to the turn, 1 m margin
  EXPECT_FALSE(left->quiet_at(118.0, 114.3, reach));  // within reach
  EXPECT_FALSE(left->quiet_at(200.0, 196.3, reach));  // on the turn
  const double end = left->stretches[0].end;
  EXPECT_FALSE(left->quiet_at(end + 3.7, end + 0.5, reach));  // base_link not 1 m past it yet
  EXPECT_TRUE(left->quiet_at(end + 5.0, end + 1.3, reach));
}

TEST(FleetRoutes, ARouteThatCannotBeBuiltIsRememberedWithItsReason) {
  FleetRoutes routes(cross(), TurnSignalParameters{});
  const auto broken = routes.route({"in_N", "in_S"}, "passenger");  // not connected
  EXPECT_FALSE(broken->understood());
  EXPECT_NE(broken->error.find("in_N"), std::string::npos) << broken->error;
  EXPECT_EQ(routes.route({"in_N", "in_S"}, "passenger").get(), broken.get());
  EXPECT_EQ(routes.not_understood(), 1);
  EXPECT_FALSE(routes.route({}, "passenger")->understood());
}

}  // namespace
}  // namespace signalsim
