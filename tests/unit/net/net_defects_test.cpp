// The loading rule (net/net_index.hpp): whatever SUMO 1.15 loads, NetIndex loads; a defect in an
// element is recorded with its line, and refuses only a route that uses the element, with one
// message naming the element and the reason. The nets are tests/data/nets/line.net.xml (ab -> bc ->
// cb; ab_0 reaches bc_1, cb_0 reaches bc_0) and crossing.net.xml with one attribute changed, and the
// bundled real net bologna_acosta (netconvert 1.22: two lanes with index 0 on internal edge :9_17).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "net/net_index.hpp"
#include "route/route_builder.hpp"
#include "test_nets.hpp"

namespace signalsim::sumo {
namespace {

using ::testing::ElementsAre;
using testing::net_path;
using testing::read_all;
using testing::ScratchDir;

const std::string kAcosta = std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/bologna_acosta/acosta_buslanes.net.xml";

/// `text` with its first `from` replaced by `to` (the test fails when `from` is not there).
std::string changed(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// 1-based line of the first occurrence of `needle`.
int line_of(const std::string& text, const std::string& needle) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

std::string route_error(const NetIndex& net, const std::vector<std::string>& edges, const std::vector<int>& exits = {}) {
  try {
    build_route(net, edges, exits);
  } catch (const RouteError& e) {
    return e.what();
  }
  return "";
}

/// line.net.xml with one change, written to the scratch directory and loaded.
struct ChangedLine {
  ScratchDir scratch;
  std::string text;
  std::string path;
  NetIndex net;
  ChangedLine(const std::string& from, const std::string& to, const std::string& base = "line.net.xml")
      : text(changed(read_all(net_path(base)), from, to)), path(scratch.write("changed.net.xml", text)),
        net(NetIndex::load(path)) {}
  std::string at(const std::string& needle) const { return path + ":" + std::to_string(line_of(text, needle)) + ": "; }
};

const char* kLaneBc1 = "<lane id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"48.50\" shape=\"51.50,-1.60 100.00,-1.60\"/>";

// ---- a real net with a defect: bologna_acosta -----------------------------------------------------

TEST(NetDefectsReal, BolognaAcostaLoadsWithItsRepeatedInternalLaneIndexRecorded) {
  const NetIndex net = NetIndex::load(kAcosta);
  ASSERT_EQ(net.defects().size(), 1u);
  const NetDefect& d = net.defects()[0];
  EXPECT_EQ(d.element, "edge ':9_17'");
  EXPECT_EQ(d.reason, "lane indices are not 0..1 (lane ':9_17_1' repeats index 0); the file's lane order is used");
  EXPECT_EQ(d.line, 989);
  EXPECT_FALSE(d.affects_routes);  // internal lanes are found by id
  EXPECT_EQ(net.defect(NetElement::Edge, ":9_17"), nullptr);
  // The file's order, as SUMO keeps it: the second lane is index 1.
  EXPECT_EQ(net.edge(":9_17")->lanes[1].id, ":9_17_1");
  EXPECT_EQ(net.edge(":9_17")->lanes[1].index, 1);
}

TEST(NetDefectsReal, Route131To209AndARouteThroughTheRepeatedIndexBuild) {
  const NetIndex net = NetIndex::load(kAcosta);
  const RoutePlan issue = build_route(net, {"131", "117", "209"});
  EXPECT_EQ(issue.map.at(0).lane_id, "131_0");
  EXPECT_EQ(issue.map.at(issue.map.size() - 1).lane_id, "209_0");
  // 11 -> 86 leaving 11 on lane 2: the left turn :9_9_1 -> :9_17_1 -> 86_2.
  const RoutePlan left = build_route(net, {"11", "86"}, {2, -1});
  std::vector<std::string> lanes;
  for (const Lanelet& l : left.map.lanelets()) lanes.push_back(l.lane_id);
  EXPECT_THAT(lanes, ElementsAre("11_2", ":9_9_1", ":9_17_1", "86_2"));
}

// ---- what SUMO 1.15 loads, signalsim loads (each checked with `sumo -n`) --------------------------

TEST(NetDefectsLoad, LaneIndexGapOnANormalEdgeRefusesOnlyRoutesOverThatEdge) {
  const ChangedLine c("id=\"bc_1\" index=\"1\"", "id=\"bc_1\" index=\"2\"");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}),
            c.at("<edge id=\"bc\"") +
                "edge 'bc': lane indices are not 0..1 (lane 'bc_1' has index 2); the file's lane order is used (a route edge)");
  EXPECT_EQ(route_error(c.net, {"cb"}), "");
}

TEST(NetDefectsLoad, RepeatedLaneIndexOnAnInternalEdgeRefusesNothing) {
  const ChangedLine c("<lane id=\":B_0_0\" index=\"0\" speed=\"4.08\" length=\"6.40\" shape=\"51.50,1.60 51.50,-4.80\"/>",
                      "<lane id=\":B_0_0\" index=\"0\" speed=\"4.08\" length=\"6.40\" shape=\"51.50,1.60 51.50,-4.80\"/>\n"
                      "        <lane id=\":B_0_1\" index=\"0\" speed=\"4.08\" length=\"6.40\" shape=\"51.50,1.60 51.50,-4.80\"/>");
  ASSERT_EQ(c.net.defects().size(), 1u);
  EXPECT_FALSE(c.net.defects()[0].affects_routes);
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}), "");  // through :B_0_0
}

