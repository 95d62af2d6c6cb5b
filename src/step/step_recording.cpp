// Writing, reading and replaying a run's recorded steps; see step_recording.hpp.
#include "step/step_recording.hpp"

#include <istream>
#include <ostream>

#include <nlohmann/json.hpp>

#include "scenario/input_error.hpp"

namespace signalsim {
namespace sumo {

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(EgoState, time, edge, lane, lane_pos, speed, accel, x, y, lateral_offset)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LightTiming, program, phase, next_switch)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LightPhase, duration, state, next)
NLOHMANN_JSON_SERIALIZE_ENUM(ProgramKind, {{ProgramKind::Other, "other"},
                                           {ProgramKind::Static, "static"},
                                           {ProgramKind::Actuated, "actuated"},
                                           {ProgramKind::DelayBased, "delay_based"}})
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LightProgram, id, kind, phases)

}  // namespace sumo

NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LeaderInfo, id, gap)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(LateralCommand, offset, reference_lane)
// A lateral command as null or the value.
void to_json(nlohmann::json& j, const std::optional<LateralCommand>& v) {
  j = v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}
void from_json(const nlohmann::json& j, std::optional<LateralCommand>& v) {
  v = j.is_null() ? std::nullopt : std::optional<LateralCommand>(j.get<LateralCommand>());
}
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(Commands, drive, right_of_way, lane_limits, emergency_braking, signal_mask, speed,
                                   lateral, move_back)
NLOHMANN_DEFINE_TYPE_NON_INTRUSIVE(StepFeedback, alive, signals, time)

namespace {

using nlohmann::json;

// An optional as null or the value (nlohmann has no std::optional conversion of its own).
template <class T>
json optional_json(const std::optional<T>& v) {
  return v ? json(*v) : json(nullptr);
}

template <class T>
std::optional<T> optional_of(const json& j, const char* key) {
  if (!j.contains(key) || j.at(key).is_null()) return std::nullopt;
  return j.at(key).get<T>();
}

json observation_json(const StepObservation& o) {
  json lights = json::array();
  for (const LightReading& l : o.lights)
    lights.push_back({{"tls_id", l.tls_id},
                      {"state", l.state},
                      {"timing", optional_json(l.timing)},
                      {"programs", optional_json(l.programs)}});
  json traffic = json::array();
  for (const sumo::SumoSession::LaneVehicle& v : o.lane_traffic)
    traffic.push_back({{"id", v.id}, {"pos", v.pos}, {"length", v.length}});
  json out = {{"ego", o.ego},         {"lateral_offset", optional_json(o.lateral_offset)},
              {"lights", lights},     {"lane_traffic", traffic},
              {"leader", optional_json(o.leader)}, {"signals", optional_json(o.signals)}};
  if (!o.ego_parameters.empty()) out["ego_parameters"] = o.ego_parameters;  // a traci light judge's only
  return out;
}

StepObservation observation_of(const json& j) {
  StepObservation o;
  o.ego = j.at("ego").get<sumo::EgoState>();
  o.lateral_offset = optional_of<double>(j, "lateral_offset");
  for (const json& l : j.at("lights"))
    o.lights.push_back({l.at("tls_id").get<std::string>(), l.at("state").get<std::string>(),
                        optional_of<sumo::LightTiming>(l, "timing"),
                        optional_of<std::vector<sumo::LightProgram>>(l, "programs")});
  for (const json& v : j.at("lane_traffic"))
    o.lane_traffic.push_back({v.at("id").get<std::string>(), v.at("pos").get<double>(), v.at("length").get<double>()});
  o.leader = optional_of<LeaderInfo>(j, "leader");
  o.signals = optional_of<int>(j, "signals");
  if (j.contains("ego_parameters"))
    o.ego_parameters = j.at("ego_parameters").get<std::vector<std::pair<std::string, std::string>>>();
  return o;
}

}  // namespace

namespace {

// One line of JSON; text that is not UTF-8 (a SUMO id) is written with replacement characters.
std::string line_of(const nlohmann::json& j) { return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace); }

}  // namespace

