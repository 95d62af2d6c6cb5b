// Reading perception, the V2I channel and light offsets through their key tables.
#include "scenario/signal_reading.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <regex>
#include <string_view>

#include "scenario/input_error.hpp"
#include "scenario/scenario_keys.hpp"

namespace signalsim {
namespace {

// SUMO's vClass names (SUMOVehicleClass.cpp, 1.15 and the classes added since), so that a misspelt
// `fleet.vclass` is refused at its line instead of selecting no vehicle.
constexpr std::array<std::string_view, 34> kSumoVClasses = {
    "ignoring",   "private",    "emergency",     "authority", "army",      "vip",      "pedestrian",
    "passenger",  "hov",        "taxi",          "bus",       "coach",     "delivery", "truck",
    "trailer",    "motorcycle", "moped",         "bicycle",   "evehicle",  "tram",     "rail_urban",
    "rail",       "rail_electric", "rail_fast",  "ship",      "container", "cable_car", "subway",
    "aircraft",   "wheelchair", "scooter",       "drone",     "custom1",   "custom2"};

bool is_sumo_vclass(const std::string& name) {
  return std::find(kSumoVClasses.begin(), kSumoVClasses.end(), name) != kSumoVClasses.end();
}

// The intervals of key `name` of `f` (`blackouts`, `omissions`); `key` is its full path for messages.
std::vector<PerceptionModelParameters::Blackout> parse_intervals(YamlFields& f, const std::string& name,
                                                                 const std::string& file, const std::string& key) {
  std::vector<PerceptionModelParameters::Blackout> out;
  const YAML::Node intervals = f.node(name);
  if (!intervals || intervals.IsNull()) return out;
  if (!intervals.IsSequence()) f.fail(name, "expected a list of [start, end] pairs");
  for (const auto& pair : intervals) {
    const auto refuse = [&] {
      throw InputError(file, yaml_line(pair), "key '" + key + "': each entry is [start, end] with start <= end", key);
    };
    if (!pair.IsSequence() || pair.size() != 2) refuse();
    std::string reason;
    std::optional<double> ends[2];
    for (int k = 0; k < 2; ++k)
      if (!(ends[k] = yaml_number(pair[k], reason)))
        throw InputError(file, yaml_line(pair[k]) > 0 ? yaml_line(pair[k]) : yaml_line(pair), "key '" + key + "': " + reason,
                         key);
    if (!(*ends[0] <= *ends[1])) refuse();
    out.push_back({*ends[0], *ends[1]});
  }
  return out;
}

// `perception.v2i:` the V2I channel's faults (docs/behaviour.md §L1.7; used with v2i.use_remaining_time). The
// camera's dropout, latency and blackouts apply to it too unless given here.
V2iChannelParameters parse_v2i_channel(const YAML::Node& node, const std::string& file, V2iChannelParameters p) {
  YamlFields f(node, file, "perception.v2i", v2i_channel_keys());
  p.dropout_probability = f.number("dropout_probability", p.dropout_probability);
  p.latency = f.number("latency", p.latency);
  if (f.node("blackouts")) p.blackouts = parse_intervals(f, "blackouts", file, "perception.v2i.blackouts");
  f.finish();
  return p;
}

PerceptionModelParameters parse_perception(const YAML::Node& node, const std::string& file, V2iChannelParameters& v2i) {
  YamlFields f(node, file, "perception", perception_keys());
  PerceptionModelParameters p;
  p.detection_range = f.number("detection_range");
  p.dropout_probability = f.number("dropout_probability");
  p.latency = f.number("latency");
  p.detections_per_light = f.integer("detections_per_light");
  p.confidence_noise = f.number("confidence_noise");
  p.misclassification_probability = f.number("misclassification_probability");
  p.blackouts = parse_intervals(f, "blackouts", file, "perception.blackouts");
  p.omission_probability = f.number("omission_probability");
  p.omissions = parse_intervals(f, "omissions", file, "perception.omissions");
  v2i.dropout_probability = p.dropout_probability;
  v2i.latency = p.latency;
  v2i.blackouts = p.blackouts;
  if (const YAML::Node channel = f.node("v2i"); channel && !channel.IsNull()) v2i = parse_v2i_channel(channel, file, v2i);
  f.finish();
  return p;
}

}  // namespace

void read_signal_inputs(const YamlFields& top, const std::string& path, Scenario& s) {
  if (top.has("perception")) s.perception = parse_perception(top.node("perception"), path, s.v2i_channel);
  s.perception.seed = static_cast<std::uint64_t>(s.seed);
  s.v2i_channel.seed = static_cast<std::uint64_t>(s.seed);
  if (top.has("light_offsets")) {
    YAML::Node offsets = top.node("light_offsets");
    if (!offsets.IsMap()) top.fail("light_offsets", "expected a mapping of light id: seconds");
    reject_duplicate_keys(offsets, path, "light_offsets");
    for (const auto& entry : offsets) {
      std::string reason;
      const std::optional<double> value = yaml_number(entry.second, reason);
      if (!value)
        throw InputError(path, yaml_line(entry.first),
                         "key 'light_offsets." + entry.first.Scalar() + "': " + reason, "light_offsets." + entry.first.Scalar());
      s.light_offsets[entry.first.Scalar()] = *value;
    }
  }
}

void read_fleet(const YamlFields& top, const std::string& path, Scenario& s) {
  if (!top.has("fleet")) return;
  s.fleet.enabled = true;
  const YAML::Node node = top.node("fleet");
  if (!node || node.IsNull()) return;  // `fleet:` alone: every vehicle, signals set
  YamlFields f(node, path, "fleet", fleet_keys());
  s.fleet.vtype = f.text_or("vtype", "");
  s.fleet.vclass = f.text_or("vclass", "");
  s.fleet.id_pattern = f.text_or("id_pattern", "");
  s.fleet.set_signals = f.choice("signals") == "set";
  if (f.has("vclass") && !is_sumo_vclass(s.fleet.vclass))
    f.fail("vclass", "'" + s.fleet.vclass + "' is not a SUMO vClass (passenger, bus, truck, ...)");
  if (!s.fleet.id_pattern.empty()) {
    try {
      std::regex check(s.fleet.id_pattern, std::regex::ECMAScript);
    } catch (const std::regex_error& e) {
      f.fail("id_pattern", "'" + s.fleet.id_pattern + "' is not a regular expression (" + e.what() + ")");
    }
  }
  f.finish();
}

}  // namespace signalsim
