// generate's glue on real nets (reads the .net.xml, no simulation): the walk graph of a net, the
// facts of a planned route, and the `arrives` expectation it adds to the scenario schema.
#include <filesystem>
#include <fstream>
#include <set>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "generate/net_graph.hpp"
#include "generate/route_facts.hpp"
#include "report/expectations.hpp"
#include "scenario/input_error.hpp"
#include "step/route_planning.hpp"
#include "net/net_index.hpp"

namespace signalsim::generate {
namespace {

const std::string kNets = std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/";

std::size_t index_of(const RouteGraph& g, const std::string& id) {
  for (std::size_t i = 0; i < g.edges().size(); ++i)
    if (g.edges()[i].id == id) return i;
  ADD_FAILURE() << "no edge " << id;
  return 0;
}

TEST(NetGraph, CrossingArmsLeadToTheThreeOtherArmsNeverBack) {
  const auto net = sumo::NetIndex::load(kNets + "cross/cross.net.xml");
  const RouteGraph g = graph_of_net(net);
  EXPECT_EQ(g.edges().size(), 8u);
  EXPECT_EQ(g.starts().size(), 4u);
  for (const std::string arm : {"N", "E", "S", "W"}) {
    std::set<std::string> to;
    for (const GraphLink& l : g.successors(index_of(g, "in_" + arm))) to.insert(g.edges()[l.to].id);
    std::set<std::string> expected;
    for (const std::string other : {"N", "E", "S", "W"})
      if (other != arm) expected.insert("out_" + other);
    EXPECT_EQ(to, expected) << "in_" << arm;
  }
  EXPECT_TRUE(g.successors(index_of(g, "out_N")).empty());  // a dead end: the net ends there
}

TEST(NetGraph, RealNetKeepsOnlyWhatAPassengerCarMayDrive) {
  const auto net = sumo::NetIndex::load(kNets + "bologna_acosta/acosta_buslanes.net.xml");
  const RouteGraph g = graph_of_net(net);
  ASSERT_GT(g.starts().size(), 50u);
  for (std::size_t i = 0; i < g.edges().size(); ++i) {
    const sumo::NetEdge* e = net.edge(g.edges()[i].id);
    ASSERT_NE(e, nullptr);
    EXPECT_FALSE(e->is_internal);
    EXPECT_TRUE(std::any_of(e->lanes.begin(), e->lanes.end(), [](const sumo::NetLane& l) { return l.allows_passenger; }))
        << e->id;
  }
  // Sorted by id: the walk does not depend on the file's order.
  EXPECT_TRUE(std::is_sorted(g.edges().begin(), g.edges().end(),
                             [](const GraphEdge& a, const GraphEdge& b) { return a.id < b.id; }));
}

Scenario scenario_for(const std::string& net, std::vector<std::string> route) {
  Scenario s;
  s.path = "test.yaml";
  s.net = net;
  s.ego.route = std::move(route);
  return s;
}

TEST(RouteFacts, ALeftTurnAtALightYieldsInsideTheJunction) {
  const std::string path = kNets + "cross/cross.net.xml";
  const auto net = sumo::NetIndex::load(path);
  const Scenario s = scenario_for(path, {"in_S", "out_W"});
  const sumo::RoutePlan plan = plan_route(s, net);
  const PlannedRouteFacts f = route_facts(plan, plan_lateral(s, plan, net), net);
  ASSERT_EQ(f.lights.size(), 1u);
  EXPECT_EQ(f.lights[0].id, "C");
  EXPECT_NEAR(f.lights[0].stop_line, 189.6, 0.05);
  ASSERT_EQ(f.light_cycles.size(), 1u);
  EXPECT_DOUBLE_EQ(f.light_cycles[0], 70.0);  // 30 + 3 + 2 + 30 + 3 + 2
  // The light's stop line, then the permissive left turn's wait inside C (link state m).
  ASSERT_EQ(f.stops.size(), 2u);
  EXPECT_TRUE(f.stops[0].light);
  EXPECT_FALSE(f.stops[1].light);
  EXPECT_NEAR(f.stops[1].s, 194.61, 0.05);
  EXPECT_THAT(f.stops[1].what, testing::HasSubstr("junction C"));
  EXPECT_TRUE(f.lane_changes.empty());
}

TEST(RouteFacts, ALightWhoseRunningProgramNeverLetsTheLinkGoIsAFact) {
  // cross.net.xml with a second program for C after the first: SUMO runs the one loaded last. Red
  // for every link in it: the route's link never goes (SUMO's bs3d game net has such lights).
  std::ifstream in(kNets + "cross/cross.net.xml");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string end_of_logic = "</tlLogic>";
  const auto at = text.find(end_of_logic);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + end_of_logic.size(),
              "\n    <tlLogic id=\"C\" type=\"static\" programID=\"red\" offset=\"0\">\n"
              "        <phase duration=\"60\" state=\"rrrrrrrrrrrrrrrr\"/>\n    </tlLogic>");
  const auto dir = std::filesystem::temp_directory_path() / "signalsim_generate_net_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "cross_red.net.xml").string();
  std::ofstream(path) << text;
  for (const auto& [net_path, never] : {std::pair{kNets + "cross/cross.net.xml", false}, {path, true}}) {
    const auto net = sumo::NetIndex::load(net_path);
    const Scenario s = scenario_for(net_path, {"in_S", "out_N"});
    const sumo::RoutePlan plan = plan_route(s, net);
    const PlannedRouteFacts f = route_facts(plan, plan_lateral(s, plan, net), net);
    EXPECT_EQ(!f.never_green.empty(), never) << net_path;
    ASSERT_EQ(f.light_cycles.size(), 1u);
    EXPECT_DOUBLE_EQ(f.light_cycles[0], never ? 60.0 : 70.0);  // the running program's cycle
  }
}

TEST(RouteFacts, TheLaneChangeARouteNeedsIsAFact) {
  const std::string path = kNets + "cross_feeder/cross_feeder.net.xml";
  const auto net = sumo::NetIndex::load(path);
  const Scenario s = scenario_for(path, {"w_far", "in_W", "out_N"});
  const sumo::RoutePlan plan = plan_route(s, net);
  const PlannedRouteFacts f = route_facts(plan, plan_lateral(s, plan, net), net);
  ASSERT_EQ(f.lane_changes.size(), 1u);
  EXPECT_EQ(f.lane_changes[0].edge, "in_W");
  EXPECT_GT(f.lane_changes[0].at, f.lane_changes[0].edge_start);
  EXPECT_LT(f.lane_changes[0].at, f.lane_changes[0].edge_end);
}

std::string write_scenario(const std::string& expect_line) {
  const auto dir = std::filesystem::temp_directory_path() / "signalsim_generate_net_test";
  std::filesystem::create_directories(dir);
  const auto path = dir / "arrives.yaml";
  std::ofstream(path) << "name: arrives\nnet: " << kNets << "cross/cross.net.xml\nego:\n  route: [in_S, out_N]\n"
                      << "expect:\n  - " << expect_line << "\n";
  return path.string();
}

TEST(ArrivesExpectation, HoldsOnlyWhenTheEgoArrived) {
  const Scenario s = load_scenario(write_scenario("arrives: true"));
  ASSERT_EQ(s.expect.size(), 1u);
  EXPECT_EQ(describe(s.expect[0]), "arrives");
  RouteMap route;
  RunRecord record;
  record.rows.resize(2);
  record.rows.back().time = 12.5;
  record.rows.back().s_front = 80.0;
  record.arrived = false;
  auto results = evaluate_expectations(s, route, record);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_FALSE(results[0].passed);
  EXPECT_THAT(results[0].detail, testing::HasSubstr("before the ego arrived"));
  record.arrived = true;
  results = evaluate_expectations(s, route, record);
  EXPECT_TRUE(results[0].passed);
  EXPECT_EQ(results[0].detail, "arrived at t=12.50 s");
}

TEST(ArrivesExpectation, OnlyTrueIsAccepted) {
  EXPECT_THROW(load_scenario(write_scenario("arrives: false")), InputError);
  try {
    load_scenario(write_scenario("arrives: {at: 3}"));
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), testing::HasSubstr("expect[0].arrives: write 'arrives: true'"));
  }
}

}  // namespace
}  // namespace signalsim::generate
