// Autoware's vehicle description as the ego's footprint (scenario/vehicle_info, and the scenario's
// ego.vehicle_info: explicit keys win).
#include <string>

#include <gtest/gtest.h>

#include "autoware_fixture.hpp"
#include "scenario/input_error.hpp"
#include "scenario/scenario.hpp"
#include "scenario/vehicle_info.hpp"
#include "temp_dir.hpp"

namespace signalsim {
namespace {

using test::fixture;

std::string error_of_file(const std::string& text) {
  TempDir dir("vehicle");
  const std::string path = dir.file("vehicle_info.param.yaml", text);
  try {
    load_vehicle_info(path);
  } catch (const InputError& e) {
    return std::string(e.what()).substr(path.size());
  }
  return "";
}

constexpr const char* kComplete =
    "/**:\n  ros__parameters:\n    wheel_base: 2.79\n    wheel_tread: 1.64\n    front_overhang: 1.0\n"
    "    rear_overhang: 1.1\n    left_overhang: 0.128\n    right_overhang: 0.128\n";

TEST(VehicleInfo, TheFootprintOfTheSampleVehicle) {
  const VehicleInfo info = load_vehicle_info(fixture("vehicle_info.param.yaml"));
  EXPECT_NEAR(info.length(), 1.0 + 2.79 + 1.1, 1e-12);
  EXPECT_NEAR(info.width(), 1.64 + 0.128 + 0.128, 1e-12);
  EXPECT_NEAR(info.base_link_to_front(), 2.79 + 1.0, 1e-12);
  EXPECT_EQ(info.lines.at("wheel_base"), 5);
  EXPECT_EQ(info.unused, (std::vector<std::string>{"wheel_radius", "wheel_width", "vehicle_height", "max_steer_angle"}));
}

TEST(VehicleInfo, BadFiles) {
  EXPECT_EQ(error_of_file(std::string(kComplete) + "    wheel_bse: 2.0\n"),
            ":9: unknown key 'wheel_bse' (did you mean 'wheel_base'?)");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters:\n    wheel_base: 2.79\n"), ": missing key 'front_overhang'");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters:\n    wheel_base: long\n"), ":3: 'wheel_base': expected a number, got 'long'");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters:\n    wheel_base: \"2.8\"\n"), ":3: 'wheel_base': expected a number, got '2.8'");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters:\n    wheel_base: 1e-310\n"),
            ":3: 'wheel_base': value 1e-310 is too small to be a number SUMO can read (below 2.2e-308); write 0");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters:\n    wheel_base: 0\n"), ":3: 'wheel_base': 0 m is out of range (0, 30]");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters:\n    rear_overhang: -0.5\n"),
            ":3: 'rear_overhang': -0.5 m is out of range [0, 30]");
  EXPECT_EQ(error_of_file("/**:\n  ros__parameters: [1, 2]\n"),
            ":2: '/**.ros__parameters' must be a mapping of name: value, got a list");
}

TEST(VehicleInfo, UnequalOverhangsAddUp) {
  TempDir dir("vehicle");
  const std::string path = dir.file("v.yaml", "/**:\n  ros__parameters:\n    wheel_base: 3.0\n    wheel_tread: 1.5\n"
                                               "    front_overhang: 0.9\n    rear_overhang: 1.2\n    left_overhang: 0.1\n"
                                               "    right_overhang: 0.3\n    vehicle_mass: 1500\n");
  const VehicleInfo info = load_vehicle_info(path);
  EXPECT_NEAR(info.length(), 5.1, 1e-12);
  EXPECT_NEAR(info.width(), 1.9, 1e-12);
  EXPECT_NEAR(info.base_link_to_front(), 3.9, 1e-12);
  EXPECT_EQ(info.unused, (std::vector<std::string>{"vehicle_mass"}));
  // Strict: a key that is not Autoware's is refused, naming its nearest key; Autoware's own unused keys are not.
  try {
    load_vehicle_info(path, /*strict=*/true);
    ADD_FAILURE() << "strict accepted vehicle_mass";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ":9: unknown key 'vehicle_mass': not a key of Autoware's "
                                            "vehicle_info.param.yaml (did you mean 'vehicle_height'?)");
  }
  EXPECT_NO_THROW(load_vehicle_info(fixture("vehicle_info.param.yaml"), /*strict=*/true));
}

TEST(VehicleInfo, TheScenarioTakesTheFootprintAndExplicitKeysWin) {
  TempDir dir("scenario");
  dir.file("x.net.xml", "<net/>\n");  // only its existence is checked at load
  const std::string head = "name: s\nnet: x.net.xml\nego:\n  route: [a]\n  vehicle_info: " + fixture("vehicle_info.param.yaml") + "\n";
  const Scenario s = load_scenario(dir.file("a.yaml", head));
  EXPECT_NEAR(s.ego.length, 4.89, 1e-9);
  EXPECT_NEAR(s.ego.width, 1.896, 1e-9);
  EXPECT_NEAR(s.ego.base_link_to_front, 3.79, 1e-9);
  EXPECT_EQ(s.ego.vehicle_info, fixture("vehicle_info.param.yaml"));
  EXPECT_EQ(s.ego.from_vehicle_info, (std::set<std::string>{"base_link_to_front", "length", "width"}));
  const Scenario explicit_length = load_scenario(dir.file("b.yaml", head + "  length: 5.2\n"));
  EXPECT_DOUBLE_EQ(explicit_length.ego.length, 5.2);
  EXPECT_NEAR(explicit_length.ego.base_link_to_front, 3.79, 1e-9);  // still the file's
  EXPECT_EQ(explicit_length.ego.from_vehicle_info.count("length"), 0u);
  // An explicit length shorter than the file's base_link_to_front cannot hold it.
  try {
    load_scenario(dir.file("c.yaml", head + "  length: 3.0\n"));
    ADD_FAILURE() << "accepted a base_link_to_front beyond the vehicle";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'ego.length': 3 m is shorter than base_link_to_front 3.79 m from vehicle_info"),
              std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace signalsim
