// The scenario loader reads every key through its key table (scenario/scenario_keys.hpp): every key of
// every table is read (tests/data/schema/every_key*.yaml hold them all and load), an unknown key is
// refused at every level, and every number is checked against its table's range.
#include <cmath>
#include <filesystem>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "scenario/input_error.hpp"
#include "scenario/overrides.hpp"
#include "scenario/scenario.hpp"
#include "scenario/scenario_keys.hpp"
#include "scenario/yaml_fields.hpp"
#include "temp_dir.hpp"

namespace signalsim {
namespace {

const std::string kData = std::string(SIGNALSIM_SOURCE_DIR) + "/tests/data/schema/";
const std::string kEveryKey = kData + "every_key.yaml";
const std::string kTakeOver = kData + "every_key_take_over.yaml";

// Key paths of the tables: "ego.max_speed", "maneuvers[].lane_change.at", "expect[].arrives".
void table_paths(const KeyTable& table, const std::string& prefix, std::set<std::string>& out) {
  for (const KeySpec& key : table.keys) {
    const std::string path = prefix + key.name;
    out.insert(path);
    if (!key.table) continue;
    if (key.type == KeyType::Mapping) table_paths(*key.table, path + ".", out);
    if (key.type == KeyType::MappingList) table_paths(*key.table, path + "[].", out);
    if (key.type == KeyType::KindList)
      for (const KeySpec& kind : key.table->keys) {
        out.insert(path + "[]." + kind.name);
        if (kind.table) table_paths(*kind.table, path + "[]." + kind.name + ".", out);
      }
  }
}

// The same paths of a file; the free names under light_offsets and params.set are not keys.
void file_paths(const YAML::Node& node, const std::string& prefix, std::set<std::string>& out) {
  for (const auto& entry : node) {
    const std::string path = prefix + entry.first.Scalar();
    out.insert(path);
    if (path == "light_offsets" || path == "params.set") continue;
    if (entry.second.IsMap()) file_paths(entry.second, path + ".", out);
    if (entry.second.IsSequence())
      for (const YAML::Node& item : entry.second)
        if (item.IsMap()) file_paths(item, path + "[].", out);
  }
}

// `doc` written into `dir` with the every_key file's relative paths made absolute.
std::string write_beside(const TempDir& dir, YAML::Node doc) {
  const auto absolute = [](YAML::Node n) {
    if (n.IsScalar()) n = kData + n.Scalar();
  };
  const auto absolute_list = [&](YAML::Node list) {
    for (std::size_t i = 0; i < list.size(); ++i) list[i] = kData + list[i].Scalar();
  };
  absolute(doc["net"]);
  absolute_list(doc["routes"]);
  absolute_list(doc["additional"]);
  absolute(doc["ego"]["vehicle_info"]);
  absolute_list(doc["params"]["files"]);
  YAML::Emitter out;
  out << doc;
  return dir.file("scenario.yaml", out.c_str());
}

// The reason of the InputError loading `path` throws ("" for none).
std::string load_error(const std::string& path) {
  try {
    (void)load_scenario(path);
  } catch (const InputError& e) {
    return e.reason();
  }
  return "";
}

// Every mapping of every_key.yaml with its place in messages ("maneuvers[1].avoid") and its table.
struct Place {
  std::string where;
  std::vector<std::string> path;  // keys and list indices (as text) from the top
  const KeyTable* table;
};
std::vector<Place> places(const YAML::Node& doc) {
  std::vector<Place> out = {{"", {}, &scenario_keys()},
                            {"ego", {"ego"}, &ego_keys()},
                            {"perception", {"perception"}, &perception_keys()},
                            {"perception.v2i", {"perception", "v2i"}, &v2i_channel_keys()},
                            {"params", {"params"}, &params_keys()},
                            {"fleet", {"fleet"}, &fleet_keys()},
                            {"obstacles[0]", {"obstacles", "0"}, &obstacle_keys()}};
  for (const char* list : {"maneuvers", "expect"}) {
    const KeyTable& kinds = std::string(list) == "maneuvers" ? maneuver_kinds() : expectation_kinds();
    for (std::size_t i = 0; i < doc[list].size(); ++i) {
      const std::string kind = doc[list][i].begin()->first.Scalar();
      if (!kinds.at(kind).table) continue;  // blinker_never, never_runs_red, arrives: no mapping
      out.push_back({std::string(list) + "[" + std::to_string(i) + "]." + kind,
                     {list, std::to_string(i), kind}, &kinds.table_of(kind)});
    }
  }
  return out;
}

YAML::Node at(YAML::Node node, const std::vector<std::string>& path) {
  for (const std::string& part : path) {
    YAML::Node next = node.IsSequence() ? node[std::stoul(part)] : node[part];
    node.reset(next);
  }
  return node;
}

std::string range_text(double min, double max) {
  std::ostringstream out;
  out << "is out of range [" << min << ", " << max << "]";
  return out.str();
}

TEST(KeyTables, TheEveryKeyFilesHoldEveryKeyOfTheTablesAndNothingElse) {
  std::set<std::string> tables, files;
  table_paths(scenario_keys(), "", tables);
  for (const std::string& file : {kEveryKey, kTakeOver}) file_paths(YAML::LoadFile(file), "", files);
  for (const std::string& path : tables) EXPECT_TRUE(files.count(path)) << path << " is in no every_key file";
  for (const std::string& path : files) EXPECT_TRUE(tables.count(path)) << path << " is in no key table";
}

TEST(KeyTables, TheLoaderReadsEveryKey) {
  Scenario s;
  ASSERT_NO_THROW(s = load_scenario(kEveryKey));
  EXPECT_TRUE(s.fleet.enabled);
  EXPECT_FALSE(s.fleet.set_signals);  // signals: observe
  EXPECT_EQ(s.fleet.vtype, "car");
  EXPECT_EQ(s.fleet.vclass, "passenger");
  EXPECT_EQ(s.fleet.id_pattern, "veh[0-9]+");
  EXPECT_EQ(s.sumo.sumo_args.size(), 2u);
  EXPECT_EQ(s.seed, 3);
  EXPECT_EQ(s.ego.depart_lane, 0);
  EXPECT_EQ(std::filesystem::path(s.ego.vehicle_info).filename(), "vehicle_info.param.yaml");
  EXPECT_EQ(s.perception.detections_per_light, 2);
  EXPECT_DOUBLE_EQ(s.perception.omission_probability, 0.05);
  ASSERT_EQ(s.perception.omissions.size(), 1u);
  EXPECT_DOUBLE_EQ(s.perception.omissions[0].end, 15.0);
  EXPECT_DOUBLE_EQ(s.v2i_channel.latency, 0.5);
  EXPECT_EQ(s.v2i_channel.blackouts.size(), 1u);
  EXPECT_DOUBLE_EQ(s.light_offsets.at("C"), 2.5);
  EXPECT_DOUBLE_EQ(s.params.number("stop_margin"), 0.5);
  EXPECT_TRUE(s.strict_params);
  ASSERT_EQ(s.lane_changes.size(), 1u);
  EXPECT_EQ(s.lane_changes[0].to_lane, 1);
  EXPECT_DOUBLE_EQ(s.lane_changes[0].approval_delay, 1.0);
  ASSERT_TRUE(s.pull_out && s.pull_over);
  EXPECT_DOUBLE_EQ(s.pull_out->at, 6.0);
  EXPECT_EQ(s.avoids.at(0).side, "left");
  EXPECT_EQ(s.expect.size(), expectation_kinds().keys.size());
  EXPECT_EQ(s.decider.kind, SutSpec::Kind::AutowareCore);
  EXPECT_EQ(s.light_judge.target, "python3 judge.py");
  EXPECT_DOUBLE_EQ(s.sut_timeout, 2.5);
  Scenario take_over;
  ASSERT_NO_THROW(take_over = load_scenario(kTakeOver));
  EXPECT_EQ(take_over.ego.id, "veh42");
}

TEST(KeyTables, AnUnknownKeyIsRefusedAtEveryLevel) {
  const TempDir dir("key-tables");
  const YAML::Node original = YAML::LoadFile(kEveryKey);
  for (const Place& place : places(original)) {
    YAML::Node doc = YAML::Clone(original);
    at(doc, place.path)["bogus"] = 1;
    const std::string key = place.where.empty() ? "bogus" : place.where + ".bogus";
    EXPECT_EQ(load_error(write_beside(dir, doc)), "unknown key '" + key + "'") << place.where;
  }
}

TEST(KeyTables, EveryNumberIsCheckedAgainstItsTablesRange) {
  const TempDir dir("key-tables");
  const YAML::Node original = YAML::LoadFile(kEveryKey);
  int checked = 0;
  for (const Place& place : places(original))
    for (const KeySpec& key : place.table->keys) {
      if ((key.type != KeyType::Number && key.type != KeyType::Integer) || !std::isfinite(key.max)) continue;
      if (!at(original, place.path)[key.name]) continue;  // (seed: not above INT_MAX in an int)
      const double above = key.max >= std::numeric_limits<int>::max() ? key.max : key.max + 1;
      if (above == key.max) continue;
      YAML::Node doc = YAML::Clone(original);
      at(doc, place.path)[key.name] = above;
      const std::string error = load_error(write_beside(dir, doc));
      const std::string name = place.where.empty() ? key.name : place.where + "." + key.name;
      EXPECT_EQ(error.rfind("key '" + name + "': value ", 0), 0u) << name << ": " << error;
      // to_s: at least from_s, not the table's minimum (the loader's rule across keys).
      const double min = key.name == "to_s" ? at(original, place.path)["from_s"].as<double>() : key.min;
      EXPECT_NE(error.find(range_text(min, key.max)), std::string::npos) << name << ": " << error;
      ++checked;
    }
  EXPECT_GT(checked, 40);
}

TEST(KeyTables, TheTopLevelKeysAreWhatOverridesSetInTheTree) {
  for (const KeySpec& key : scenario_keys().keys) EXPECT_TRUE(is_scenario_key(key.name)) << key.name;
  EXPECT_FALSE(is_scenario_key("turn_signal_search_time"));
  EXPECT_FALSE(is_scenario_key("v2i"));
}

TEST(KeyTables, KindsAreListedInTheirTablesOrder) {
  EXPECT_EQ(maneuver_kinds().names(), "lane_change, avoid, pull_out, pull_over");
  EXPECT_EQ(expectation_kinds().names(),
            "blinker_through_junction, blinker_through_lanelet, blinker_on, no_blinker, blinker_never, "
            "stops_before_light, passes_light, emergency_stop_at_light, never_in_dilemma_zone, v2i_stop_at_light, "
            "never_runs_red, lateral_offset_follows_plan, arrives");
}

TEST(KeyTables, ReadingAKeyTheTableDoesNotListIsALoaderBug) {
  const YAML::Node mapping = YAML::Load("{max_speed: 3}");
  const YamlFields fields(mapping, "f.yaml", "ego", ego_keys());
  EXPECT_THROW((void)fields.number("top_speed", 1.0, 0.0, 2.0), std::logic_error);
  EXPECT_THROW((void)fields.text("max_speed"), std::logic_error);  // a number in the table
  EXPECT_DOUBLE_EQ(fields.number("max_speed"), 3.0);
}

TEST(KeyTables, FleetModeIsOffWithoutTheKeyAndAnIdPatternMustBeARegularExpression) {
  EXPECT_FALSE(load_scenario(kTakeOver).fleet.enabled);
  const Scenario all = load_scenario(kTakeOver, {{"fleet.signals=set"}});  // what run --fleet sets
  EXPECT_TRUE(all.fleet.enabled && all.fleet.set_signals && all.fleet.id_pattern.empty());
  try {
    (void)load_scenario(kTakeOver, {{"fleet.id_pattern=veh[0-9"}});
    FAIL() << "a broken id_pattern was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("key 'fleet.id_pattern': 'veh[0-9' is not a regular expression"),
              std::string::npos)
        << e.what();
  }
}

TEST(KeyTables, AFleetVclassMustBeASumoVehicleClass) {
  EXPECT_EQ(load_scenario(kTakeOver, {{"fleet.vclass=bus"}}).fleet.vclass, "bus");
  for (const std::string& bad : {"passengr", "3", "Passenger"}) {
    try {
      (void)load_scenario(kTakeOver, {{"fleet.vclass=" + bad}});
      ADD_FAILURE() << "fleet.vclass " << bad << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("key 'fleet.vclass': '" + bad + "' is not a SUMO vClass"),
                std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace signalsim
