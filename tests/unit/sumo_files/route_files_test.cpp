// The route-file scan: vehicles, trips and flows by id with their edges, as a user writes them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sumo/net_index.hpp"
#include "sumo/route_files.hpp"

namespace signalsim::sumo {
namespace {

const std::string kData = std::string(SIGNALSIM_SOURCE_DIR) + "/tests/data/user_sumo/";

TEST(RouteFiles, VehiclesWithInlineOrNamedRoutesFlowsAndTrips) {
  const RouteFiles files = RouteFiles::scan({kData + "demand.rou.xml", kData + "vtypes.add.xml"});
  const RouteFileVehicle* v42 = files.vehicle("veh42");
  ASSERT_NE(v42, nullptr);
  EXPECT_EQ(v42->kind, "vehicle");
  EXPECT_EQ(v42->edges, (std::vector<std::string>{"in_S", "out_W"}));  // inline <route>
  EXPECT_EQ(v42->type, "sedan");
  EXPECT_EQ(v42->depart_lane, "best");
  EXPECT_EQ(v42->line, 10);
  const RouteFileVehicle* v40 = files.vehicle("veh40");
  ASSERT_NE(v40, nullptr);
  EXPECT_EQ(v40->edges, (std::vector<std::string>{"in_N", "out_S"}));  // route="north_to_south"
  const RouteFileVehicle* flow = files.vehicle("east.3");                 // SUMO names flow vehicles id.n
  ASSERT_NE(flow, nullptr);
  EXPECT_EQ(flow->kind, "flow");
  EXPECT_EQ(flow->edges, (std::vector<std::string>{"in_W", "out_E"}));
  const RouteFileVehicle* trip = files.vehicle("trip7");
  ASSERT_NE(trip, nullptr);
  EXPECT_TRUE(trip->edges.empty()) << "a trip's route is SUMO's, at departure";
  EXPECT_EQ(files.vehicle("veh99"), nullptr);
  EXPECT_EQ(files.vehicle("east.x"), nullptr);
  EXPECT_EQ(files.vehicle("veh42.1"), nullptr) << "only flows have numbered members";
}

TEST(RouteFiles, TheBundledRealDemandIsScannedWhole) {
  const std::string dir = std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/bologna_acosta/";
  const RouteFiles files = RouteFiles::scan({dir + "acosta.rou.xml", dir + "acosta_busses.rou.xml"});
  EXPECT_GE(files.vehicle_count(), 8622u);
  const RouteFileVehicle* v = files.vehicle("Costa_12_0");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->edges.size(), 14u);
  EXPECT_EQ(v->edges.front(), "78[0]");
}

TEST(RouteFiles, MissingAndMalformedFilesNameTheFileAndLine) {
  EXPECT_THROW(RouteFiles::scan({kData + "nowhere.rou.xml"}), NetError);
  const auto path = std::filesystem::temp_directory_path() / "signalsim_malformed.rou.xml";
  std::ofstream(path) << "<routes>\n<vehicle depart=\"0\"/>\n</routes>\n";
  try {
    RouteFiles::scan({path.string()});
    ADD_FAILURE() << "a vehicle without an id was accepted";
  } catch (const NetError& e) {
    EXPECT_NE(std::string(e.what()).find("signalsim_malformed.rou.xml:2: <vehicle> without an id"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signalsim::sumo
