// FleetTracker on sumo_nets/cross without SUMO: the selection, the decisions and masks of a vehicle
// driving its own route (values as SUMO would report them), re-routes, arrivals and the record.
#include "fleet/fleet_tracker.hpp"

#include <gtest/gtest.h>

namespace signalsim {
namespace {

using State = sumo::SumoSession::TrafficState;
using Vehicle = sumo::SumoSession::TrafficVehicle;

const sumo::NetIndex& cross_net() {
  static const sumo::NetIndex net = sumo::NetIndex::load(std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/cross/cross.net.xml");
  return net;
}

FleetTracker tracker(const FleetSpec& spec = {}) {
  return FleetTracker(spec, TurnSignalParameters{}, "de", cross_net(), "ego", 0.1);
}

const Vehicle kCar{"car", "passenger", 4.5};

TEST(FleetTracker, SelectsByVtypeVclassAndIdPatternAndNeverTheEgo) {
  FleetSpec spec;
  spec.vclass = "passenger";
  spec.id_pattern = "N_.*";
  FleetTracker t = tracker(spec);
  EXPECT_FALSE(t.depart("ego", kCar));
  EXPECT_FALSE(t.depart("E_left.0", kCar));  // id
  EXPECT_FALSE(t.depart("N_van.0", Vehicle{"van", "delivery", 6.0}));  // class
  EXPECT_TRUE(t.depart("N_left.0", kCar));
  EXPECT_FALSE(t.depart("N_left.0", kCar));  // already followed
  EXPECT_EQ(t.followed(), std::vector<std::string>{"N_left.0"});
  const FleetRecord r = t.finish();
  EXPECT_EQ(r.totals.vehicles_seen, 3);
  EXPECT_EQ(r.totals.vehicles_selected, 1);
}

TEST(FleetTracker, ALeftTurnerSignalsLeftWithinReachAndTheMaskKeepsTheBrakeLight) {
  FleetTracker t = tracker();
  ASSERT_TRUE(t.depart("N_left.0", kCar));
  t.follow_route(0, "r1", {"in_N", "out_E"});
  std::vector<int> masks;
  t.step(1.0, {State{"r1", "in_N_1", 100.0, 13.89, 0}}, masks);  // 89.6 m to the turn: beyond 71.67
  EXPECT_EQ(masks, std::vector<int>{0});
  t.step(2.0, {State{"r1", "in_N_1", 120.0, 13.89, 0}}, masks);
  EXPECT_EQ(masks, std::vector<int>{sumo::kBlinkerLeft});
  t.step(3.0, {State{"r1", "in_N_1", 130.0, 12.0, 0}}, masks);  // slowing: brake light too
  EXPECT_EQ(masks, std::vector<int>{sumo::kBlinkerLeft | sumo::kBrakeLight});
  t.step(4.0, {State{"r1", "out_E_1", 30.0, 12.0, 0}}, masks);  // past the junction
  EXPECT_EQ(masks, std::vector<int>{0});
  const FleetRecord r = t.finish();
  ASSERT_EQ(r.events.size(), 2u);
  EXPECT_EQ(r.events[0].blinker, Blinker::Left);
  EXPECT_EQ(r.events[0].place, "C");
  EXPECT_EQ(r.events[0].source, "intersection");
  EXPECT_DOUBLE_EQ(r.events[0].s_front, 120.0);
  EXPECT_EQ(r.events[1].blinker, Blinker::None);
  EXPECT_NEAR(r.places.at("C").lead_sum, 189.60 - 120.0, 0.01);
  EXPECT_EQ(r.totals.vehicles_signalled, 1);
}

TEST(FleetTracker, ARerouteFollowsTheNewRouteAndAnUnknownRouteIsLeftToSumo) {
  FleetTracker t = tracker();
  ASSERT_TRUE(t.depart("v", kCar));
  t.follow_route(0, "straight", {"in_N", "out_S"});
  std::vector<int> masks;
  t.step(1.0, {State{"straight", "in_N_0", 120.0, 13.89, 0}}, masks);
  EXPECT_EQ(masks, std::vector<int>{0});
  EXPECT_TRUE(t.route_changed(0, "!v!var#1"));
  t.follow_route(0, "!v!var#1", {"in_N", "out_W"});  // now a right turn
  t.step(1.1, {State{"!v!var#1", "in_N_0", 121.4, 13.89, 0}}, masks);
  EXPECT_EQ(masks, std::vector<int>{sumo::kBlinkerRight});
  t.follow_route(0, "!v!var#2", {"in_N", "in_S"});  // not connected
  t.step(1.2, {State{"!v!var#2", "in_N_0", 122.8, 13.89, 0}}, masks);
  EXPECT_EQ(masks, std::vector<int>{-1});  // SUMO's own blinker
  t.arrive("v");
  EXPECT_TRUE(t.followed().empty());
  const FleetRecord r = t.finish();
  EXPECT_EQ(r.totals.rerouted, 2);
  EXPECT_EQ(r.totals.left_to_sumo, 1);
  ASSERT_EQ(r.left_examples.size(), 1u);
  EXPECT_EQ(r.left_examples[0].first, "v");
}

}  // namespace
}  // namespace signalsim
