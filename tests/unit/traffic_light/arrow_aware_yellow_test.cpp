// docs/behaviour.md §L5.3: the upstream scene-level tests of arrow-aware yellow passing (§L1.8), all rows,
// with the upstream fixture. The upstream test calls isStopSignal() once per step; here each step()
// runs it once (APPROACH, stop point ahead) and reports is_stop_signal and yellow_state.
#include <gtest/gtest.h>

#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {
namespace {

using C = SignalColor;

// docs/behaviour.md §L5.3 fixture.
TrafficLightJudgeParameters fixture_parameters(bool feature = true) {
  TrafficLightJudgeParameters p;
  p.stop_margin = 0.0;
  p.tl_state_timeout = 1.0;
  p.yellow_lamp_period = 3.0;
  p.yellow_light_stop_velocity = 1.0;
  p.stop_time_hysteresis = 0.0;
  p.enable_pass_judge = false;
  p.enable_arrow_aware_yellow_passing = feature;
  p.restart_suppression.min_behind_distance_to_stop = 0.0;
  p.restart_suppression.max_behind_distance_to_stop = 0.0;
  p.max_accel = 1.0;  // planner node overrides of the fixture
  p.max_jerk = 1.0;
  p.delay_response_time = 0.0;
  p.is_simulation = false;
  return p;
}

struct Lane {
  bool is_turn_lane = true;
  bool has_static_arrow = true;
};

class ArrowAwareYellow : public ::testing::Test {
 protected:
  void make(bool feature, Lane lane) {
    judge_.emplace(fixture_parameters(feature));
    lane_ = lane;
  }
  // One call with the signal written at stamp = now (never timed out); shape CIRCLE, SOLID_ON, 1.0.
  TrafficLightJudgeResult call(C color) {
    TrafficLightJudgeInput in;
    in.now = now_;
    in.distance_to_stop_point = 50.0;
    in.velocity = 0.0;
    in.observation = SignalObservation{{SignalElement{color, SignalShape::Circle, SignalStatus::SolidOn, 1.0}}, now_};
    in.turn_direction = LaneTurnDirection::Else;  // the module's own turn_direction is not used by the override
    in.is_turn_lane = lane_.is_turn_lane;
    in.has_static_arrow = lane_.has_static_arrow;
    now_ += 0.1;
    return judge_->step(in);
  }

  std::optional<TrafficLightJudge> judge_;
  Lane lane_;
  double now_ = 100.0;
};

TEST_F(ArrowAwareYellow, TransitionToYellowFromGreen) {
  make(true, {});
  const auto g = call(C::Green);
  EXPECT_EQ(g.yellow_state, YellowState::NotYellow);
  EXPECT_FALSE(g.is_stop_signal);  // implied fact: green circle -> go
  const auto y = call(C::Amber);
  EXPECT_EQ(y.yellow_state, YellowState::FromGreen);
  EXPECT_FALSE(y.is_stop_signal);
  EXPECT_EQ(y.verdict, SignalVerdict::ArrowAwareYellowPass);
  EXPECT_EQ(y.decision, JudgeDecision::Pass);
}

TEST_F(ArrowAwareYellow, TransitionToYellowFromRed) {
  make(true, {});
  EXPECT_EQ(call(C::Red).yellow_state, YellowState::NotYellow);
  const auto y = call(C::Amber);
  EXPECT_EQ(y.yellow_state, YellowState::FromNonGreen);
  EXPECT_TRUE(y.is_stop_signal);
}

TEST_F(ArrowAwareYellow, StateResetWhenYellowEnds) {
  make(true, {});
  call(C::Green);
  EXPECT_EQ(call(C::Amber).yellow_state, YellowState::FromGreen);
  EXPECT_EQ(call(C::Red).yellow_state, YellowState::NotYellow);
}

TEST_F(ArrowAwareYellow, NotTurnLane) {
  make(true, {.is_turn_lane = false, .has_static_arrow = true});
  call(C::Green);
  const auto y = call(C::Amber);
  EXPECT_EQ(y.yellow_state, YellowState::FromGreen);
  EXPECT_TRUE(y.is_stop_signal);
}

TEST_F(ArrowAwareYellow, NoStaticArrow) {
  make(true, {.is_turn_lane = true, .has_static_arrow = false});
  call(C::Green);
  const auto y = call(C::Amber);
  EXPECT_EQ(y.yellow_state, YellowState::FromGreen);
  EXPECT_TRUE(y.is_stop_signal);
}

TEST_F(ArrowAwareYellow, UnknownToYellow) {
  make(true, {});
  const auto y = call(C::Amber);  // first observation ever
  EXPECT_EQ(y.yellow_state, YellowState::NotYellow);
  EXPECT_TRUE(y.is_stop_signal);
}

TEST_F(ArrowAwareYellow, FeatureDisabled) {
  make(false, {});
  call(C::Green);
  const auto y = call(C::Amber);
  EXPECT_EQ(y.yellow_state, YellowState::NotYellow);
  EXPECT_TRUE(y.is_stop_signal);
}

// Consequences of §L1.8 beyond the upstream rows.

TEST_F(ArrowAwareYellow, PlainAmberOnALaneWithoutTurnDirectionStops) {
  make(true, {.is_turn_lane = false, .has_static_arrow = false});
  EXPECT_TRUE(call(C::Amber).is_stop_signal);
}

TEST_F(ArrowAwareYellow, ClassificationHoldsForTheWholeYellowPhase) {
  make(true, {});
  call(C::Green);
  for (int k = 0; k < 20; ++k) {
    const auto y = call(C::Amber);
    EXPECT_EQ(y.yellow_state, YellowState::FromGreen);
    EXPECT_FALSE(y.is_stop_signal);
  }
}

TEST_F(ArrowAwareYellow, YellowOfUnknownOriginIsClassifiedOnItsSecondCycle) {
  // Final version: the first yellow with no previous elements keeps NotYellow; on the next cycle the
  // previous elements (amber) hold no green circle -> FromNonGreen. Both stop.
  make(true, {});
  EXPECT_EQ(call(C::Amber).yellow_state, YellowState::NotYellow);
  const auto y = call(C::Amber);
  EXPECT_EQ(y.yellow_state, YellowState::FromNonGreen);
  EXPECT_TRUE(y.is_stop_signal);
}

TEST_F(ArrowAwareYellow, TimedOutSignalStopsAndDoesNotTrack) {
  make(true, {});
  call(C::Green);
  // Amber captured long ago: row 2 (timeout) wins before the tracker runs.
  TrafficLightJudgeInput in;
  in.now = now_ + 5.0;
  in.distance_to_stop_point = 50.0;
  in.observation = SignalObservation{{SignalElement{C::Amber, SignalShape::Circle, SignalStatus::SolidOn, 1.0}}, now_};
  in.is_turn_lane = true;
  in.has_static_arrow = true;
  const auto r = judge_->step(in);
  EXPECT_EQ(r.verdict, SignalVerdict::TimedOut);
  EXPECT_TRUE(r.is_stop_signal);
  EXPECT_EQ(r.yellow_state, YellowState::NotYellow);
}

TEST_F(ArrowAwareYellow, DefaultParametersDisableTheFeature) {
  // docs/behaviour.md §L1.8 (corrected): autoware_launch's shipped traffic_light.param.yaml has false.
  EXPECT_FALSE(TrafficLightJudgeParameters{}.enable_arrow_aware_yellow_passing);
}

}  // namespace
}  // namespace signalsim
