// Reading expectations through their key tables, and describing them in one line.
#include "scenario/expectation_reading.hpp"

#include <sstream>

#include "scenario/input_error.hpp"
#include "scenario/scenario_keys.hpp"

namespace signalsim {
namespace {

Blinker parse_blinker(const YamlFields& fields, const std::string& key) {
  const std::string v = fields.choice(key);
  if (v == "left") return Blinker::Left;
  if (v == "right") return Blinker::Right;
  if (v == "hazard") return Blinker::Hazard;
  return Blinker::None;
}

// `- blinker_never: right`: the value read as the key `blinker` of a mapping of its own.
const KeyTable& blinker_never_keys() {
  static const KeyTable table = [] {
    KeySpec blinker = as_required(expectation_kinds().at("blinker_never"));
    blinker.name = "blinker";
    return KeyTable{"expect[].blinker_never", "", {blinker}};
  }();
  return table;
}

Expectation read_light_expectation(const std::string& kind, const YamlFields& fields) {
  const std::string light = fields.text("light");
  if (kind == "stops_before_light") {
    ExpectStopsBeforeLight e;
    e.light = light;
    e.tolerance = fields.number("tolerance");
    fields.finish();
    return e;
  }
  fields.finish();
  if (kind == "passes_light") return ExpectPassesLight{light};
  if (kind == "emergency_stop_at_light") return ExpectEmergencyStopAtLight{light};
  if (kind == "never_in_dilemma_zone") return ExpectNeverInDilemmaZone{light};
  return ExpectV2iStopAtLight{light};
}

Expectation parse_expectation(const YAML::Node& item, const std::string& file, std::size_t index) {
  const std::string where = "expect[" + std::to_string(index) + "]";
  if (!item.IsMap() || item.size() != 1)
    throw InputError(file, yaml_line(item), where + ": each expectation is a one-key mapping, e.g. "
                                                    "'- blinker_never: right'", where);
  const std::string kind = item.begin()->first.Scalar();
  const YAML::Node body = item.begin()->second;
  const KeyTable& kinds = expectation_kinds();
  if (kind == "blinker_never" || kind == "never_runs_red" || kind == "arrives") {
    if (kind != "blinker_never") {
      if (!body.IsScalar() || body.Scalar() != "true")
        throw InputError(file, yaml_line(body), where + "." + kind + ": write '" + kind + ": true'", where);
      if (kind == "arrives") return ExpectArrives{};
      return ExpectNeverRunsRed{};
    }
    YAML::Node wrapped;
    wrapped["blinker"] = body;
    YamlFields fields(wrapped, file, where + "." + kind, blinker_never_keys());
    if (!body.IsScalar())
      throw InputError(file, yaml_line(body), where + ".blinker_never: expected left, right or hazard", where);
    try {
      return ExpectBlinkerNever{parse_blinker(fields, "blinker")};
    } catch (const InputError& e) {  // the wrapping mapping has no lines: the value's
      throw InputError(file, yaml_line(body), e.reason(), e.key());
    }
  }
  if (!kinds.find(kind)) {
    (void)YamlFields(body, file, where + "." + kind);  // a body that is no mapping is reported first
    throw InputError(file, yaml_line(item.begin()->first),
                     where + ": unknown expectation '" + kind + "' (known: " + kinds.names() + ")", where);
  }
  YamlFields fields(body, file, where + "." + kind, kinds.table_of(kind));
  if (kind == "blinker_through_junction" || kind == "blinker_through_lanelet") {
    ExpectBlinkerThrough e;
    if (kind == "blinker_through_junction") e.junction = fields.text("junction");
    else e.lanelet = fields.text("lanelet");
    e.blinker = parse_blinker(fields, "blinker");
    e.lead = fields.required_number("lead");
    fields.finish();
    return e;
  }
  if (kind == "blinker_on") {
    ExpectBlinkerOn e;
    e.blinker = parse_blinker(fields, "blinker");
    e.from_s = fields.required_number("from_s");
    e.to_s = fields.required_number("to_s", e.from_s, kinds.table_of(kind).at("to_s").max);
    fields.finish();
    return e;
  }
  if (kind == "no_blinker") {
    ExpectNoBlinker e;
    e.from_s = fields.required_number("from_s");
    e.to_s = fields.required_number("to_s", e.from_s, kinds.table_of(kind).at("to_s").max);
    fields.finish();
    return e;
  }
  if (kind == "lateral_offset_follows_plan") {
    ExpectLateralFollowsPlan e;
    e.tolerance = fields.number("tolerance");
    fields.finish();
    return e;
  }
  return read_light_expectation(kind, fields);
}

}  // namespace

void read_expectations(const YamlFields& top, const std::string& path, Scenario& s) {
  const YAML::Node expect = top.node("expect");
  if (!expect || expect.IsNull()) return;
  if (!expect.IsSequence()) top.fail("expect", "expected a list of expectations");
  for (std::size_t i = 0; i < expect.size(); ++i) s.expect.push_back(parse_expectation(expect[i], path, i));
}

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

}  // namespace signalsim