void write_recording_header(std::ostream& out, const CoreSetup& setup) {
  std::vector<bool> arrows;
  for (const sumo::ApproachLight& light : setup.lights) arrows.push_back(light.has_arrow);
  out << line_of({{"format", "signalsim-steps"},
                  {"version", kStepRecordingVersion},
                  {"start_time", setup.start_time},
                  {"arrows", arrows}})
      << '\n';
}

RunRecord RecordingCore::finish(int collisions) {
  out_ << line_of({{"collisions", collisions}}) << '\n';
  return inner_.finish(collisions);
}

Commands RecordingCore::step(const StepObservation& seen) {
  last_ = inner_.step(seen);
  return last_;
}

bool RecordingCore::record(const StepObservation& seen, const StepFeedback& feedback) {
  out_ << line_of({{"observation", observation_json(seen)}, {"commands", last_}, {"feedback", feedback}}) << '\n';
  return inner_.record(seen, feedback);
}

StepRecording read_step_recording(std::istream& in, const std::string& source) {
  StepRecording recording;
  recording.source = source;
  std::string line;
  int number = 0;
  bool header = false;
  try {
    while (std::getline(in, line)) {
      ++number;
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const json j = json::parse(line);
      if (!header) {
        if (!j.is_object() || j.value("format", "") != "signalsim-steps" || j.value("version", 0) != kStepRecordingVersion)
          throw InputError(source, number,
                           "not a signalsim-steps recording of version " + std::to_string(kStepRecordingVersion));
        recording.start_time = j.at("start_time").get<double>();
        recording.arrows = j.at("arrows").get<std::vector<bool>>();
        header = true;
      } else if (j.contains("collisions")) {
        recording.collisions = j.at("collisions").get<int>();
      } else {
        recording.steps.push_back({observation_of(j.at("observation")), j.at("commands").get<Commands>(),
                                   j.at("feedback").get<StepFeedback>()});
      }
    }
  } catch (const json::exception& e) {
    throw InputError(source, number, std::string("not a recorded step: ") + e.what());
  }
  if (!header) throw InputError(source, 0, "empty, not a signalsim-steps recording");
  return recording;
}

std::vector<sumo::ApproachLight> with_recorded_arrows(std::vector<sumo::ApproachLight> lights,
                                                      const StepRecording& recording) {
  if (lights.size() != recording.arrows.size())
    throw InputError(recording.source, 1,
                     "recorded with " + std::to_string(recording.arrows.size()) + " approach lights, the route has " +
                         std::to_string(lights.size()));
  for (std::size_t i = 0; i < lights.size(); ++i) lights[i].has_arrow = recording.arrows[i];
  return lights;
}

std::string unrecorded(const ObservationDemand& want, const StepObservation& seen) {
  for (const LightDemand& light : want.lights) {
    const LightReading* reading = seen.light(light.tls_id);
    if (!reading) return "light " + light.tls_id;
    if (light.timing && !reading->timing) return "the timing of light " + light.tls_id;
    if (light.programs && !reading->programs) return "the programs of light " + light.tls_id;
  }
  if (want.lateral_reference_lane && !seen.lateral_offset)
    return "the lateral offset from " + *want.lateral_reference_lane;
  if (want.signals && !seen.signals) return "the signal mask";
  if (want.ego_parameters.size() > seen.ego_parameters.size()) return "the ego's parameters";
  return "";
}

Replay replay(RunCore& core, const StepRecording& recording) {
  Replay out;
  for (const RecordedStep& step : recording.steps) {
    const ObservationDemand want = core.demand(step.observation.ego);
    if (const std::string missing = unrecorded(want, step.observation); !missing.empty()) {
      out.unrecorded = "step " + std::to_string(out.steps) + " at " + std::to_string(step.observation.ego.time) +
                       " s: the core asks for " + missing + ", which the recording does not hold";
      break;
    }
    const Commands commands = core.step(step.observation);
    if (!out.first_different_commands && !(commands == step.commands)) out.first_different_commands = out.steps;
    ++out.steps;
    if (core.record(step.observation, step.feedback)) break;
  }
  out.record = core.finish(recording.collisions);
  return out;
}

}  // namespace signalsim
