#include "scenario/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "scenario/countries.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"
#include "scenario/vehicle_info.hpp"
#include "sumo/number_parsing.hpp"
#include "sumo/file_paths.hpp"
#include "scenario/sumo_inputs.hpp"
#include "scenario/utf8_text.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

Blinker parse_blinker(const YamlFields& fields, const std::string& key) {
  const std::string v = fields.text(key);
  if (v == "left") return Blinker::Left;
  if (v == "right") return Blinker::Right;
  if (v == "hazard") return Blinker::Hazard;
  if (v == "none") return Blinker::None;
  fields.fail(key, "'" + v + "' is not one of left, right, hazard, none");
}

Expectation parse_expectation(const YAML::Node& item, const std::string& file, std::size_t index) {
  const std::string where = "expect[" + std::to_string(index) + "]";
  if (!item.IsMap() || item.size() != 1)
    throw InputError(file, yaml_line(item), where + ": each expectation is a one-key mapping, e.g. "
                                                    "'- blinker_never: right'");
  const std::string kind = item.begin()->first.Scalar();
  const YAML::Node body = item.begin()->second;
  if (kind == "blinker_never" || kind == "never_runs_red" || kind == "arrives") {
    if (kind != "blinker_never") {
      if (!body.IsScalar() || body.Scalar() != "true")
        throw InputError(file, yaml_line(body), where + "." + kind + ": write '" + kind + ": true'");
      if (kind == "arrives") return ExpectArrives{};
      return ExpectNeverRunsRed{};
    }
    YAML::Node wrapped;
    wrapped["blinker"] = body;
    YamlFields fields(wrapped, file, where + "." + kind);
    if (!body.IsScalar()) throw InputError(file, yaml_line(body), where + ".blinker_never: expected left, right or hazard");
    return ExpectBlinkerNever{parse_blinker(fields, "blinker")};
  }
  YamlFields fields(body, file, where + "." + kind);
  if (kind == "blinker_through_junction" || kind == "blinker_through_lanelet") {
    ExpectBlinkerThrough e;
    if (kind == "blinker_through_junction") e.junction = fields.text("junction");
    else e.lanelet = fields.text("lanelet");
    e.blinker = parse_blinker(fields, "blinker");
    e.lead = fields.required_number("lead", 0.0, 10000.0);
    fields.finish();
    return e;
  }
  if (kind == "stops_before_light") {
    ExpectStopsBeforeLight e;
    e.light = fields.text("light");
    e.tolerance = fields.number("tolerance", 0.5, 0.0, 100.0);
    fields.finish();
    return e;
  }
  if (kind == "passes_light") {
    ExpectPassesLight e;
    e.light = fields.text("light");
    fields.finish();
    return e;
  }
  if (kind == "emergency_stop_at_light") {
    ExpectEmergencyStopAtLight e;
    e.light = fields.text("light");
    fields.finish();
    return e;
  }
  if (kind == "never_in_dilemma_zone") {
    ExpectNeverInDilemmaZone e;
    e.light = fields.text("light");
    fields.finish();
    return e;
  }
  if (kind == "v2i_stop_at_light") {
    ExpectV2iStopAtLight e;
    e.light = fields.text("light");
    fields.finish();
    return e;
  }
  if (kind == "blinker_on") {
    ExpectBlinkerOn e;
    e.blinker = parse_blinker(fields, "blinker");
    e.from_s = fields.required_number("from_s", -1e6, 1e9);
    e.to_s = fields.required_number("to_s", e.from_s, 1e9);
    fields.finish();
    return e;
  }
  if (kind == "no_blinker") {
    ExpectNoBlinker e;
    e.from_s = fields.required_number("from_s", -1e6, 1e9);
    e.to_s = fields.required_number("to_s", e.from_s, 1e9);
    fields.finish();
    return e;
  }
  if (kind == "lateral_offset_follows_plan") {
    ExpectLateralFollowsPlan e;
    e.tolerance = fields.number("tolerance", 0.2, 0.0, 10.0);
    fields.finish();
    return e;
  }
  throw InputError(file, yaml_line(item.begin()->first),
                   where + ": unknown expectation '" + kind +
                       "' (known: blinker_through_junction, blinker_through_lanelet, blinker_on, no_blinker, blinker_never, "
                       "stops_before_light, passes_light, emergency_stop_at_light, never_in_dilemma_zone, "
                       "v2i_stop_at_light, never_runs_red, "
                       "lateral_offset_follows_plan, arrives)");
}