TEST(NetDefectsLoad, NanLengthRefusesOnlyARouteThatDrivesTheLane) {
  const ChangedLine c("id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"48.50\"",
                      "id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"nan\"");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}),
            c.at("id=\"bc_1\"") + "lane 'bc_1': attribute 'length' is not a number: 'nan' (a lane the route drives on edge 'bc')");
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}), "");  // enters and ends on bc_0
}

TEST(NetDefectsLoad, NegativeLength) {
  const ChangedLine c("id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"48.50\"",
                      "id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"-3\"");
  EXPECT_EQ(c.net.defect(NetElement::Lane, "bc_1")->reason, "attribute 'length' is negative: '-3'");
}

TEST(NetDefectsLoad, LinkIndexThatIsNoIntegerWithoutALightRefusesNothing) {
  const ChangedLine c("via=\":B_1_0\" dir=\"s\" state=\"M\"", "via=\":B_1_0\" dir=\"s\" state=\"M\" linkIndex=\"x\"");
  ASSERT_EQ(c.net.defects().size(), 1u);
  EXPECT_EQ(c.net.defects()[0].reason, "attribute 'linkIndex' is not an integer: 'x'");
  EXPECT_FALSE(c.net.defects()[0].affects_routes);
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}), "");
}

TEST(NetDefectsLoad, ParamWithoutValueIsNoDefect) {
  const ChangedLine c(kLaneBc1, "<lane id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"48.50\" "
                                "shape=\"51.50,-1.60 100.00,-1.60\"><param key=\"k\"/></lane>");
  EXPECT_TRUE(c.net.defects().empty());
  EXPECT_EQ(c.net.lane("bc_1")->params.at("k"), "");
}

// ---- what SUMO refuses is a defect of its element too: loaded, refused where used ---------------

TEST(NetDefectsRefused, MissingShape) {
  const ChangedLine c(" shape=\"51.50,-1.60 100.00,-1.60\"", "");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}), c.at("id=\"bc_1\"") + "lane 'bc_1': has no shape (a lane the route drives on edge 'bc')");
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}), "");
}

TEST(NetDefectsRefused, MalformedShapePoint) {
  const ChangedLine c("shape=\"51.50,-1.60 100.00,-1.60\"", "shape=\"51.50,-1.60 100.00\"");
  EXPECT_EQ(c.net.defect(NetElement::Lane, "bc_1")->reason, "attribute 'shape' has a malformed point: '100.00'");
}

TEST(NetDefectsRefused, NumberThatDoesNotParse) {
  const ChangedLine c("id=\"bc_1\" index=\"1\" speed=\"13.89\"", "id=\"bc_1\" index=\"1\" speed=\"fast\"");
  EXPECT_EQ(c.net.defect(NetElement::Lane, "bc_1")->reason, "attribute 'speed' is not a number: 'fast'");
  EXPECT_DOUBLE_EQ(c.net.lane("bc_1")->speed, 13.89);  // SUMO's default until a route uses it
}

TEST(NetDefectsRefused, ConnectionLaneThatIsNoIntegerRefusesRoutesOverItsFromEdge) {
  const ChangedLine c("<connection from=\"ab\" to=\"bc\" fromLane=\"0\"", "<connection from=\"ab\" to=\"bc\" fromLane=\"x\"");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}),
            c.at("<connection from=\"ab\"") + "connection 'ab' -> 'bc': attribute 'fromLane' is not an integer: 'x' (a route edge)");
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}), "");
}

TEST(NetDefectsRefused, UnknownDirRefusesRoutesOverItsFromLane) {
  const ChangedLine c("via=\":B_0_0\" dir=\"t\"", "via=\":B_0_0\" dir=\"q\"");
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}),
            c.at("<connection from=\"cb\" to=\"bc\"") +
                "connection 'cb' -> 'bc': attribute 'dir' is not a SUMO link direction (s t T l r L R invalid): 'q' "
                "(a lane the route drives on edge 'cb')");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}), "");
}

TEST(NetDefectsRefused, DuplicateEdgeIdNamesBothLines) {
  const ChangedLine c("<edge id=\"cb\" from=\"C\" to=\"B\" priority=\"-1\">", "<edge id=\"bc\" from=\"C\" to=\"B\" priority=\"-1\">");
  const int first = line_of(c.text, "<edge id=\"bc\"");
  const std::size_t second_at = c.text.find("<edge id=\"bc\"", c.text.find("<edge id=\"bc\"") + 1);
  const int second = 1 + static_cast<int>(std::count(c.text.begin(), c.text.begin() + static_cast<std::ptrdiff_t>(second_at), '\n'));
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}), c.path + ":" + std::to_string(second) +
                                                  ": edge 'bc': another edge has this id; this one is ignored (first "
                                                  "defined at line " + std::to_string(first) + ") (a route edge)");
  EXPECT_EQ(c.net.edge("bc")->lanes.size(), 2u);  // the first one
}

