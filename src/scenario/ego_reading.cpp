// Reading the ego: its keys through ego_keys, then the footprint from ego.vehicle_info.
#include "scenario/ego_reading.hpp"

#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"
#include "scenario/scenario_keys.hpp"
#include "scenario/vehicle_info.hpp"
#include "core/file_paths.hpp"
#include "core/number_parsing.hpp"

namespace signalsim {
namespace {

// The footprint from Autoware's vehicle description; a key the scenario gives wins (and is noted).
void apply_vehicle_info(const VehicleInfo& info, int line, const std::string& path, EgoSpec& ego,
                        std::vector<std::string>& notes, std::vector<std::string>& warnings) {
  ego.vehicle_info = info.file;
  const struct {
    const char* key;
    double value;
    double& field;
  } derived[] = {{"length", info.length(), ego.length},
                 {"width", info.width(), ego.width},
                 {"base_link_to_front", info.base_link_to_front(), ego.base_link_to_front}};
  for (const auto& [key, value, field] : derived) {
    if (ego.given.count(key)) {
      notes.push_back(path + ":" + std::to_string(ego.lines[key]) + ": ego." + key + " " + short_number(field) +
                      " replaces " + short_number(value) + " from vehicle_info " + info.file);
      continue;
    }
    field = value;
    ego.given.insert(key);  // given, through the file (a taken-over vehicle's vType must agree)
    ego.lines[key] = line;
    ego.from_vehicle_info.insert(key);
  }
  if (ego.length < 0.5 || ego.length > 30.0 || ego.width < 0.3 || ego.width > 5.0)
    throw InputError(info.file, info.lines.at("wheel_base"),
                     "the vehicle is " + short_number(ego.length) + " m x " + short_number(ego.width) +
                         " m (length 0.5-30 m, width 0.3-5 m)");
  ego.vehicle_info_unused = info.unused;
  if (!info.unused.empty()) notes.push_back(unused_parameters_note({info.file, info.unused}));
  warnings.insert(warnings.end(), info.warnings.begin(), info.warnings.end());
}

// params.strict, read before params: it applies to the vehicle description too.
bool strict_params(const YAML::Node& root, const std::string& path) {
  bool strict = false;
  const YAML::Node& const_root = root;  // (a lookup through a non-const node would add the key)
  const YAML::Node params_node = const_root["params"];
  if (params_node && params_node.IsMap() && params_node["strict"]) {
    const YAML::Node given = params_node["strict"];
    if (!(given.IsScalar() && YAML::convert<bool>::decode(given, strict)))
      throw InputError(path, yaml_line(given), "key 'params.strict': expected true or false", "params.strict");
  }
  return strict;
}

}  // namespace

void read_ego(const YamlFields& top, const YAML::Node& root, const std::string& path, Scenario& s) {
  if (!top.has("ego") && top.has("fleet")) {  // an egoless fleet run (docs/fleet.md "Without an ego")
    s.has_ego = false;
    s.strict_params = strict_params(root, path);
    return;
  }
  if (!top.has("ego")) throw InputError(path, 0, "missing required key 'ego'");
  YamlFields ego(top.node("ego"), path, "ego", ego_keys());
  for (const KeySpec& key : ego_keys().keys)  // what the scenario gave (vehicle_info is not a value)
    if (key.name != "vehicle_info" && ego.has(key.name)) {
      s.ego.given.insert(key.name);
      s.ego.lines[key.name] = ego.line_of(key.name);
    }
  s.ego.id = ego.text_or("id");
  s.ego.route = ego.text_list("route");
  if (s.ego.route.empty() && s.ego.id.empty()) ego.fail("route", "the route needs at least one edge");
  s.ego.depart_pos = ego.number("depart_pos");
  s.ego.depart_speed = ego.number("depart_speed");
  s.ego.max_speed = ego.number("max_speed");
  s.ego.length = ego.number("length");
  s.ego.width = ego.number("width");
  s.ego.base_link_to_front = ego.number("base_link_to_front", vehicle_defaults::kBaseLinkShare * s.ego.length);
  s.strict_params = strict_params(root, path);
  if (ego.has("vehicle_info")) {
    const std::string file = resolve_beside(path, ego.text("vehicle_info"));
    if (const std::string problem = input_file_problem(file); !problem.empty())
      ego.fail("vehicle_info", "vehicle_info file '" + file + "' " + problem);
    apply_vehicle_info(load_vehicle_info(file, s.strict_params), ego.line_of("vehicle_info"), path, s.ego, s.notes,
                       s.warnings);
  }
  if (s.ego.base_link_to_front > s.ego.length) {
    if (s.ego.from_vehicle_info.count("base_link_to_front"))
      ego.fail("length", short_number(s.ego.length) + " m is shorter than base_link_to_front " +
                             short_number(s.ego.base_link_to_front) + " m from vehicle_info " + s.ego.vehicle_info);
    ego.fail("base_link_to_front", "is longer than the vehicle (ego.length)");
  }
  s.ego.accel = ego.number("accel");
  s.ego.decel = ego.number("decel");
  s.ego.emergency_decel = ego.number("emergency_decel");
  if (s.ego.depart_speed > s.ego.max_speed) ego.fail("depart_speed", "exceeds ego.max_speed");
  s.ego.depart_lane = ego.integer("depart_lane");
  // A taken-over vehicle departs as its route file says (docs/sumo.md); the keys SUMO's definition
  // already fixes may only repeat it (checked against SUMO once it departed, scenario/take_over).
  if (!s.ego.id.empty())
    for (const char* key : {"depart_pos", "depart_speed", "depart_lane"})
      if (ego.has(key))
        ego.fail(key, "vehicle '" + s.ego.id + "' (ego.id) departs as its route file says; remove ego." + key);
  ego.finish();
}

void refuse_ego_only_keys(const YamlFields& top) {
  static const char* const kEgoOnly[] = {"obstacles", "maneuvers", "perception", "decider", "light_judge", "expect"};
  for (const char* key : kEgoOnly)
    if (top.has(key))
      top.fail(key, std::string("is about the ego, and the scenario has none (fleet: without ego:, docs/fleet.md "
                                "\"Without an ego\"); give an ego or remove ") + key);
}

}  // namespace signalsim
