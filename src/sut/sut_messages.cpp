// The JSON-lines messages and replies; see sut_messages.hpp.
#include "sut/sut_messages.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace signalsim {
namespace {

using Json = nlohmann::ordered_json;

// NaN and infinities have no JSON number: null.
Json number(double value) { return std::isfinite(value) ? Json(value) : Json(nullptr); }

std::string_view hazard_text(HazardLights h) {
  if (h == HazardLights::Enable) return "enable";
  if (h == HazardLights::Disable) return "disable";
  return "no_command";
}

Json lanelet_json(const Lanelet& l) {
  Json centerline = Json::array();
  for (const Vec2& p : l.shape.points()) centerline.push_back(Json::array({p.x, p.y}));
  Json successors = Json::array();
  for (TurnDirection d : l.successor_turn_directions) successors.push_back(to_string(d));
  Json tags = Json::object();
  for (const auto& [key, value] : l.params) tags[key] = value;
  return Json{{"id", l.lane_id},
              {"edge", l.edge_id},
              {"junction", l.junction_id},
              {"s_start", l.s_start},
              {"s_end", l.s_end()},
              {"length", l.length},
              {"speed_limit", l.speed_limit},
              {"turn_direction", to_string(l.turn_direction)},
              {"successor_turns", std::move(successors)},
              {"roundabout_role", to_string(l.roundabout_role)},
              {"roundabout_id", l.roundabout_id},
              {"leaves_ring_at_end", l.leaves_ring_at_end},
              {"turn_signal_distance", l.turn_signal_distance ? number(*l.turn_signal_distance) : Json(nullptr)},
              {"tags", std::move(tags)},
              {"centerline", std::move(centerline)}};
}

Json light_json(const SutLight& light) {
  Json elements = Json::array();
  for (const SignalElement& e : light.elements)
    elements.push_back({{"color", to_string(e.color)},
                        {"shape", to_string(e.shape)},
                        {"status", to_string(e.status)},
                        {"confidence", number(e.confidence)}});
  return Json{{"tls_id", light.tls_id},
              {"link_index", light.link_index},
              {"lanelet_index", light.route_index},
              {"stop_line_s", light.stop_line_s},
              {"distance", light.distance},
              {"delivered", light.delivered},
              {"elements", std::move(elements)},
              {"time_to_red", light.time_to_red ? number(*light.time_to_red) : Json(nullptr)}};
}

std::string line_of(const Json& message) { return message.dump() + "\n"; }

// The start of a reply for a message (at most 80 characters).
std::string excerpt(const std::string& line) { return line.size() > 80 ? line.substr(0, 77) + "..." : line; }

Json parse_object(const std::string& line) {
  Json reply = Json::parse(line, nullptr, false);
  if (reply.is_discarded()) throw SutReplyError("reply is not JSON: " + excerpt(line));
  if (!reply.is_object()) throw SutReplyError("reply is not a JSON object: " + excerpt(line));
  return reply;
}

}  // namespace

std::string sut_hello_message(const SutRun& run, std::string_view role) {
  Json parameters = Json::object();
  for (const auto& [name, value] : run.parameters) parameters[name] = value;
  Json lanelets = Json::array();
  if (run.route)
    for (const Lanelet& l : run.route->lanelets()) lanelets.push_back(lanelet_json(l));
  Json shift_lines = Json::array();
  for (const SutShiftLine& s : run.shift_lines)
    shift_lines.push_back(
        {{"module", to_string(s.module)}, {"edge", s.edge_id}, {"s_start", s.s_start}, {"s_end", s.s_end}, {"shift", s.shift}});
  return line_of(Json{{"type", "hello"},
                      {"protocol", kSutProtocolVersion},
                      {"role", role},
                      {"scenario", run.scenario},
                      {"step_length", run.step_length},
                      {"vehicle_length", run.vehicle_length},
                      {"base_link_to_front", run.base_link_to_front},
                      {"parameters", std::move(parameters)},
                      {"lanelets", std::move(lanelets)},
                      {"shift_lines", std::move(shift_lines)}});
}

std::string sut_step_message(const SutStep& step, const RouteMap& route) {
  Json window_ids = Json::array();
  for (std::size_t i = step.window.first; i < step.window.last && i < route.size(); ++i)
    window_ids.push_back(route.at(i).lane_id);
  const TurnSignalInfo& r = step.request;
  Json lights = Json::array();
  for (const SutLight& l : step.lights) lights.push_back(light_json(l));
  const SutEgo& e = step.ego;
  return line_of(Json{
      {"type", "step"},
      {"time", step.time},
      {"ego",
       {{"x", e.x}, {"y", e.y}, {"yaw", e.yaw}, {"speed", e.speed}, {"accel", e.accel}, {"s_front", e.s_front}, {"s_base", e.s_base}}},
      {"window", {{"first", step.window.first}, {"last", step.window.last}, {"lanelets", std::move(window_ids)}}},
      {"request",
       {{"module", to_string(r.source)},
        {"turn", to_string(r.turn)},
        {"hazard", hazard_text(r.hazard)},
        {"desired_start", r.desired_start},
        {"desired_end", r.desired_end},
        {"required_start", r.required_start},
        {"required_end", r.required_end}}},
      {"lights", std::move(lights)}});
}

std::string sut_bye_message() { return line_of(Json{{"type", "bye"}}); }

Blinker parse_decider_reply(const std::string& line) {
  const Json reply = parse_object(line);
  const auto it = reply.find("blinker");
  if (it == reply.end()) throw SutReplyError("reply lacks 'blinker': " + excerpt(line));
  if (it->is_string()) {
    const std::string& b = it->get_ref<const std::string&>();
    if (b == "none") return Blinker::None;
    if (b == "left") return Blinker::Left;
    if (b == "right") return Blinker::Right;
    if (b == "hazard") return Blinker::Hazard;
  }
  throw SutReplyError("reply's 'blinker' is " + excerpt(it->dump()) + ", not \"none\", \"left\", \"right\" or \"hazard\"");
}

std::vector<SutLightAnswer> parse_light_judge_reply(const std::string& line, const SutStep& step) {
  const Json reply = parse_object(line);
  const auto it = reply.find("lights");
  if (it == reply.end()) throw SutReplyError("reply lacks 'lights': " + excerpt(line));
  if (!it->is_array() || it->size() != step.lights.size())
    throw SutReplyError("reply's 'lights' is not an array of " + std::to_string(step.lights.size()) +
                        " answer(s), one per light of the step: " + excerpt(line));
  std::vector<SutLightAnswer> answers;
  for (std::size_t i = 0; i < step.lights.size(); ++i) {
    const Json& a = (*it)[i];
    const std::string at = "reply's lights[" + std::to_string(i) + "]";
    if (!a.is_object()) throw SutReplyError(at + " is not an object");
    const auto id = a.find("tls_id");
    if (id == a.end() || !id->is_string() || id->get<std::string>() != step.lights[i].tls_id)
      throw SutReplyError(at + " lacks 'tls_id' \"" + step.lights[i].tls_id + "\" (answers follow the step's lights)");
    const auto decision = a.find("decision");
    const bool stop = decision != a.end() && *decision == "stop";
    if (decision == a.end() || (!stop && *decision != "go"))
      throw SutReplyError(at + " lacks 'decision' \"stop\" or \"go\"");
    const auto reason = a.find("reason");
    if (reason != a.end() && !reason->is_string()) throw SutReplyError(at + "'s 'reason' is not a string");
    answers.push_back({stop, reason == a.end() ? std::string() : reason->get<std::string>()});
  }
  return answers;
}

}  // namespace signalsim
