// The JSON-lines messages as written (hello, step, bye: one compact object per line, numbers that
// read back exactly) and the replies as parsed, each refusal with its reason.
#include "sut/sut_messages.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace signalsim {
namespace {

using nlohmann::json;

RouteMap two_lanelets() {
  Lanelet a;
  a.lane_id = "in_0";
  a.edge_id = "in";
  a.length = 10.0;
  a.speed_limit = 13.89;
  a.shape = Polyline({{0.0, 0.0}, {10.0, 0.0}});
  a.successor_turn_directions = {TurnDirection::Left};
  Lanelet b;
  b.lane_id = ":C_0_0";
  b.edge_id = ":C_0";
  b.junction_id = "C";
  b.is_internal = true;
  b.s_start = 10.0;
  b.length = 0.1 + 0.2;  // not exactly 0.3: must read back as written
  b.shape = Polyline({{10.0, 0.0}, {10.3, 0.0}});
  b.turn_direction = TurnDirection::Left;
  b.turn_signal_distance = 50.0;
  b.params = {{"exit_turn_signal_left", "true"}};
  return RouteMap({a, b});
}

std::string reply_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SutReplyError& e) {
    return e.what();
  }
  return "";
}

TEST(SutMessages, HelloCarriesTheRunAndTheRoute) {
  const RouteMap route = two_lanelets();
  SutRun run;
  run.scenario = "s";
  run.base_link_to_front = 3.7;
  run.parameters = {{"turn_signal_search_time", "3.0"}};
  run.route = &route;
  run.shift_lines = {{RequestSource::LaneChange, "in", 1.0, 9.0, 3.2}};
  const std::string line = sut_hello_message(run, "decider");
  ASSERT_EQ(line.back(), '\n');
  EXPECT_EQ(line.find('\n'), line.size() - 1);
  const json hello = json::parse(line);
  EXPECT_EQ(hello["type"], "hello");
  EXPECT_EQ(hello["protocol"], 1);
  EXPECT_EQ(hello["role"], "decider");
  EXPECT_EQ(hello["parameters"]["turn_signal_search_time"], "3.0");
  EXPECT_EQ(hello["lanelets"][0]["turn_signal_distance"], nullptr);
  EXPECT_EQ(hello["lanelets"][0]["successor_turns"], json::array({"left"}));
  EXPECT_EQ(hello["lanelets"][1]["junction"], "C");
  EXPECT_EQ(hello["lanelets"][1]["turn_direction"], "left");
  EXPECT_EQ(hello["lanelets"][1]["turn_signal_distance"], 50.0);
  EXPECT_EQ(hello["lanelets"][1]["s_end"].get<double>(), 10.0 + (0.1 + 0.2));
  EXPECT_EQ(hello["lanelets"][1]["tags"]["exit_turn_signal_left"], "true");
  EXPECT_EQ(hello["lanelets"][1]["centerline"], json::parse("[[10.0,0.0],[10.3,0.0]]"));
  EXPECT_EQ(hello["shift_lines"][0]["module"], "lane_change");
  EXPECT_EQ(sut_bye_message(), "{\"type\":\"bye\"}\n");
}

TEST(SutMessages, StepCarriesTheEgoWindowRequestAndLights) {
  const RouteMap route = two_lanelets();
  SutStep step;
  step.time = 12.3;
  step.ego.s_front = 5.0;
  step.window = {0, 2};
  step.request.turn = TurnIndicator::EnableRight;
  step.request.hazard = HazardLights::Enable;
  step.request.source = RequestSource::PullOut;
  step.lights.push_back({"C", 2, 0, 10.0, 5.0, true, {{SignalColor::Red, SignalShape::Circle}}, std::nullopt});
  const json m = json::parse(sut_step_message(step, route));
  EXPECT_EQ(m["time"], 12.3);
  EXPECT_EQ(m["window"]["lanelets"], json::array({"in_0", ":C_0_0"}));
  EXPECT_EQ(m["request"]["module"], "pull_out");
  EXPECT_EQ(m["request"]["turn"], "right");
  EXPECT_EQ(m["request"]["hazard"], "enable");
  EXPECT_EQ(m["lights"][0]["elements"][0]["color"], "red");
  EXPECT_EQ(m["lights"][0]["elements"][0]["shape"], "circle");
  EXPECT_EQ(m["lights"][0]["time_to_red"], nullptr);
}

TEST(SutMessages, DeciderReplies) {
  EXPECT_EQ(parse_decider_reply(R"({"blinker": "left"})"), Blinker::Left);
  EXPECT_EQ(parse_decider_reply(R"({"blinker":"hazard","why":1})"), Blinker::Hazard);
  EXPECT_EQ(reply_error_of([] { parse_decider_reply("left"); }), "reply is not JSON: left");
  EXPECT_EQ(reply_error_of([] { parse_decider_reply("[1]"); }), "reply is not a JSON object: [1]");
  EXPECT_EQ(reply_error_of([] { parse_decider_reply("{}"); }), "reply lacks 'blinker': {}");
  EXPECT_EQ(reply_error_of([] { parse_decider_reply(R"({"blinker": 2})"); }),
            "reply's 'blinker' is 2, not \"none\", \"left\", \"right\" or \"hazard\"");
}

TEST(SutMessages, LightJudgeRepliesOnePerLightInOrder) {
  SutStep step;
  step.lights.resize(2);
  step.lights[0].tls_id = "A";
  step.lights[1].tls_id = "B";
  const auto answers = parse_light_judge_reply(
      R"({"lights": [{"tls_id": "A", "decision": "stop", "reason": "red"}, {"tls_id": "B", "decision": "go"}]})", step);
  ASSERT_EQ(answers.size(), 2u);
  EXPECT_TRUE(answers[0].stop);
  EXPECT_EQ(answers[0].reason, "red");
  EXPECT_FALSE(answers[1].stop);
  EXPECT_NE(reply_error_of([&] { parse_light_judge_reply(R"({"lights": [{"tls_id": "A", "decision": "go"}]})", step); })
                .find("not an array of 2 answer(s)"),
            std::string::npos);
  EXPECT_NE(reply_error_of([&] {
              parse_light_judge_reply(R"({"lights": [{"tls_id": "B", "decision": "go"}, {"tls_id": "A", "decision": "go"}]})", step);
            }).find("lights[0] lacks 'tls_id' \"A\""),
            std::string::npos);
  EXPECT_NE(reply_error_of([&] {
              parse_light_judge_reply(R"({"lights": [{"tls_id": "A", "decision": "red"}, {"tls_id": "B", "decision": "go"}]})", step);
            }).find("lacks 'decision' \"stop\" or \"go\""),
            std::string::npos);
}

}  // namespace
}  // namespace signalsim