std::vector<PerceptionModelParameters::Blackout> parse_blackouts(YamlFields& f, const YAML::Node& blackouts,
                                                                 const std::string& file, const std::string& key) {
  std::vector<PerceptionModelParameters::Blackout> out;
  if (!blackouts || blackouts.IsNull()) return out;
  if (!blackouts.IsSequence()) f.fail("blackouts", "expected a list of [start, end] pairs");
  for (const auto& pair : blackouts) {
    double a = 0.0, b = 0.0;
    if (!pair.IsSequence() || pair.size() != 2 || !YAML::convert<double>::decode(pair[0], a) ||
        !YAML::convert<double>::decode(pair[1], b) || !std::isfinite(a) || !std::isfinite(b) || !(a <= b))
      throw InputError(file, yaml_line(pair), "key '" + key + "': each entry is [start, end] with start <= end");
    out.push_back({a, b});
  }
  return out;
}

// `perception.v2i:` the V2I channel's faults (docs/behaviour.md §L1.7; used with v2i.use_remaining_time). The
// camera's dropout, latency and blackouts apply to it too unless given here.
V2iChannelParameters parse_v2i_channel(const YAML::Node& node, const std::string& file, V2iChannelParameters p) {
  YamlFields f(node, file, "perception.v2i");
  p.dropout_probability = f.number("dropout_probability", p.dropout_probability, 0.0, 1.0);
  p.latency = f.number("latency", p.latency, 0.0, 60.0);
  if (const YAML::Node blackouts = f.node("blackouts"))
    p.blackouts = parse_blackouts(f, blackouts, file, "perception.v2i.blackouts");
  f.finish();
  return p;
}

PerceptionModelParameters parse_perception(const YAML::Node& node, const std::string& file, V2iChannelParameters& v2i) {
  YamlFields f(node, file, "perception");
  PerceptionModelParameters p;
  p.detection_range = f.number("detection_range", p.detection_range, 0.0, 1e9);
  p.dropout_probability = f.number("dropout_probability", 0.0, 0.0, 1.0);
  p.latency = f.number("latency", 0.0, 0.0, 60.0);
  p.detections_per_light = f.integer("detections_per_light", 1, 1, 100);
  p.confidence_noise = f.number("confidence_noise", 0.0, 0.0, 1.0);
  p.misclassification_probability = f.number("misclassification_probability", 0.0, 0.0, 1.0);
  p.blackouts = parse_blackouts(f, f.node("blackouts"), file, "perception.blackouts");
  v2i.dropout_probability = p.dropout_probability;
  v2i.latency = p.latency;
  v2i.blackouts = p.blackouts;
  if (const YAML::Node channel = f.node("v2i"); channel && !channel.IsNull()) v2i = parse_v2i_channel(channel, file, v2i);
  f.finish();
  return p;
}

// The footprint from Autoware's vehicle description; a key the scenario gives wins (and is noted).
void apply_vehicle_info(const VehicleInfo& info, int line, const std::string& path, EgoSpec& ego,
                        std::vector<std::string>& notes) {
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
      notes.push_back(path + ":" + std::to_string(ego.lines[key]) + ": ego." + key + " " + sumo::short_number(field) +
                      " replaces " + sumo::short_number(value) + " from vehicle_info " + info.file);
      continue;
    }
    field = value;
    ego.given.insert(key);  // given, through the file (a taken-over vehicle's vType must agree)
    ego.lines[key] = line;
    ego.from_vehicle_info.insert(key);
  }
  if (ego.length < 0.5 || ego.length > 30.0 || ego.width < 0.3 || ego.width > 5.0)
    throw InputError(info.file, info.lines.at("wheel_base"),
                     "the vehicle is " + sumo::short_number(ego.length) + " m x " + sumo::short_number(ego.width) +
                         " m (length 0.5-30 m, width 0.3-5 m)");
  ego.vehicle_info_unused = info.unused;
  if (!info.unused.empty()) notes.push_back(unused_parameters_note({info.file, info.unused}));
}

