// Finding a vehicle of the user's route files by id: vehicles with inline or named routes, flows and
// trips, as a user writes them, and the bundled real demand.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "net/net_index.hpp"
#include "net/route_files.hpp"
#include "temp_dir.hpp"

namespace signalsim::sumo {
namespace {

const std::string kData = std::string(SIGNALSIM_SOURCE_DIR) + "/tests/data/user_sumo/";
const std::vector<std::string> kFiles = {kData + "demand.rou.xml", kData + "vtypes.add.xml"};

TEST(RouteFiles, AVehicleWithAnInlineRoute) {
  const auto v42 = find_route_file_vehicle(kFiles, "veh42");
  ASSERT_TRUE(v42);
  EXPECT_EQ(v42->kind, "vehicle");
  EXPECT_EQ(v42->edges, (std::vector<std::string>{"in_S", "out_W"}));
  EXPECT_EQ(v42->type, "sedan");
  EXPECT_EQ(v42->depart, "5");
  EXPECT_EQ(v42->depart_lane, "best");
  EXPECT_EQ(v42->line, 10);
  EXPECT_EQ(v42->stops, 0);
}

TEST(RouteFiles, ANamedRouteAFlowsVehiclesAndATrip) {
  const auto v40 = find_route_file_vehicle(kFiles, "veh40");
  ASSERT_TRUE(v40);
  EXPECT_EQ(v40->edges, (std::vector<std::string>{"in_N", "out_S"}));  // route="north_to_south"
  const auto flow = find_route_file_vehicle(kFiles, "east.3");          // SUMO names flow vehicles id.n
  ASSERT_TRUE(flow);
  EXPECT_EQ(flow->kind, "flow");
  EXPECT_EQ(flow->depart, "10");  // the flow's begin
  EXPECT_EQ(flow->edges, (std::vector<std::string>{"in_W", "out_E"}));
  EXPECT_FALSE(find_route_file_vehicle(kFiles, "east.3", false)) << "flows only when asked for";
  const auto trip = find_route_file_vehicle(kFiles, "trip7");
  ASSERT_TRUE(trip);
  EXPECT_TRUE(trip->edges.empty()) << "a trip's route is SUMO's, at departure";
  EXPECT_FALSE(find_route_file_vehicle(kFiles, "veh99"));
  EXPECT_FALSE(find_route_file_vehicle(kFiles, "east.x"));
  EXPECT_FALSE(find_route_file_vehicle(kFiles, "veh42.1")) << "only flows have numbered members";
  EXPECT_FALSE(find_route_file_vehicle(kFiles, "sedan")) << "a vType's id is no vehicle";
  EXPECT_FALSE(find_route_file_vehicle(kFiles, "veh4")) << "a prefix of an id is not the id";
}

TEST(RouteFiles, TheBundledRealDemand) {
  const std::string dir = std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/bologna_acosta/";
  const std::vector<std::string> files = {dir + "acosta.rou.xml", dir + "acosta_busses.rou.xml"};
  const auto v = find_route_file_vehicle(files, "Costa_12_0");
  ASSERT_TRUE(v);
  EXPECT_EQ(v->edges.size(), 14u);
  EXPECT_EQ(v->edges.front(), "78[0]");
  const auto bus = find_route_file_vehicle(files, "bus_130_0");  // in the second file, with its stops
  ASSERT_TRUE(bus);
  EXPECT_GT(bus->stops, 0);
  EXPECT_FALSE(find_route_file_vehicle(files, "ego"));
}

TEST(RouteFiles, WrittenOtherwiseAndMalformed) {
  const TempDir dir("route_files");
  const std::string path = dir.file("user.rou.xml", "<routes>\n  <vehicle depart='1' id = 'single'>\n"
                                                   "    <route edges='a b'/>\n    <stop lane='b_0' duration='5'/>\n"
                                                   "  </vehicle>\n  <vehicle id=\"broken\" depart=\"0\"><route edges=\"a\">\n"
                                                   "</routes>\n");
  const auto single = find_route_file_vehicle({path}, "single");
  ASSERT_TRUE(single);
  EXPECT_EQ(single->line, 2);
  EXPECT_EQ(single->edges, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(single->stops, 1);
  EXPECT_THROW(find_route_file_vehicle({kData + "nowhere.rou.xml"}, "x"), NetError);
  try {
    find_route_file_vehicle({path}, "broken");
    ADD_FAILURE() << "a malformed vehicle was accepted";
  } catch (const NetError& e) {
    EXPECT_NE(std::string(e.what()).find("user.rou.xml:6: <vehicle> is not well-formed XML"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signalsim::sumo
