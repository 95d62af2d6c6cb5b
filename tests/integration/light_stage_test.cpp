// The traffic-light stage of the step loop (sim/light_stage) while a light changes: each step it
// reports the state of the ego's link and what perception delivered, and judges on that state. The
// stage reuses what a state showed until the state changes; these tests fail if it kept one too long.
// No SUMO: the states come from the test.
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

TEST(LightStage, EachStepReportsAndJudgesTheStateOfThatStep) {
  const sumo::ApproachLight light = left_turn_light();
  TrafficLightStage stage({light}, TrafficLightJudgeParameters{}, PerceptionModelParameters{}, 300.0);
  // Green, a left arrow under a red straight link, yellow, red, green again, and off.
  const std::vector<std::string> states = {"GG", "GG", "Gr", "Gr", "yy", "yy", "rr", "rr", "GG", "OO", "GG"};
  std::string state;
  const TrafficLightStage::StateOf state_of = [&state](const std::string& tls) {
    EXPECT_EQ(tls, "L");
    return &state;
  };
  std::vector<std::string> seen;
  for (std::size_t k = 0; k < states.size(); ++k) {
    state = states[k];
    const double now = 0.1 * static_cast<double>(k);
    const std::vector<LightStep> steps = stage.step(now, 20.0 + 0.1 * static_cast<double>(k), 0.0, 0.0, state_of);
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
