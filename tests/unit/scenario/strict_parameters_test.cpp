// Strict parameters against Autoware's own keys (data/autoware_keys.yaml): autoware_launch's files with
// their full key structure load (tests/data/autoware_launch, written by tools/autoware_key_tables), a
// key Autoware knows but signalsim does not use is listed, one Autoware dropped is a warning, any
// other key an error naming the nearest known key; the table read and judged on its own.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "scenario/autoware_key_table.hpp"
#include "scenario/input_error.hpp"
#include "scenario/parameters.hpp"
#include "scenario/scenario.hpp"
#include "scenario/vehicle_info.hpp"
#include "temp_dir.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::error_of;

std::string launch_file(const std::string& name) {
  return std::string(SIGNALSIM_SOURCE_DIR) + "/tests/data/autoware_launch/" + name;
}

const char* const kParameterFiles[] = {
    "behavior_path_planner.param.yaml", "traffic_light.param.yaml", "behavior_velocity_planner_common.param.yaml",
    "lane_change.param.yaml",           "start_planner.param.yaml", "goal_planner.param.yaml",
    "static_obstacle_avoidance.param.yaml"};

const char* const kTable =
    "files:\n"
    "  behavior_path_planner.param.yaml:\n"
    "    known: [planning_hz, backward_path_length, turn_signal_search_time]\n"
    "    dropped:\n"
    "      drivable_area_width: {repository: owner/universe, commit: \"0123abcd\", date: 2023-05-01}\n";

TEST(AutowareKeyTable, KnownDroppedAndTheNearestKnownKey) {
  TempDir dir("keys");
  const AutowareKeyTables tables = read_autoware_key_tables(dir.file("keys.yaml", kTable));
  const AutowareFileKeys& keys = tables.files.at("behavior_path_planner.param.yaml");
  EXPECT_TRUE(keys.knows("planning_hz"));
  EXPECT_FALSE(keys.knows("drivable_area_width"));
  ASSERT_NE(keys.dropped_key("drivable_area_width"), nullptr);
  EXPECT_EQ(keys.dropped_key("drivable_area_width")->commit, "0123abcd");
  EXPECT_EQ(keys.nearest_known("backward_path_lenght"), "backward_path_length");
  EXPECT_EQ(keys.nearest_known("planning_rate"), "planning_hz");
}

TEST(AutowareKeyTable, StrictJudgesAKeyByItsFilesEntry) {
  TempDir dir("keys");
  const AutowareKeyTables tables = read_autoware_key_tables(dir.file("keys.yaml", kTable));
  const std::string file = "/p/behavior_path_planner.param.yaml";
  EXPECT_EQ(strict_key_warning(tables, "behavior_path_planner.param.yaml", file, 3, "planning_hz", "parameter"),
            std::nullopt);
  EXPECT_EQ(strict_key_warning(tables, "behavior_path_planner.param.yaml", file, 4, "drivable_area_width", "parameter"),
            std::optional<std::string>(file + ":4: parameter 'drivable_area_width' was dropped from Autoware's "
                                              "behavior_path_planner.param.yaml (owner/universe 0123abcd, "
                                              "2023-05-01): it has no effect"));
  EXPECT_EQ(error_of([&] {
              strict_key_warning(tables, "behavior_path_planner.param.yaml", file, 5, "backward_path_lenght", "parameter");
            }),
            file + ":5: unknown parameter 'backward_path_lenght': not a key of Autoware's "
                   "behavior_path_planner.param.yaml (did you mean 'backward_path_length'?)");
  // A file the table does not have: every key must be one signalsim uses.
  EXPECT_EQ(error_of([&] { strict_key_warning(tables, "mine.yaml", "mine.yaml", 2, "planning_hz", "parameter"); }),
            "mine.yaml:2: unknown parameter 'planning_hz' (strict parameters: every key must be known)");
}

TEST(AutowareKeyTable, AMalformedTableNamesItsLine) {
  TempDir dir("keys");
  const std::string path = dir.file("keys.yaml", "files:\n  x.param.yaml:\n    known: a\n    dropped: {}\n");
  EXPECT_EQ(error_of([&] { read_autoware_key_tables(path); }), path + ":3: 'x.param.yaml.known' must be a list");
}

TEST(AutowareKeyTable, TheBundledTableHasEveryFileSignalsimReads) {
  const AutowareKeyTables& tables = autoware_key_tables();
  for (const char* file : kParameterFiles) EXPECT_EQ(tables.files.count(file), 1u) << file;
  const AutowareFileKeys& vehicle = tables.files.at("vehicle_info.param.yaml");
  EXPECT_TRUE(vehicle.knows("wheel_radius") && vehicle.knows("wheel_base") && vehicle.knows("max_steer_angle"));
  const AutowareFileKeys& avoidance = tables.files.at("static_obstacle_avoidance.param.yaml");
  ASSERT_NE(avoidance.dropped_key("avoidance.yield.enable_signalling_during_yield"), nullptr);
  EXPECT_EQ(avoidance.dropped_key("avoidance.yield.enable_signalling_during_yield")->commit, "e4f932aebc");
  EXPECT_TRUE(tables.files.at("traffic_light.param.yaml").knows("traffic_light.v2i.use_remaining_time"));
  EXPECT_NE(tables.files.at("traffic_light.param.yaml").dropped_key("traffic_light.external_tl_state_timeout"), nullptr);
}

// --- autoware_launch's files, every key of them -------------------------------------------------