// Top-level scenario keys; any other override key is a parameter name.
bool is_scenario_key(const std::string& key) {
  static const char* const keys[] = {"name", "description", "net", "sumocfg", "routes", "sumo_args", "additional",
                                     "step_length", "duration",
                                     "seed", "country", "ego", "perception", "light_offsets", "params", "obstacles", "maneuvers",
                                     "expect"};
  for (const char* k : keys)
    if (key == k) return true;
  return false;
}

// Applies "--set key=value" overrides to the YAML tree; parameters are collected separately.
YAML::Node apply_overrides(YAML::Node root, const ScenarioOverrides& overrides, YAML::Node& parameters) {
  for (const std::string& item : overrides.set) {
    if (const auto bad = find_invalid_utf8(item))
      throw InputError("--set", 0, "an override is not UTF-8 text: " + describe_invalid_utf8(item, *bad));
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--set", 0, "'" + item + "' is not of the form key=value");
    const std::string key = item.substr(0, eq);
    if (eq + 1 == item.size())
      throw InputError("--set", 0, "'" + item + "': empty value (write " + key + "=VALUE)");
    YAML::Node value;
    try {
      value = YAML::Load(item.substr(eq + 1));
    } catch (const YAML::Exception& e) {
      throw InputError("--set", 0, "'" + item + "': malformed value: " + e.msg);
    }
    // A scalar rebuilt without a parse mark carries no line, so a message about it names no line of
    // the scenario file (it came from the command line).
    if (value.IsScalar()) value = YAML::Node(value.Scalar());
    const std::string head = key.substr(0, key.find('.'));
    if (!is_scenario_key(head)) {
      parameters[key] = value;
      continue;
    }
    // Walk (creating) the mapping path a.b.c and set its last element.
    YAML::Node node = root;
    std::size_t start = 0;
    while (true) {
      const std::size_t dot = key.find('.', start);
      const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
      if (dot == std::string::npos) {
        node[part] = value;
        break;
      }
      if (!node[part] || node[part].IsNull()) node[part] = YAML::Node(YAML::NodeType::Map);
      if (!node[part].IsMap()) throw InputError("--set", 0, "'" + key + "': '" + part + "' is not a mapping");
      YAML::Node child = node[part];
      node.reset(child);
      start = dot + 1;
    }
  }
  return root;
}

}  // namespace

std::string_view to_string(Blinker b) {
  switch (b) {
    case Blinker::Left: return "left";
    case Blinker::Right: return "right";
    case Blinker::Hazard: return "hazard";
    case Blinker::None: break;
  }
  return "none";
}

std::string describe(const Expectation& expectation) {
  std::ostringstream out;
  std::visit(
      [&](const auto& e) {
        using T = std::decay_t<decltype(e)>;
        if constexpr (std::is_same_v<T, ExpectBlinkerThrough>) {
          out << (e.junction.empty() ? "blinker_through_lanelet " + e.lanelet
                                     : "blinker_through_junction " + e.junction)
              << " " << to_string(e.blinker) << " lead " << e.lead;
        } else if constexpr (std::is_same_v<T, ExpectBlinkerOn>) {
          out << "blinker_on " << to_string(e.blinker) << " from_s " << e.from_s << " to_s " << e.to_s;
        } else if constexpr (std::is_same_v<T, ExpectStopsBeforeLight>) {
          out << "stops_before_light " << e.light << " tolerance " << e.tolerance;
        } else if constexpr (std::is_same_v<T, ExpectPassesLight>) {
          out << "passes_light " << e.light;
        } else if constexpr (std::is_same_v<T, ExpectEmergencyStopAtLight>) {
          out << "emergency_stop_at_light " << e.light;
        } else if constexpr (std::is_same_v<T, ExpectNeverInDilemmaZone>) {
          out << "never_in_dilemma_zone " << e.light;
        } else if constexpr (std::is_same_v<T, ExpectV2iStopAtLight>) {
          out << "v2i_stop_at_light " << e.light;
        } else if constexpr (std::is_same_v<T, ExpectLateralFollowsPlan>) {
          out << "lateral_offset_follows_plan tolerance " << e.tolerance;
        } else if constexpr (std::is_same_v<T, ExpectNeverRunsRed>) {
          out << "never_runs_red";
        } else if constexpr (std::is_same_v<T, ExpectArrives>) {
          out << "arrives";
        } else if constexpr (std::is_same_v<T, ExpectNoBlinker>) {
          out << "no_blinker from_s " << e.from_s << " to_s " << e.to_s;
        } else {
          out << "blinker_never " << to_string(e.blinker);
        }
      },
      expectation);
  return out.str();
}

