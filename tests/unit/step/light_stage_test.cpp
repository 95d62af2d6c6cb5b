// The traffic-light stage of a step (step/light_stage): what it asks SUMO for (the lights of the
// window, else the next light beyond it; with V2I the timing every step and the programs until it
// has them), and, while a light changes, that each step it reports the state of the ego's link and
// what perception delivered, and judges on that state. The stage reuses what a state showed until
// the state changes; these tests fail if it kept one too long. No SUMO: the readings come from the test.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "step/light_stage.hpp"

namespace signalsim {
namespace {

// A left turn (link 0) beside the straight link (link 1) of the same lane, stop line at s = 100.
sumo::ApproachLight left_turn_light() {
  sumo::ApproachLight light;
  light.tls_id = "L";
  light.link_index = 0;
  light.lane_index = 0;
  light.direction = TurnDirection::Left;
  light.links = {{TurnDirection::Left, 0, 0}, {TurnDirection::Straight, 1, 0}};
  light.s_stop_line = 100.0;
  return light;
}

// The observation of one light's state.
StepObservation reading_of(const std::string& tls, const std::string& state) {
  StepObservation seen;
  seen.lights.push_back({tls, state, std::nullopt, std::nullopt});
  return seen;
}

// Two lights 250 m apart, each a left turn at link 0.
std::vector<sumo::ApproachLight> two_lights() {
  sumo::ApproachLight near = left_turn_light(), far = left_turn_light();
  far.tls_id = "F";
  far.s_stop_line = 350.0;
  far.route_index = 2;
  return {near, far};
}

TEST(LightStage, AsksForTheWindowsLightsElseTheNextLightBeyondIt) {
  TrafficLightStage stage(two_lights(), TrafficLightJudgeParameters{}, PerceptionModelParameters{}, 300.0);
  const auto asked = [&stage](double s_front) {
    ObservationDemand want;
    stage.demand(s_front, want);
    std::vector<std::string> ids;
    for (const LightDemand& l : want.lights) ids.push_back(l.tls_id);
    return ids;
  };
  EXPECT_EQ(asked(0.0), (std::vector<std::string>{"L"}));        // F is 350 m ahead: beyond the horizon
  EXPECT_EQ(asked(60.0), (std::vector<std::string>{"L", "F"}));  // both within 300 m
  // Once L is behind the dead line (2 m past its stop line) it is dropped by the step.
  const std::vector<LightStep> steps = stage.step(0.0, 103.0, 10.0, 0.0, [] {
    StepObservation seen = reading_of("L", "GG");
    seen.lights.push_back({"F", "GG", std::nullopt, std::nullopt});
    return seen;
  }());
  EXPECT_EQ(steps.size(), 2u);
  EXPECT_EQ(asked(103.0), (std::vector<std::string>{"F"}));
  // Far from every light: the next one's state only, for the timeline row.
  TrafficLightStage fresh(two_lights(), TrafficLightJudgeParameters{}, PerceptionModelParameters{}, 50.0);
  ObservationDemand want;
  fresh.demand(0.0, want);
  ASSERT_EQ(want.lights.size(), 1u);
  EXPECT_EQ(want.lights[0].tls_id, "L");
  EXPECT_TRUE(fresh.step(0.0, 0.0, 10.0, 0.0, reading_of("L", "GG")).empty());
  EXPECT_EQ(fresh.next_light()->tls_id, "L");
}

TEST(LightStage, WithV2iAsksForTheTimingEveryStepAndTheProgramsUntilItHasThem) {
  TrafficLightJudgeParameters judge;
  judge.v2i.use_remaining_time = true;
  TrafficLightStage stage({left_turn_light()}, judge, PerceptionModelParameters{}, 300.0);
  sumo::LightProgram program;
  program.id = "0";
  program.phases = {{30.0, "GG", {}}, {3.0, "yy", {}}, {30.0, "rr", {}}};
  for (int k = 0; k < 3; ++k) {
    ObservationDemand want;
    stage.demand(20.0, want);
    ASSERT_EQ(want.lights.size(), 1u);
    EXPECT_TRUE(want.lights[0].timing) << k;
    EXPECT_EQ(want.lights[0].programs, k == 0) << k;  // read once, when the light is first judged
    StepObservation seen = reading_of("L", "GG");
    seen.lights[0].timing = sumo::LightTiming{"0", 0, 30.0};
    if (want.lights[0].programs) seen.lights[0].programs = std::vector<sumo::LightProgram>{program};
    const std::vector<LightStep> steps = stage.step(0.1 * k, 20.0, 10.0, 0.0, seen);
    ASSERT_EQ(steps.size(), 1u);
    EXPECT_TRUE(steps[0].judged);
  }
}

TEST(LightStage, EachStepReportsAndJudgesTheStateOfThatStep) {
  const sumo::ApproachLight light = left_turn_light();
  TrafficLightStage stage({light}, TrafficLightJudgeParameters{}, PerceptionModelParameters{}, 300.0);
  // Green, a left arrow under a red straight link, yellow, red, green again, and off.
  const std::vector<std::string> states = {"GG", "GG", "Gr", "Gr", "yy", "yy", "rr", "rr", "GG", "OO", "GG"};
  std::vector<std::string> seen;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const std::string& state = states[k];
    const double now = 0.1 * static_cast<double>(k);
    const double s_front = 20.0 + 0.1 * static_cast<double>(k);
    ObservationDemand want;
    stage.demand(s_front, want);
    ASSERT_EQ(want.lights.size(), 1u) << k;
    EXPECT_EQ(want.lights[0].tls_id, "L");
    EXPECT_FALSE(want.lights[0].timing);  // V2I off
    const std::vector<LightStep> steps = stage.step(now, s_front, 0.0, 0.0, reading_of("L", state));
    ASSERT_EQ(steps.size(), 1u) << k;
    const LightStep& step = steps.front();
    EXPECT_EQ(step.own_state, state[0]) << k;
    const auto truth = sumo::signal_elements(state, light);
    EXPECT_EQ(step.judged, truth.has_value()) << k;
    EXPECT_EQ(step.observed, truth ? sumo::describe_elements(*truth) : "") << k;
    // The judge's raw stop signal (before its hysteresis) follows the circle: red and yellow stop.
    if (step.judged) {
      EXPECT_EQ(step.result.is_stop_signal, state[0] == 'r' || state[0] == 'y') << k;
    }
    seen.push_back(step.observed);
  }
  // What the camera saw, step by step: the arrow only under the red straight link, nothing while off.
  EXPECT_EQ(seen, (std::vector<std::string>{"green", "green", "red+green_left_arrow", "red+green_left_arrow",
                                            "amber", "amber", "red", "red", "green", "", "green"}));
}

}  // namespace
}  // namespace signalsim