TEST(StrictParameters, AutowareLaunchFilesLoadWithTheDroppedKeyWarned) {
  ParameterSet set;
  for (const char* file : kParameterFiles) EXPECT_NO_THROW(set.apply_file(launch_file(file), /*strict=*/true)) << file;
  ASSERT_EQ(set.warnings().size(), 1u);
  EXPECT_EQ(set.warnings()[0], launch_file("static_obstacle_avoidance.param.yaml") +
                                   ":227: parameter 'avoidance.yield.enable_signalling_during_yield' was dropped from "
                                   "Autoware's static_obstacle_avoidance.param.yaml (tier4/autoware_universe_planning "
                                   "e4f932aebc, 2026-02-26): it has no effect");
  // Autoware's keys signalsim does not model are listed, one note line per file.
  std::size_t listed = 0;
  for (const UnusedParameters& u : set.unused()) listed += u.keys.size();
  // Every key of the seven files but those signalsim uses and the dropped one: 614 before signalsim
  // read the avoidance's candidate_path_turn_signal and turn_signal_on_approval_hold_duration and the
  // start planner's enable_back.
  EXPECT_EQ(listed, 614u - 3u - 1u);
  EXPECT_DOUBLE_EQ(set.number("max_prepare_time"), 2.0);
  EXPECT_EQ(set.origin("max_prepare_time"), launch_file("static_obstacle_avoidance.param.yaml") + ":206");
  const VehicleInfo vehicle = load_vehicle_info(launch_file("vehicle_info.param.yaml"), /*strict=*/true);
  EXPECT_EQ(vehicle.unused, (std::vector<std::string>{"wheel_radius", "wheel_width", "vehicle_height", "max_steer_angle"}));
  EXPECT_TRUE(vehicle.warnings.empty());
}

TEST(StrictParameters, ATypoOfAnAutowareKeyNamesTheNearestKnownOne) {
  TempDir dir("strict");
  const std::string path = dir.file("behavior_path_planner.param.yaml",
                                    "/**:\n  ros__parameters:\n    planning_hz: 10.0\n    backward_path_lenght: 5.0\n");
  ParameterSet set;
  EXPECT_EQ(error_of([&] { set.apply_file(path, /*strict=*/true); }),
            path + ":4: unknown parameter 'backward_path_lenght': not a key of Autoware's "
                   "behavior_path_planner.param.yaml (did you mean 'backward_path_length'?)");
  // Lenient, the same key is listed.
  ParameterSet lenient;
  ASSERT_NO_THROW(lenient.apply_file(path, /*strict=*/false));
  ASSERT_EQ(lenient.unused().size(), 1u);
  EXPECT_EQ(lenient.unused()[0].keys, (std::vector<std::string>{"planning_hz", "backward_path_lenght"}));
}

TEST(StrictParameters, AFileOfAnotherNameKeepsOnlySignalsimsKeys) {
  TempDir dir("strict");
  const std::string path = dir.file("candidate.yaml", "/**:\n  ros__parameters:\n    planning_hz: 10.0\n");
  ParameterSet set;
  EXPECT_EQ(error_of([&] { set.apply_file(path, /*strict=*/true); }),
            path + ":3: unknown parameter 'planning_hz' (strict parameters: every key must be known)");
  const std::string signalsims = dir.file("mine.yaml", "turn_signal_search_time: 2.0\n");
  EXPECT_NO_THROW(set.apply_file(signalsims, /*strict=*/true));
}

TEST(StrictParameters, VehicleInfoOfAnyNameIsCheckedAgainstAutowaresVehicleInfo) {
  TempDir dir("strict");
  const std::string dims = "/**:\n  ros__parameters:\n    wheel_base: 2.79\n    wheel_tread: 1.64\n"
                           "    front_overhang: 1.0\n    rear_overhang: 1.1\n    left_overhang: 0.128\n"
                           "    right_overhang: 0.128\n";
  const std::string known = dir.file("my_car.yaml", dims + "    wheel_radius: 0.383\n");
  EXPECT_EQ(load_vehicle_info(known, /*strict=*/true).unused, (std::vector<std::string>{"wheel_radius"}));
  const std::string typo = dir.file("my_van.yaml", dims + "    vehicle_hieght: 2.5\n");
  EXPECT_EQ(error_of([&] { load_vehicle_info(typo, /*strict=*/true); }),
            typo + ":9: unknown key 'vehicle_hieght': not a key of Autoware's vehicle_info.param.yaml (did you mean "
                   "'vehicle_height'?)");
}

// --- a scenario: the warnings it keeps, --params as an override ----------------------------------

TEST(StrictParameters, TheScenarioKeepsTheWarningAndAppendedFilesApplyLast) {
  TempDir dir("strict");
  dir.file("x.net.xml", "<net/>\n");  // only its existence is checked at load
  const std::string scenario = dir.file(
      "s.yaml", "name: s\nnet: x.net.xml\nego: {route: [a]}\nparams:\n  files: [" +
                    launch_file("static_obstacle_avoidance.param.yaml") + "]\n");
  const std::string candidate = dir.file("candidate.yaml", "turn_signal_search_time: 2.0\n");
  const Scenario s =
      load_scenario(scenario, ScenarioOverrides{{"params.strict=true", "params.files+=\"" + candidate + "\""}});
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_NE(s.warnings[0].find("'avoidance.yield.enable_signalling_during_yield' was dropped"), std::string::npos);
  EXPECT_DOUBLE_EQ(s.params.number("turn_signal_search_time"), 2.0);
  EXPECT_EQ(s.params.origin("turn_signal_search_time"), candidate + ":1");
  // Without strict parameters the dropped key is only listed.
  EXPECT_TRUE(load_scenario(scenario).warnings.empty());
}

}  // namespace
}  // namespace signalsim