Scenario load_scenario(const std::string& path, const ScenarioOverrides& overrides) {
  YAML::Node root = load_yaml_file(path, "scenario file");
  // Before the overrides walk it (fuzzing: a scalar file and --set threw yaml-cpp's own "operator[]
  // call on a scalar"; yaml-cpp turned a list file into a mapping). An empty file stays empty.
  if (root && !root.IsNull() && !root.IsMap()) YamlFields(root, path, "");
  YAML::Node parameter_overrides;
  root = apply_overrides(root, overrides, parameter_overrides);
  Scenario s;
  s.path = path;
  YamlFields top(root, path, "");
  s.name = top.text("name");
  s.description = top.text_or("description", "");
  read_simulation_keys(top, path, s);
  // The timeline is kept in memory: cap the number of steps (about 0.5 kB each).
  if (s.duration / s.step_length > 2e6)
    top.fail("duration", "duration / step_length exceeds 2 000 000 steps; shorten the run or lengthen the step");
  s.country = top.text_or("country", "");
  if (!s.country.empty() && !is_country_code(s.country)) top.fail("country", unknown_country_reason(s.country));

  if (!top.has("ego")) throw InputError(path, 0, "missing required key 'ego'");
  YamlFields ego(top.node("ego"), path, "ego");
  for (const char* key : {"id", "route", "depart_pos", "depart_speed", "max_speed", "length", "width",
                          "base_link_to_front", "accel", "decel", "emergency_decel", "depart_lane"})
    if (ego.has(key)) {
      s.ego.given.insert(key);
      s.ego.lines[key] = ego.line_of(key);
    }
  s.ego.id = ego.text_or("id", "");
  s.ego.route = ego.text_list("route");
  if (s.ego.route.empty() && s.ego.id.empty()) ego.fail("route", "the route needs at least one edge");
  s.ego.depart_pos = ego.number("depart_pos", 0.0, 0.0, 1e6);
  s.ego.depart_speed = ego.number("depart_speed", 0.0, 0.0, 100.0);
  s.ego.max_speed = ego.number("max_speed", 13.89, 0.1, 100.0);
  s.ego.length = ego.number("length", 4.5, 0.5, 30.0);
  s.ego.width = ego.number("width", 1.8, 0.3, 5.0);
  s.ego.base_link_to_front = ego.number("base_link_to_front", kBaseLinkShare * s.ego.length, 0.0, 30.0);
  // params.strict is read here already: it applies to the vehicle description too.
  const YAML::Node& const_root = root;  // (a lookup through a non-const node would add the key)
  const YAML::Node params_node = const_root["params"];
  if (params_node && params_node.IsMap() && params_node["strict"]) {
    const YAML::Node strict = params_node["strict"];
    if (!(strict.IsScalar() && YAML::convert<bool>::decode(strict, s.strict_params)))
      throw InputError(path, yaml_line(strict), "key 'params.strict': expected true or false");
  }
  if (ego.has("vehicle_info"))
    apply_vehicle_info(load_vehicle_info(sumo::resolve_beside(path, ego.text("vehicle_info")), s.strict_params),
                       ego.line_of("vehicle_info"), path, s.ego, s.notes);
  if (s.ego.base_link_to_front > s.ego.length) {
    if (s.ego.from_vehicle_info.count("base_link_to_front"))
      ego.fail("length", sumo::short_number(s.ego.length) + " m is shorter than base_link_to_front " +
                             sumo::short_number(s.ego.base_link_to_front) + " m from vehicle_info " + s.ego.vehicle_info);
    ego.fail("base_link_to_front", "is longer than the vehicle (ego.length)");
  }
  s.ego.accel = ego.number("accel", 1.0, 0.1, 10.0);
  s.ego.decel = ego.number("decel", 1.0, 0.1, 10.0);
  s.ego.emergency_decel = ego.number("emergency_decel", 9.0, 1.0, 15.0);
  if (s.ego.depart_speed > s.ego.max_speed) ego.fail("depart_speed", "exceeds ego.max_speed");
  s.ego.depart_lane = ego.integer("depart_lane", -1, -1, 100);
  // A taken-over vehicle departs as its route file says (docs/sumo.md); the keys SUMO's definition
  // already fixes may only repeat it (checked against SUMO once it departed, scenario/take_over).
  if (!s.ego.id.empty())
    for (const char* key : {"depart_pos", "depart_speed", "depart_lane"})
      if (ego.has(key))
        ego.fail(key, "vehicle '" + s.ego.id + "' (ego.id) departs as its route file says; remove ego." + key);
  ego.finish();

  const YAML::Node obstacles = top.node("obstacles");
  if (obstacles && !obstacles.IsNull()) {
    if (!obstacles.IsSequence()) top.fail("obstacles", "expected a list of obstacles");
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      YamlFields fields(obstacles[i], path, "obstacles[" + std::to_string(i) + "]");
      ObstacleSpec o;
      o.id = fields.text("id");
      o.edge = fields.text("edge");
      o.lane = fields.integer("lane", 0, 0, 100);
      o.pos = fields.required_number("pos", 0.0, 1e6);
      o.length = fields.number("length", 4.5, 0.5, 30.0);
      fields.finish();
      for (const ObstacleSpec& other : s.obstacles)
        if (other.id == o.id) fields.fail("id", "'" + o.id + "' is declared twice");
      s.obstacles.push_back(o);
    }
  }
  const YAML::Node maneuvers = top.node("maneuvers");
  if (maneuvers && !maneuvers.IsNull()) {
    if (!maneuvers.IsSequence()) top.fail("maneuvers", "expected a list of maneuvers");
    for (std::size_t i = 0; i < maneuvers.size(); ++i) {
      const YAML::Node item = maneuvers[i];
      const std::string where = "maneuvers[" + std::to_string(i) + "]";
      if (!item.IsMap() || item.size() != 1)
        throw InputError(path, yaml_line(item), where + ": each maneuver is a one-key mapping, e.g. "
                                                        "'- lane_change: {at: 40, length: 50}'");
      const std::string kind = item.begin()->first.Scalar();
      if (kind == "avoid") {
        YamlFields fields(item.begin()->second, path, where + ".avoid");
        AvoidManeuver a;
        a.obstacle = fields.text("obstacle");
        a.clearance = fields.number("clearance", 1.0, 0.0, 10.0);
        a.side = fields.text_or("side", "auto");
        if (a.side != "auto" && a.side != "left" && a.side != "right")
          fields.fail("side", "'" + a.side + "' is not one of auto, left, right");
        a.length = fields.number("length", 0.0, 0.0, 10000.0);
        fields.finish();
        s.avoids.push_back(a);
        continue;
      }
      if (kind == "pull_out") {
        if (s.pull_out) throw InputError(path, yaml_line(item), where + ": at most one pull_out");
        YamlFields fields(item.begin()->second, path, where + ".pull_out");
        PullOutManeuver m;
        m.offset = fields.required_number("offset", -10.0, 10.0);
        m.length = fields.number("length", 30.0, 1.0, 10000.0);
        m.at = fields.number("at", -1.0, 0.0, 1e6);
        m.backward = fields.number("backward", 0.0, 0.0, 1000.0);
        fields.finish();
        s.pull_out = m;
        continue;
      }
      if (kind == "pull_over") {
        if (s.pull_over) throw InputError(path, yaml_line(item), where + ": at most one pull_over");
        YamlFields fields(item.begin()->second, path, where + ".pull_over");
        PullOverManeuver m;
        m.edge = fields.text("edge");
        m.pos = fields.required_number("pos", 0.0, 1e6);
        m.offset = fields.required_number("offset", -10.0, 10.0);
        m.length = fields.number("length", 30.0, 1.0, 10000.0);
        fields.finish();
        s.pull_over = m;
        continue;
      }
      if (kind != "lane_change")
        throw InputError(path, yaml_line(item.begin()->first),
                         where + ": unknown maneuver '" + kind + "' (known: lane_change, avoid, pull_out, pull_over)");
      YamlFields fields(item.begin()->second, path, where + ".lane_change");
      LaneChangeManeuver m;
      m.edge = fields.text_or("edge", "");
      if (!m.edge.empty()) m.to_lane = static_cast<int>(fields.required_number("to_lane", 0.0, 63.0));
      m.at = fields.required_number("at", 0.0, 1e6);
      m.length = fields.number("length", kDefaultLaneChangeLength, 1.0, 10000.0);
      m.approval_delay = fields.number("approval_delay", 0.0, 0.0, 3600.0);
      fields.finish();
      for (const LaneChangeManeuver& other : s.lane_changes)
        if (other.edge == m.edge)
          throw InputError(path, yaml_line(item), where + ": a second lane_change on " +
                                                      (m.edge.empty() ? std::string("the first edge") : "edge '" + m.edge + "'") +
                                                      " (at most one per edge)");
      s.lane_changes.push_back(m);
    }
  }

  if (top.has("perception")) s.perception = parse_perception(top.node("perception"), path, s.v2i_channel);
  s.perception.seed = static_cast<std::uint64_t>(s.seed);
  s.v2i_channel.seed = static_cast<std::uint64_t>(s.seed);
  if (top.has("light_offsets")) {
    YAML::Node offsets = top.node("light_offsets");
    if (!offsets.IsMap()) top.fail("light_offsets", "expected a mapping of light id: seconds");
    for (const auto& entry : offsets) {
      double value = 0.0;
      if (!entry.second.IsScalar() || !YAML::convert<double>::decode(entry.second, value) || !std::isfinite(value))
        throw InputError(path, yaml_line(entry.second),
                         "key 'light_offsets." + entry.first.Scalar() + "': expected a number of seconds");
      s.light_offsets[entry.first.Scalar()] = value;
    }
  }

  // Parameters: defaults, params.files, the country preset, params.set, then --set overrides.
  YAML::Node set;
  if (top.has("params")) {
    YamlFields params(top.node("params"), path, "params");
    // strict: every key of a parameter file must be one signalsim uses (else they are listed).
    (void)params.node("strict");  // read with the ego (it applies to ego.vehicle_info too)
    for (const std::string& file : params.text_list("files"))
      s.params.apply_file(sumo::resolve_beside(path, file), s.strict_params);
    const YAML::Node given = params.node("set");
    if (given) set.reset(given);  // (assigning an absent node would throw)
    params.finish();
  }
  if (!s.country.empty()) {
    const Country country = load_country(s.country);
    s.params.apply(country.parameters, ParameterOrigin{country.path, "country " + country.code});
  }
  if (set && !set.IsNull()) s.params.apply(set, ParameterOrigin{path, "set"});
  if (parameter_overrides.size() > 0) s.params.apply(parameter_overrides, ParameterOrigin{"--set", "--set"});
  s.params.check_consistency(path);
  for (const UnusedParameters& file : s.params.unused()) s.notes.push_back(unused_parameters_note(file));

  const YAML::Node expect = top.node("expect");
  if (expect && !expect.IsNull()) {
    if (!expect.IsSequence()) top.fail("expect", "expected a list of expectations");
    for (std::size_t i = 0; i < expect.size(); ++i) {
      s.expect.push_back(parse_expectation(expect[i], path, i));
      s.expect_lines.push_back(yaml_line(expect[i]));
    }
  }
  top.finish();
  for (const std::string& note : s.notes) note_once(note);  // the scenario loaded: say what it ignored
  return s;
}

}  // namespace signalsim
