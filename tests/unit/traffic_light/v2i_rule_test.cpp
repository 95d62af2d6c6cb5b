// V2I remaining time to red (docs/behaviour.md §L1.7): the rule (t_pass, horizon, red stops with arrows, the
// velocity-threshold branch) and how the judge OR-s it into to_be_stopped (no hysteresis; the pass
// judge of §L2 still applies).
#include <gtest/gtest.h>

#include <cmath>

#include "signal_element.hpp"
#include "traffic_light/traffic_light_judge.hpp"
#include "traffic_light/traffic_light_judge_explain.hpp"
#include "traffic_light/v2i_rule.hpp"

namespace signalsim {
namespace {

using C = SignalColor;
using S = SignalShape;

using test::el;
SignalPrediction red_prediction_at(double stamp) { return {stamp, {el(C::Red)}}; }

V2iVerdict rule(double d, double v, const std::vector<SignalPrediction>& p,
                LaneTurnDirection dir = LaneTurnDirection::Straight) {
  return will_turn_red_before_reaching_stop_line(d, v, 100.0, dir, p, V2iParameters{});
}

TEST(V2iRule, RedWithinTheHorizonTurnsRed) {
  // d 50 m at 10 m/s: t_pass 5 s, horizon 7 s.
  const V2iVerdict in = rule(50.0, 10.0, {red_prediction_at(106.9)});
  EXPECT_TRUE(in.turns_red);
  EXPECT_DOUBLE_EQ(in.t_pass, 5.0);
  EXPECT_DOUBLE_EQ(in.horizon, 7.0);
  EXPECT_NEAR(*in.time_to_red, 6.9, 1e-9);
  const V2iVerdict out = rule(50.0, 10.0, {red_prediction_at(107.1)});
  EXPECT_FALSE(out.turns_red) << "red after the ego passed, with 2 s to spare: no stop";
  EXPECT_NEAR(*out.time_to_red, 7.1, 1e-9);
}

TEST(V2iRule, OnlyRedStopsCount) {
  EXPECT_FALSE(rule(50.0, 10.0, {{101.0, {el(C::Amber)}}, {102.0, {el(C::Green)}}}).turns_red);
  EXPECT_FALSE(rule(50.0, 10.0, {}).time_to_red);
  // The earliest red stop of several is reported.
  EXPECT_NEAR(*rule(50.0, 10.0, {red_prediction_at(130.0), red_prediction_at(104.0)}).time_to_red, 4.0, 1e-9);
}

TEST(V2iRule, AGreenArrowOfTheLanesDirectionIsNoRedStop) {
  const SignalPrediction red_left_arrow{104.0, {el(C::Red), el(C::Green, S::LeftArrow)}};
  EXPECT_FALSE(rule(50.0, 10.0, {red_left_arrow}, LaneTurnDirection::Left).turns_red);
  EXPECT_TRUE(rule(50.0, 10.0, {red_left_arrow}, LaneTurnDirection::Straight).turns_red) << "not the straight lane's arrow";
  EXPECT_TRUE(rule(50.0, 10.0, {red_left_arrow}, LaneTurnDirection::Else).turns_red) << "no turn direction: arrows ignored";
  const SignalPrediction red_amber_arrow{104.0, {el(C::Red), el(C::Amber, S::LeftArrow)}};
  EXPECT_TRUE(rule(50.0, 10.0, {red_amber_arrow}, LaneTurnDirection::Left).turns_red) << "arrows count only when green";
}

TEST(V2iRule, AtOrBelowTheVelocityThresholdTheDepartureTimeCounts) {
  // v 0.5 m/s is not above the threshold: t_pass = required_time_to_departure 3 s, horizon 5 s.
  const V2iVerdict slow = rule(1.0, 0.5, {red_prediction_at(104.9)});
  EXPECT_DOUBLE_EQ(slow.t_pass, 3.0);
  EXPECT_TRUE(slow.turns_red);
  EXPECT_FALSE(rule(1.0, 0.5, {red_prediction_at(105.1)}).turns_red);
  // Just above it, d / v: 1 m at 0.51 m/s is 1.96 s, horizon 3.96 s.
  EXPECT_FALSE(rule(1.0, 0.51, {red_prediction_at(104.5)}).turns_red);
  EXPECT_NEAR(rule(1.0, 0.51, {}).t_pass, 1.0 / 0.51, 1e-12);
}

TEST(V2iRule, RejectsNegativeParameters) {
  V2iParameters p;
  p.last_time_allowed_to_pass = -1.0;
  EXPECT_THROW(validate(p), std::invalid_argument);
  TrafficLightJudgeParameters judge;
  judge.v2i.velocity_threshold = std::nan("");
  EXPECT_THROW(TrafficLightJudge{judge}, std::invalid_argument);
}

// The judge with V2I on, the camera showing green.
TrafficLightJudgeParameters with_v2i(bool on = true) {
  TrafficLightJudgeParameters p;
  p.v2i.use_remaining_time = on;
  return p;
}

TrafficLightJudgeInput green(double now, double d, double v, std::vector<SignalPrediction> predictions) {
  TrafficLightJudgeInput in;
  in.now = now;
  in.distance_to_stop_point = d;
  in.velocity = v;
  in.observation = SignalObservation{{el(C::Green)}, now};
  in.turn_direction = LaneTurnDirection::Straight;
  in.predictions = std::move(predictions);
  return in;
}

TEST(V2iJudge, GreenWithRedPredictedWithinTheHorizonStopsAtOnce) {
  TrafficLightJudge judge(with_v2i());
  // d 100 m at 10 m/s: t_pass 10 s, horizon 12 s; red in 11 s. No hysteresis: the first step stops.
  const TrafficLightJudgeInput in = green(0.0, 100.0, 10.0, {red_prediction_at(11.0)});
  const TrafficLightJudgeResult r = judge.step(in);
  EXPECT_FALSE(r.is_stop_signal) << "the camera says go";
  EXPECT_TRUE(r.v2i_stop);
  EXPECT_TRUE(r.to_be_stopped);
  EXPECT_EQ(r.decision, JudgeDecision::Stop);
  EXPECT_EQ(r.zone, JudgeZone::Stoppable);
  ASSERT_TRUE(r.stop_point_distance);
  EXPECT_DOUBLE_EQ(*r.stop_point_distance, 100.0);
  const std::string reason = explain(r, in, judge.parameters());
  EXPECT_NE(reason.find("V2I: red in 11.00 s < horizon 12.00 s"), std::string::npos) << reason;
}

TEST(V2iJudge, RedOutsideTheHorizonPasses) {
  TrafficLightJudge judge(with_v2i());
  const TrafficLightJudgeResult r = judge.step(green(0.0, 100.0, 10.0, {red_prediction_at(12.5)}));
  EXPECT_FALSE(r.v2i_stop);
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
  EXPECT_NEAR(*r.v2i_time_to_red, 12.5, 1e-9);
}

TEST(V2iJudge, OffByDefaultAndWhenOff) {
  EXPECT_FALSE(TrafficLightJudgeParameters{}.v2i.use_remaining_time);
  TrafficLightJudge judge(with_v2i(false));
  const TrafficLightJudgeInput in = green(0.0, 100.0, 10.0, {red_prediction_at(11.0)});
  const TrafficLightJudgeResult r = judge.step(in);
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
  EXPECT_FALSE(r.v2i_stop);
  EXPECT_FALSE(r.v2i_time_to_red) << "nothing evaluated";
}

TEST(V2iJudge, ThePassJudgeStillApplies) {
  // 20 m at 10 m/s: cannot stop (judge line 25.6 m) and reaches the line in the yellow (27.5 m): pass.
  TrafficLightJudge near(with_v2i());
  const TrafficLightJudgeResult pass = near.step(green(0.0, 20.0, 10.0, {red_prediction_at(3.0)}));
  EXPECT_TRUE(pass.v2i_stop);
  EXPECT_EQ(pass.zone, JudgeZone::PassThroughYellow);
  EXPECT_EQ(pass.decision, JudgeDecision::Pass);
  // 55 m at 16.67 m/s: judge line 62.6 m >= d >= yellow lamp line 45.8 m: dilemma zone, emergency stop.
  TrafficLightJudge dilemma(with_v2i());
  const TrafficLightJudgeResult emergency = dilemma.step(green(0.0, 55.0, 16.67, {red_prediction_at(3.0)}));
  EXPECT_EQ(emergency.zone, JudgeZone::DilemmaZone);
  EXPECT_EQ(emergency.decision, JudgeDecision::EmergencyStop);
}

TEST(V2iJudge, SlowEgoUsesTheDepartureTime) {
  // At 0.3 m/s, 2 m before the stop point: t_pass = 3 s, horizon 5 s.
  TrafficLightJudge soon(with_v2i());
  const TrafficLightJudgeResult stop = soon.step(green(0.0, 2.0, 0.3, {red_prediction_at(4.5)}));
  EXPECT_EQ(stop.decision, JudgeDecision::Stop);
  EXPECT_EQ(stop.zone, JudgeZone::Stoppable) << "2 m is beyond the judge line at 0.3 m/s";
  TrafficLightJudge later(with_v2i());
  EXPECT_EQ(later.step(green(0.0, 2.0, 0.3, {red_prediction_at(5.5)})).decision, JudgeDecision::Pass)
      << "with d / v (6.7 s) it would have stopped";
}

TEST(V2iJudge, NoHysteresisAndNoLatchOfItsOwn) {
  TrafficLightJudge judge(with_v2i());
  EXPECT_EQ(judge.step(green(0.0, 100.0, 10.0, {red_prediction_at(11.0)})).decision, JudgeDecision::Stop);
  // The prediction is gone (lost channel): a green camera with no V2I rule releases the stop.
  EXPECT_EQ(judge.step(green(0.1, 99.0, 10.0, {})).decision, JudgeDecision::Pass);
}

}  // namespace
}  // namespace signalsim