TEST(NetDefectsRefused, DuplicateLaneAndJunctionIds) {
  const ChangedLine lane("<lane id=\"cb_0\"", "<lane id=\"bc_0\"");
  EXPECT_EQ(lane.net.defect(NetElement::Lane, "bc_0")->reason,
            "another lane has this id (first defined at line " + std::to_string(line_of(lane.text, "<lane id=\"bc_0\"")) + ")");
  EXPECT_EQ(lane.net.lane("bc_0"), &lane.net.edge("bc")->lanes[0]);  // the first one
  const ChangedLine junction("<junction id=\"A\"", "<junction id=\"B\"");
  EXPECT_EQ(junction.net.defect(NetElement::Junction, "B")->reason,
            "another junction has this id; this one is ignored (first defined at line " +
                std::to_string(line_of(junction.text, "<junction id=\"B\"")) + ")");
}

TEST(NetDefectsRefused, ProgramsMayShareAnIdButNotAnIdAndAProgramId) {
  const std::string logic = "<tlLogic id=\"C\" type=\"static\" programID=\"0\" offset=\"0\">";
  const ChangedLine other(logic, "<tlLogic id=\"C\" type=\"static\" programID=\"1\" offset=\"0\"><phase duration=\"5\" "
                                 "state=\"GGGGGGGGGGGGGGGGGGGG\"/></tlLogic>\n    " + logic, "crossing.net.xml");
  // crossing.net.xml's one defect is edge n_in's turn_signal_distance 'far' (RouteBuilderParams).
  ASSERT_EQ(other.net.defects().size(), 1u);
  EXPECT_EQ(other.net.defects()[0].element, "edge 'n_in'");
  EXPECT_EQ(other.net.tl_logics().size(), 2u);
  const ChangedLine same(logic, "<tlLogic id=\"C\" type=\"static\" programID=\"0\" offset=\"0\"><phase duration=\"5\" "
                                "state=\"GGGGGGGGGGGGGGGGGGGG\"/></tlLogic>\n    " + logic, "crossing.net.xml");
  ASSERT_EQ(same.net.defects().size(), 2u);  // in file order: the param (line 137), then the tlLogic
  EXPECT_EQ(same.net.defects()[1].reason, "another tlLogic has this id and programID '0'; this one is ignored (first "
                                          "defined at line " + std::to_string(line_of(same.text, "<tlLogic")) + ")");
  EXPECT_EQ(same.net.defects()[1].line, line_of(same.text, "<tlLogic") + 1);
  EXPECT_EQ(same.net.tl_logics().size(), 1u);
}

TEST(NetDefectsRefused, LaneWithoutIdRefusesRoutesOverItsEdge) {
  const ChangedLine c("<lane id=\"bc_1\" ", "<lane ");
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}), c.at("<lane index=\"1\"") + "edge 'bc': a <lane> has no id (a route edge)");
}

TEST(NetDefectsRefused, NormalEdgeWithoutLanesRefusesRoutesOverItAtItsLine) {
  const ChangedLine c("<lane id=\"ab_0\" index=\"0\" speed=\"13.89\" length=\"48.50\" shape=\"0.00,-1.60 48.50,-1.60\"/>", "");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}), c.at("<edge id=\"ab\"") + "edge 'ab': the edge has no <lane> (a route edge)");
  EXPECT_EQ(route_error(c.net, {"cb", "bc"}), "");
}

TEST(NetDefectsRefused, ParamWithoutKey) {
  const ChangedLine c(kLaneBc1, "<lane id=\"bc_1\" index=\"1\" speed=\"13.89\" length=\"48.50\" "
                                "shape=\"51.50,-1.60 100.00,-1.60\">\n<param value=\"v\"/></lane>");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}),
            c.at("<param value") + "lane 'bc_1' <param>: attribute 'key' is missing (a lane the route drives on edge 'bc')");
}

TEST(NetDefectsRefused, JunctionOfTheRoute) {
  const ChangedLine c("<junction id=\"B\" type=\"priority\" x=\"50.00\"", "<junction id=\"B\" type=\"priority\" x=\"fifty\"");
  EXPECT_EQ(route_error(c.net, {"ab", "bc"}), c.at("<junction id=\"B\"") +
                                                   "junction 'B': attribute 'x' is not a number: 'fifty' (the junction "
                                                   "of the route's connection 'ab' -> 'bc')");
  EXPECT_EQ(route_error(c.net, {"bc"}), "");
}

TEST(NetDefectsRefused, LightOfTheRoute) {
  const ChangedLine c("<phase duration=\"3\"", "<phase duration=\"three\"", "crossing.net.xml");
  EXPECT_EQ(route_error(c.net, {"s_in", "n_out"}),
            c.at("<phase duration=\"three\"") + "tlLogic 'C' <phase>: attribute 'duration' is not a number: 'three' (the "
                                                  "light of the route's connection 's_in' -> 'n_out')");
}

}  // namespace
}  // namespace signalsim::sumo
