// A light left out of a delivered perception message (docs/behaviour.md §L1.3): the judge drops what it
// received but keeps its stamp (a stop signal, timed out later, never received if nothing came), and
// the perception model's omission fault produces such messages. "No message" (the last one stays in
// force) is the contrast throughout.
#include <gtest/gtest.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "traffic_light/perception_model.hpp"
#include "traffic_light/traffic_light_judge.hpp"
#include "traffic_light/traffic_light_judge_explain.hpp"

namespace signalsim {
namespace {

using C = SignalColor;
using S = SignalShape;

const std::vector<SignalElement> kGreen = {SignalElement{C::Green, S::Circle, SignalStatus::SolidOn, 1.0}};

enum class Delivery { Nothing, Missing, Green };

// Far from the line (a stop is always stoppable), at 10 m/s.
TrafficLightJudgeInput at(double now, Delivery delivery) {
  TrafficLightJudgeInput in;
  in.now = now;
  in.distance_to_stop_point = 150.0;
  in.velocity = 10.0;
  if (delivery == Delivery::Green) in.observation = SignalObservation{kGreen, now};
  in.missing_from_message = delivery == Delivery::Missing;
  return in;
}

TEST(LightLeftOut, AMessageWithoutTheLightIsAStopSignalAtOnce) {
  TrafficLightJudge judge;
  EXPECT_EQ(judge.step(at(0.0, Delivery::Green)).verdict, SignalVerdict::Go);
  const auto r1 = judge.step(at(0.1, Delivery::Missing));
  EXPECT_EQ(r1.verdict, SignalVerdict::Stop);
  EXPECT_TRUE(r1.is_stop_signal);
  EXPECT_TRUE(r1.missing_from_message);
  EXPECT_TRUE(r1.looked_at.empty());
  EXPECT_DOUBLE_EQ(r1.signal_age, 0.1) << "the stamp of the last message with the light is kept";
  EXPECT_EQ(r1.decision, JudgeDecision::Pass) << "first stop cycle: hysteresis";
  EXPECT_EQ(judge.step(at(0.2, Delivery::Missing)).decision, JudgeDecision::Pass);  // elapsed 0.1, not > 0.1
  const auto r3 = judge.step(at(0.3, Delivery::Missing));
  EXPECT_EQ(r3.decision, JudgeDecision::Stop);
  EXPECT_EQ(explain(r3, at(0.3, Delivery::Missing), judge.parameters()),
            "stop: stoppable (judge line 25.62 m < d 150.00 m); stop signal: the light was left out of the latest "
            "message");
}

TEST(LightLeftOut, NoMessageKeepsTheGreenInForceWhereAMessageWithoutItStops) {
  TrafficLightJudge silent;
  TrafficLightJudge left_out;
  silent.step(at(0.0, Delivery::Green));
  left_out.step(at(0.0, Delivery::Green));
  for (int k = 1; k <= 5; ++k) {
    const double t = 0.1 * k;
    const auto s = silent.step(at(t, Delivery::Nothing));
    const auto m = left_out.step(at(t, Delivery::Missing));
    EXPECT_EQ(s.verdict, SignalVerdict::Go) << t;
    EXPECT_EQ(s.decision, JudgeDecision::Pass) << t;
    EXPECT_EQ(m.verdict, SignalVerdict::Stop) << t;
  }
  EXPECT_TRUE(left_out.is_prev_state_stop());
  EXPECT_FALSE(silent.is_prev_state_stop());
}

TEST(LightLeftOut, NoMessageAfterOneWithoutTheLightKeepsItLeftOut) {
  TrafficLightJudge judge;
  judge.step(at(0.0, Delivery::Green));
  judge.step(at(0.1, Delivery::Missing));
  const auto r = judge.step(at(0.2, Delivery::Nothing));
  EXPECT_EQ(r.verdict, SignalVerdict::Stop) << "the node's map still lacks the light";
  EXPECT_TRUE(r.missing_from_message);
  EXPECT_EQ(judge.step(at(0.3, Delivery::Green)).verdict, SignalVerdict::Go) << "seen again: go";
}

TEST(LightLeftOut, LeftOutBeforeItWasEverSeenIsNeverReceived) {
  TrafficLightJudge judge;  // is_simulation: pass
  const auto r = judge.step(at(0.0, Delivery::Missing));
  EXPECT_EQ(r.verdict, SignalVerdict::NeverReceived);
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
  EXPECT_FALSE(r.missing_from_message);
}

TEST(LightLeftOut, LeftOutLongAfterTheLastSightingIsTimedOut) {
  TrafficLightJudge judge;
  judge.step(at(0.0, Delivery::Green));
  EXPECT_EQ(judge.step(at(1.0, Delivery::Missing)).verdict, SignalVerdict::Stop);  // age 1.0: not > 1.0
  EXPECT_EQ(judge.step(at(1.1, Delivery::Missing)).verdict, SignalVerdict::TimedOut);
}

TEST(LightLeftOut, AnObservationCannotAlsoBeMissing) {
  TrafficLightJudge judge;
  judge.step(at(0.0, Delivery::Green));
  TrafficLightJudgeInput both = at(0.1, Delivery::Green);
  both.missing_from_message = true;
  EXPECT_THROW(judge.step(both), std::invalid_argument);
  EXPECT_EQ(judge.step(at(0.1, Delivery::Nothing)).verdict, SignalVerdict::Go) << "state unchanged";
}

// ---- the perception model's omission fault --------------------------------------------------------

TEST(PerceptionOmission, ScheduledOmissionsDeliverMessagesWithoutTheLight) {
  PerceptionModelParameters p;
  p.omissions = {{0.2, 0.4}};
  PerceptionModel model(p);
  for (int k = 0; k <= 6; ++k) {
    const double t = 0.1 * k;
    const SignalDelivery d = model.observe(kGreen, 50.0, t);
    const bool omitted = k >= 2 && k <= 4;  // closed interval, integer nanoseconds
    EXPECT_TRUE(d.delivered()) << t;
    EXPECT_EQ(d.missing_from_message, omitted) << t;
    EXPECT_EQ(d.observation.has_value(), !omitted) << t;
  }
}

TEST(PerceptionOmission, NoCaptureMeansNoMessageEvenInAnOmission) {
  PerceptionModelParameters p;
  p.omissions = {{0.0, 10.0}};
  p.blackouts = {{0.0, 1.0}};
  p.detection_range = 100.0;
  PerceptionModel model(p);
  EXPECT_FALSE(model.observe(kGreen, 50.0, 0.5).delivered()) << "blacked out: no message";
  EXPECT_FALSE(model.observe(kGreen, 150.0, 1.5).delivered()) << "out of range: no message";
  EXPECT_TRUE(model.observe(kGreen, 50.0, 2.0).missing_from_message);
}

TEST(PerceptionOmission, AMessageWithoutTheLightComesWithTheLatency) {
  PerceptionModelParameters p;
  p.latency = 0.2;
  p.omissions = {{0.1, 0.1}};
  PerceptionModel model(p);
  EXPECT_FALSE(model.observe(kGreen, 50.0, 0.0).delivered());
  EXPECT_FALSE(model.observe(kGreen, 50.0, 0.1).delivered());
  EXPECT_TRUE(model.observe(kGreen, 50.0, 0.2).observation.has_value());  // the capture of 0.0
  const SignalDelivery late = model.observe(kGreen, 50.0, 0.3);           // the message of 0.1
  EXPECT_TRUE(late.missing_from_message);
  EXPECT_FALSE(late.observation.has_value());
}

TEST(PerceptionOmission, TheProbabilityHasItsOwnSeededStream) {
  PerceptionModelParameters p;
  p.seed = 7;
  p.omission_probability = 0.3;
  p.dropout_probability = 0.2;
  PerceptionModelParameters without = p;
  without.omission_probability = 0.0;
  PerceptionModel a(p), b(p), c(without);
  int omitted = 0, steps = 0;
  for (int k = 0; k < 2000; ++k) {
    const double t = 0.1 * k;
    const SignalDelivery da = a.observe(kGreen, 50.0, t);
    EXPECT_EQ(da, b.observe(kGreen, 50.0, t)) << "same seed, same deliveries";
    EXPECT_EQ(da.delivered(), c.observe(kGreen, 50.0, t).delivered()) << "the dropout draws are unchanged";
    if (da.delivered()) {
      ++steps;
      omitted += da.missing_from_message ? 1 : 0;
    }
  }
  const double rate = static_cast<double>(omitted) / steps;
  EXPECT_NEAR(rate, 0.3, 0.04);
}

TEST(PerceptionOmission, ParametersOutOfRangeAreRefused) {
  PerceptionModelParameters p;
  p.omission_probability = 1.5;
  EXPECT_THROW(validate(p), std::invalid_argument);
  p.omission_probability = 1.0;
  EXPECT_NO_THROW(validate(p));
  p.omissions = {{3.0, 2.0}};
  try {
    validate(p);
    FAIL() << "a reversed omission was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "perception parameter omissions[0] must be finite with start <= end");
  }
}

}  // namespace
}  // namespace signalsim
