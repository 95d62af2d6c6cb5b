// docs/behaviour.md §L1.2 state machine, §L1.3 lookup rules, §L1.5 hysteresis and latch, §L1.6 restart
// suppression, §L2.3 predicates at their boundaries, §L2.6 zones, and the signalsim Decisions.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "signal_element.hpp"
#include "traffic_light/judge_line.hpp"
#include "traffic_light/traffic_light_judge.hpp"
#include "traffic_light/traffic_light_judge_explain.hpp"

namespace signalsim {
namespace {

using C = SignalColor;
using S = SignalShape;

using test::el;

SignalObservation obs(std::vector<SignalElement> e, double stamp) { return SignalObservation{std::move(e), stamp}; }

TrafficLightJudgeInput input(double now, std::optional<double> d, double v, std::optional<SignalObservation> o,
                             double a0 = 0.0) {
  TrafficLightJudgeInput in;
  in.now = now;
  in.distance_to_stop_point = d;
  in.velocity = v;
  in.acceleration = a0;
  in.observation = std::move(o);
  return in;
}

// A red light observed fresh at `now`.
TrafficLightJudgeInput red_at(double now, double d, double v, double a0 = 0.0) {
  return input(now, d, v, obs({el(C::Red)}, now), a0);
}
TrafficLightJudgeInput green_at(double now, double d, double v) { return input(now, d, v, obs({el(C::Green)}, now)); }

// Default parameters with no hysteresis: the first red cycle has elapsed 0 (not > 0) and passes,
// the second is judged. Runs the warm-up cycle at the same d and v, returns the judged step.
TrafficLightJudgeResult judged_red(TrafficLightJudge& judge, double d, double v, double a0 = 0.0) {
  judge.step(red_at(0.0, d, v, a0));
  return judge.step(red_at(0.1, d, v, a0));
}

TrafficLightJudgeParameters no_hysteresis() {
  TrafficLightJudgeParameters p;
  p.stop_time_hysteresis = 0.0;
  return p;
}

TEST(TrafficLightJudge, DefaultsFollowTheDecisions) {
  const TrafficLightJudgeParameters p;
  EXPECT_EQ(p.yellow_light_stop_velocity, 2.0);
  EXPECT_TRUE(p.is_simulation);
  EXPECT_EQ(p.stop_margin, 0.0);
  EXPECT_EQ(p.tl_state_timeout, 1.0);
  EXPECT_EQ(p.stop_time_hysteresis, 0.1);
  EXPECT_EQ(p.yellow_lamp_period, 2.75);
  EXPECT_TRUE(p.enable_pass_judge);
  EXPECT_EQ(p.restart_suppression.min_behind_distance_to_stop, 0.5);
  EXPECT_EQ(p.restart_suppression.max_behind_distance_to_stop, 1.0);
  EXPECT_EQ(p.max_accel, -2.8);
  EXPECT_EQ(p.max_jerk, -5.0);
  EXPECT_EQ(p.delay_response_time, 0.5);
}

TEST(TrafficLightJudge, ExplainTellsEachStepsDecisionAndWhy) {
  // Green, then red while approaching (stop latched), rolling over the line (GO_OUT), re-armed on a
  // new approach, a signal that times out, no stop point: each step's reason line.
  std::vector<TrafficLightJudgeInput> steps = {green_at(0.0, 60.0, 10.0), red_at(0.1, 59.0, 10.0),
                                               red_at(0.2, 58.0, 10.0),   red_at(0.3, 0.7, 0.0),
                                               red_at(0.4, -2.5, 1.0),    red_at(0.5, 30.0, 8.0),
                                               input(2.0, 29.0, 8.0, std::nullopt),
                                               input(2.1, std::nullopt, 8.0, std::nullopt)};
  steps[3].is_vehicle_stopped = true;  // restart suppression at d = 0.7 m
  const std::vector<std::string> reasons = {
      "pass: go signal [green circle] for a else lane",
      "pass: stop signal held 0.000 s, not > stop_time_hysteresis 0.000 s; stop signal [red circle] for a else lane",
      "stop: stoppable (judge line 25.62 m < d 58.00 m); stop signal [red circle] for a else lane",
      "stop: restart suppressed (stopped at d = 0.70 m within (0.50, 1.00) m); stop signal [red circle] for a "
      "else lane",
      "none: APPROACH -> GO_OUT (d = -2.50 m < -2.0 m)",
      "none: GO_OUT -> APPROACH (re-armed, d = 30.00 m > 1.0 m)",
      "stop (latched stop since an earlier step): stoppable (judge line 17.63 m < d 29.00 m); signal timed out "
      "(age 1.500 s > tl_state_timeout 1.000 s)",
      "none: the path does not cross the stop line",
  };
  TrafficLightJudge judge(no_hysteresis());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    SCOPED_TRACE(i);
    const TrafficLightJudgeResult r = judge.step(steps[i]);
    EXPECT_EQ(explain(r, steps[i], judge.parameters()), reasons[i]);
  }
}

TEST(TrafficLightJudge, ExplainTellsAGoOutStepApartFromTheDeadLine) {
  // Both steps end in GO_OUT at the same d: one stays there, the other crosses the dead line.
  TrafficLightJudge judge(no_hysteresis());
  const TrafficLightJudgeInput over = red_at(0.0, -3.0, 1.0);
  const TrafficLightJudgeResult crossed = judge.step(over);
  EXPECT_EQ(explain(crossed, over, judge.parameters()), "none: APPROACH -> GO_OUT (d = -3.00 m < -2.0 m)");
  const TrafficLightJudgeInput still = red_at(0.1, -3.0, 1.0);
  const TrafficLightJudgeResult stayed = judge.step(still);
  EXPECT_EQ(explain(stayed, still, judge.parameters()), "none: GO_OUT (re-arms when d > 1.0 m)");
}

TEST(TrafficLightJudge, NoStopPointMeansNoDecisionAndNoStateChange) {
  // docs/behaviour.md §L1.2 STEP 1.
  TrafficLightJudge judge;
  const auto r = judge.step(red_at(0.0, 0.0, 10.0));  // warm the timer... (d = 0)
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
  const auto none = judge.step(input(0.1, std::nullopt, 10.0, obs({el(C::Red)}, 0.1)));
  EXPECT_EQ(none.decision, JudgeDecision::None);
  EXPECT_EQ(none.verdict, SignalVerdict::NotEvaluated);
  EXPECT_EQ(none.state, JudgeState::Approach);
  EXPECT_FALSE(none.stop_point_distance.has_value());
}

TEST(TrafficLightJudge, GreenPasses) {
  TrafficLightJudge judge;
  for (int k = 0; k < 5; ++k) {
    const auto r = judge.step(green_at(0.1 * k, 50.0 - k, 10.0));
    EXPECT_EQ(r.decision, JudgeDecision::Pass);
    EXPECT_EQ(r.verdict, SignalVerdict::Go);
    EXPECT_FALSE(r.is_stop_signal);
    EXPECT_EQ(r.zone, JudgeZone::None);
  }
}

// ---- §L1.5 hysteresis --------------------------------------------------------------------------

TEST(Hysteresis, ThirdStopCycleStopsAtATenthOfASecondEvenWithAccumulatedClockError) {
  // docs/behaviour.md §L1.5: elapsed 0 and 0.1 pass, 0.2 (> 0.1) stops. The clock below accumulates
  // `t += 0.1`, so raw double differences are sometimes 0.10000000000000003; the judge compares
  // integer nanoseconds and is immune.
  bool saw_raw_difference_above_threshold = false;
  for (int start = 0; start < 40; ++start) {
    double t = 0.0;
    for (int k = 0; k < start; ++k) t += 0.1;
    TrafficLightJudge judge;
    judge.step(green_at(t, 80.0, 10.0));
    const double t0 = t + 0.1;
    const double t1 = t0 + 0.1;
    const double t2 = t1 + 0.1;
    if (t1 - t0 > 0.1) saw_raw_difference_above_threshold = true;
    const auto r0 = judge.step(red_at(t0, 79.0, 10.0));
    const auto r1 = judge.step(red_at(t1, 78.0, 10.0));
    const auto r2 = judge.step(red_at(t2, 77.0, 10.0));
    EXPECT_TRUE(r0.is_stop_signal);
    EXPECT_EQ(r0.decision, JudgeDecision::Pass) << "start " << start;
    EXPECT_EQ(r0.stop_signal_elapsed, 0.0);
    EXPECT_EQ(r1.decision, JudgeDecision::Pass) << "start " << start;
    EXPECT_DOUBLE_EQ(r1.stop_signal_elapsed, 0.1);
    EXPECT_EQ(r2.decision, JudgeDecision::Stop) << "start " << start;
    EXPECT_DOUBLE_EQ(r2.stop_signal_elapsed, 0.2);
  }
  EXPECT_TRUE(saw_raw_difference_above_threshold) << "the clock sweep should exercise the rounding hazard";
}

TEST(Hysteresis, AnyGoCycleClearsTheTimer) {
  // docs/behaviour.md §L1.5: no accumulation.
  TrafficLightJudge judge;
  EXPECT_EQ(judge.step(red_at(0.0, 80.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red_at(0.1, 79.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(green_at(0.2, 78.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red_at(0.3, 77.0, 10.0)).stop_signal_elapsed, 0.0);
  EXPECT_EQ(judge.step(red_at(0.4, 76.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red_at(0.5, 75.0, 10.0)).decision, JudgeDecision::Stop);
}

TEST(Hysteresis, ZeroHysteresisStillPassesTheFirstStopCycle) {
  // elapsed 0 is not > 0 (docs/behaviour.md §L1.2 3.5).
  TrafficLightJudge judge(no_hysteresis());
  EXPECT_EQ(judge.step(red_at(0.0, 80.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red_at(0.1, 79.0, 10.0)).decision, JudgeDecision::Stop);
}

// ---- §L1.2 stop latch ---------------------------------------------------------------------------

TEST(StopLatch, OnceStoppingItNeverSwitchesToPass) {
  TrafficLightJudge judge(no_hysteresis());
  const auto first = judged_red(judge, 60.0, 10.0);
  ASSERT_EQ(first.decision, JudgeDecision::Stop);
  EXPECT_EQ(first.zone, JudgeZone::Stoppable);
  EXPECT_TRUE(first.is_prev_state_stop);
  EXPECT_EQ(first.stop_point_distance, 60.0);
  // Now place the ego where a fresh judge would pass through (cannot stop, reachable).
  const auto r = judge.step(red_at(0.2, 30.0, 12.0));
  EXPECT_EQ(r.zone, JudgeZone::PassThroughYellow);
  EXPECT_EQ(r.decision, JudgeDecision::Stop);
  EXPECT_TRUE(r.is_prev_state_stop);
  TrafficLightJudge fresh(no_hysteresis());
  EXPECT_EQ(judged_red(fresh, 30.0, 12.0).decision, JudgeDecision::Pass);
}

TEST(StopLatch, BypassesTheHysteresisAndIsClearedOnlyByAGoCycle) {
  TrafficLightJudge judge;  // hysteresis 0.1
  judge.step(red_at(0.0, 80.0, 10.0));
  judge.step(red_at(0.1, 79.0, 10.0));
  ASSERT_EQ(judge.step(red_at(0.2, 78.0, 10.0)).decision, JudgeDecision::Stop);
  // A timed-out or unrecognised signal keeps the stop at once (latch: no hysteresis).
  EXPECT_EQ(judge.step(input(0.3, 77.0, 10.0, obs({}, 0.3))).decision, JudgeDecision::Stop);
  // A go cycle clears the latch ...
  const auto go = judge.step(green_at(0.4, 76.0, 10.0));
  EXPECT_EQ(go.decision, JudgeDecision::Pass);
  EXPECT_FALSE(go.is_prev_state_stop);
  // ... and the hysteresis applies again.
  EXPECT_EQ(judge.step(red_at(0.5, 75.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red_at(0.6, 74.0, 10.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red_at(0.7, 73.0, 10.0)).decision, JudgeDecision::Stop);
}

TEST(StopLatch, SurvivesGoOutAndReArm) {
  // docs/behaviour.md §L1.2: is_prev_state_stop is not reset on the transition to GO_OUT.
  TrafficLightJudge judge(no_hysteresis());
  ASSERT_EQ(judged_red(judge, 10.0, 3.0).decision, JudgeDecision::Stop);
  EXPECT_EQ(judge.step(red_at(0.2, -2.5, 3.0)).state, JudgeState::GoOut);
  EXPECT_TRUE(judge.is_prev_state_stop());
  EXPECT_EQ(judge.step(red_at(0.3, 50.0, 10.0)).state, JudgeState::Approach);  // re-arm step: None
  // First red cycle after re-arm stops immediately: latch still set.
  const auto r = judge.step(red_at(0.4, 49.0, 10.0));
  EXPECT_EQ(r.stop_signal_elapsed, 0.0);
  EXPECT_EQ(r.decision, JudgeDecision::Stop);
}

// ---- §L1.2 GO_OUT / re-arm ----------------------------------------------------------------------

TEST(GoOut, EnteredStrictlyBelowMinusTwoMetres) {
  TrafficLightJudge judge;
  EXPECT_EQ(judge.step(green_at(0.0, -2.0, 5.0)).state, JudgeState::Approach);
  const auto r = judge.step(green_at(0.1, std::nextafter(-2.0, -3.0), 5.0));
  EXPECT_EQ(r.state, JudgeState::GoOut);
  EXPECT_EQ(r.decision, JudgeDecision::None);
  EXPECT_EQ(r.verdict, SignalVerdict::NotEvaluated);
}

TEST(GoOut, NeverStopsAndReArmsStrictlyAboveOneMetre) {
  TrafficLightJudge judge(no_hysteresis());
  judge.step(green_at(0.0, -2.5, 5.0));
  ASSERT_EQ(judge.state(), JudgeState::GoOut);
  double t = 0.1;
  for (double d : {-1.0, 0.0, 0.5, 1.0}) {
    const auto r = judge.step(red_at(t, d, 0.0));
    t += 0.1;
    EXPECT_EQ(r.decision, JudgeDecision::None) << d;
    EXPECT_EQ(r.state, JudgeState::GoOut) << d;
    EXPECT_FALSE(r.stop_point_distance.has_value());
  }
  const auto rearm = judge.step(red_at(t, std::nextafter(1.0, 2.0), 0.0));
  EXPECT_EQ(rearm.state, JudgeState::Approach);
  EXPECT_EQ(rearm.decision, JudgeDecision::None);  // the re-arm cycle itself does nothing
  EXPECT_EQ(judge.step(red_at(t + 0.1, 1.0, 0.0)).decision, JudgeDecision::Pass);  // hysteresis cycle
  EXPECT_EQ(judge.step(red_at(t + 0.2, 1.0, 0.0)).decision, JudgeDecision::Stop);
}

TEST(GoOut, ClearsTheStopSignalTimer) {
  TrafficLightJudge judge;
  judge.step(red_at(0.0, -1.0, 5.0));
  judge.step(red_at(0.1, -1.5, 5.0));
  judge.step(red_at(0.2, -2.1, 5.0));  // GO_OUT
  judge.step(red_at(0.3, 5.0, 5.0));   // re-arm
  const auto r = judge.step(red_at(0.4, 4.5, 5.0));
  EXPECT_EQ(r.stop_signal_elapsed, 0.0);
}

// ---- §L1.3 lookup: never received, timeout, empty, latest observation -----------------------------

TEST(SignalLookup, NeverReceivedPassesInSimulation) {
  TrafficLightJudge judge;  // is_simulation = true
  for (int k = 0; k < 5; ++k) {
    const auto r = judge.step(input(0.1 * k, 30.0, 10.0, std::nullopt));
    EXPECT_EQ(r.verdict, SignalVerdict::NeverReceived);
    EXPECT_FALSE(r.is_stop_signal);
    EXPECT_EQ(r.decision, JudgeDecision::Pass);
  }
}

TEST(SignalLookup, NeverReceivedStopsOnARealVehicle) {
  TrafficLightJudgeParameters p;
  p.is_simulation = false;
  TrafficLightJudge judge(p);
  const auto r0 = judge.step(input(0.0, 60.0, 10.0, std::nullopt));
  EXPECT_EQ(r0.verdict, SignalVerdict::NeverReceived);
  EXPECT_TRUE(r0.is_stop_signal);
  EXPECT_EQ(r0.decision, JudgeDecision::Pass);  // hysteresis
  judge.step(input(0.1, 59.0, 10.0, std::nullopt));
  EXPECT_EQ(judge.step(input(0.2, 58.0, 10.0, std::nullopt)).decision, JudgeDecision::Stop);
}

TEST(SignalLookup, TimedOutStrictlyAfterOneSecondThenStops) {
  TrafficLightJudge judge;
  double t = 0.0;
  judge.step(green_at(t, 80.0, 10.0));  // stamp 0
  TrafficLightJudgeResult r;
  for (int k = 1; k <= 10; ++k) {  // t accumulates to ~1.0 (0.9999999999999999)
    t += 0.1;
    r = judge.step(input(t, 80.0 - k, 10.0, std::nullopt));
    EXPECT_EQ(r.verdict, SignalVerdict::Go) << t;
  }
  t += 0.1;  // 1.1
  r = judge.step(input(t, 69.0, 10.0, std::nullopt));
  EXPECT_EQ(r.verdict, SignalVerdict::TimedOut);
  EXPECT_TRUE(r.is_stop_signal);
  EXPECT_EQ(r.decision, JudgeDecision::Pass);  // first stop cycle: hysteresis
  t += 0.1;
  judge.step(input(t, 68.0, 10.0, std::nullopt));
  t += 0.1;
  r = judge.step(input(t, 67.0, 10.0, std::nullopt));
  EXPECT_EQ(r.decision, JudgeDecision::Stop);
  const std::string reason = explain(r, input(t, 67.0, 10.0, std::nullopt), judge.parameters());
  EXPECT_NE(reason.find("timed out"), std::string::npos) << reason;
}

TEST(SignalLookup, TimeoutComparesTheStampNotTheDeliveryTime) {
  // A late (latency) observation is as old as its stamp.
  TrafficLightJudge judge;
  const auto fresh = judge.step(input(5.0, 80.0, 10.0, obs({el(C::Green)}, 4.0)));
  EXPECT_EQ(fresh.verdict, SignalVerdict::Go);  // age exactly 1.0: not timed out
  const auto stale = judge.step(input(5.1, 79.0, 10.0, obs({el(C::Green)}, 4.0)));
  EXPECT_EQ(stale.verdict, SignalVerdict::TimedOut);
}

TEST(SignalLookup, LastObservationStaysInForceUntilReplaced) {
  TrafficLightJudge judge;
  judge.step(input(0.0, 80.0, 10.0, obs({el(C::Red)}, 0.0)));
  EXPECT_EQ(judge.step(input(0.1, 79.0, 10.0, std::nullopt)).verdict, SignalVerdict::Stop);
  EXPECT_EQ(judge.step(input(0.2, 78.0, 10.0, obs({el(C::Green)}, 0.2))).verdict, SignalVerdict::Go);
  EXPECT_EQ(judge.step(input(0.3, 77.0, 10.0, std::nullopt)).verdict, SignalVerdict::Go);
}

TEST(SignalLookup, DeliveredButNothingRecognisedIsAStopSignal) {
  TrafficLightJudge judge;
  const auto r = judge.step(input(0.0, 80.0, 10.0, obs({}, 0.0)));
  EXPECT_EQ(r.verdict, SignalVerdict::Stop);
  EXPECT_TRUE(r.is_stop_signal);
  EXPECT_EQ(judge.step(input(0.1, 80.0, 10.0, obs({el(C::Unknown, S::Unknown)}, 0.1))).verdict, SignalVerdict::Stop);
}

TEST(SignalLookup, ObservationDeliveredWhileNotLookingIsRemembered) {
  // Like the node's signal map: an observation received in GO_OUT (or without a stop point) is the
  // latest one when the module next looks.
  TrafficLightJudgeParameters p;
  p.is_simulation = false;
  TrafficLightJudge judge(p);
  judge.step(input(0.0, -3.0, 5.0, std::nullopt));                   // GO_OUT
  judge.step(input(0.1, 0.0, 5.0, obs({el(C::Green)}, 0.1)));        // GO_OUT, observation arrives
  judge.step(input(0.2, std::nullopt, 5.0, std::nullopt));           // no stop point
  judge.step(input(0.3, 50.0, 5.0, std::nullopt));                   // re-arm
  const auto r = judge.step(input(0.4, 49.0, 5.0, std::nullopt));
  EXPECT_EQ(r.verdict, SignalVerdict::Go);
}

TEST(SignalLookup, HighestConfidencePerShapeDecides) {
  // Decision "highest reliability wins".
  TrafficLightJudge judge;
  EXPECT_EQ(judge.step(input(0.0, 80.0, 10.0, obs({el(C::Green, S::Circle, 0.6), el(C::Red, S::Circle, 0.9)}, 0.0)))
                .verdict,
            SignalVerdict::Stop);
  EXPECT_EQ(judge.step(input(0.1, 80.0, 10.0, obs({el(C::Green, S::Circle, 0.95), el(C::Red, S::Circle, 0.9)}, 0.1)))
                .verdict,
            SignalVerdict::Go);
  // Tie: the cautious color.
  EXPECT_EQ(judge.step(input(0.2, 80.0, 10.0, obs({el(C::Green, S::Circle, 0.9), el(C::Red, S::Circle, 0.9)}, 0.2)))
                .verdict,
            SignalVerdict::Stop);
}

TEST(SignalLookup, ArrowsMatchedToTurnDirection) {
  const auto red_with_left_arrow = obs({el(C::Red), el(C::Green, S::LeftArrow)}, 0.0);
  const std::vector<std::pair<LaneTurnDirection, SignalVerdict>> cases = {
      {LaneTurnDirection::Left, SignalVerdict::Go},
      {LaneTurnDirection::Right, SignalVerdict::Stop},
      {LaneTurnDirection::Straight, SignalVerdict::Stop},
      {LaneTurnDirection::Else, SignalVerdict::Stop}};
  for (const auto& [dir, expected] : cases) {
    TrafficLightJudge judge;
    auto in = input(0.0, 50.0, 10.0, red_with_left_arrow);
    in.turn_direction = dir;
    EXPECT_EQ(judge.step(in).verdict, expected) << to_string(dir);
  }
  // The arrow must be green.
  TrafficLightJudge judge;
  auto in = input(0.0, 50.0, 10.0, obs({el(C::Red), el(C::Amber, S::LeftArrow)}, 0.0));
  in.turn_direction = LaneTurnDirection::Left;
  EXPECT_EQ(judge.step(in).verdict, SignalVerdict::Stop);
}

// ---- §L1.6 restart suppression ------------------------------------------------------------------

TEST(RestartSuppression, StoppedStrictlyInsideTheWindowStaysPut) {
  for (double d : {0.5, 0.75, 1.0, 0.4, 1.1}) {
    TrafficLightJudge judge;
    auto in = red_at(0.0, d, 0.0);
    in.is_vehicle_stopped = true;
    const auto r = judge.step(in);
    const bool inside = d > 0.5 && d < 1.0;
    EXPECT_EQ(r.restart_suppressed, inside) << d;
    if (inside) {
      // Raw is_stop: applies already in the first (hysteresis) cycle; stop where the ego stands.
      EXPECT_EQ(r.decision, JudgeDecision::Stop);
      EXPECT_EQ(r.stop_point_distance, 0.0);
      EXPECT_FALSE(r.to_be_stopped);
      EXPECT_FALSE(r.is_prev_state_stop);  // latch not updated on this branch
    } else {
      EXPECT_EQ(r.decision, JudgeDecision::Pass) << d;  // hysteresis cycle
    }
  }
}

TEST(RestartSuppression, NeedsStoppedAndAStopSignal) {
  TrafficLightJudge judge;
  auto moving = red_at(0.0, 0.75, 0.3);
  moving.is_vehicle_stopped = false;
  EXPECT_FALSE(judge.step(moving).restart_suppressed);
  auto green = green_at(0.1, 0.75, 0.0);
  green.is_vehicle_stopped = true;
  const auto r = judge.step(green);
  EXPECT_FALSE(r.restart_suppressed);
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
}

TEST(RestartSuppression, VehicleStoppedHelper) {
  EXPECT_TRUE(is_vehicle_stopped(0.0));
  EXPECT_TRUE(is_vehicle_stopped(0.0009));
  EXPECT_TRUE(is_vehicle_stopped(-0.0009));
  EXPECT_FALSE(is_vehicle_stopped(0.001));
  // Autoware's isVehicleStopped tests the signed speed: reversing is "stopped".
  EXPECT_TRUE(is_vehicle_stopped(-0.5));
  EXPECT_TRUE(is_vehicle_stopped(-0.001));
}

// ---- §L2.3 predicates at their boundaries and §L2.6 zones ------------------------------------------

TEST(PassJudge, JudgeDistEqualToDIsNotStoppable) {
  TrafficLightJudgeParameters p = no_hysteresis();
  p.yellow_lamp_period = 10.0;  // everything reachable
  const double v = 12.0;
  const double judge_dist = calc_judge_line_dist_with_jerk_limit(v, 0.0, p.max_accel, p.max_jerk, p.delay_response_time);
  {
    TrafficLightJudge judge(p);
    const auto r = judged_red(judge, judge_dist, v);
    EXPECT_EQ(r.judge_dist, judge_dist);
    EXPECT_EQ(r.zone, JudgeZone::PassThroughYellow);
    EXPECT_EQ(r.decision, JudgeDecision::Pass);
    EXPECT_FALSE(r.is_prev_state_stop);
  }
  {
    TrafficLightJudge judge(p);
    const auto r = judged_red(judge, std::nextafter(judge_dist, 1e9), v);
    EXPECT_EQ(r.zone, JudgeZone::OptionalZone);
    EXPECT_EQ(r.decision, JudgeDecision::Stop);
  }
}

TEST(PassJudge, DEqualToYellowLampLineIsNotReachable) {
  const double v = 12.0;  // judge line ~35.04 m > yellow lamp line 33.0 m
  const double line = v * 2.75;
  ASSERT_EQ(line, 33.0);
  {
    TrafficLightJudge judge(no_hysteresis());
    const auto r = judged_red(judge, 33.0, v);
    EXPECT_GT(r.judge_dist, 33.0);
    EXPECT_EQ(r.yellow_lamp_line, 33.0);
    EXPECT_EQ(r.zone, JudgeZone::DilemmaZone);
    EXPECT_EQ(r.decision, JudgeDecision::EmergencyStop);
    EXPECT_EQ(r.stop_point_distance, 33.0);
  }
  {
    TrafficLightJudge judge(no_hysteresis());
    const auto r = judged_red(judge, std::nextafter(33.0, 0.0), v);
    EXPECT_EQ(r.zone, JudgeZone::PassThroughYellow);
    EXPECT_EQ(r.decision, JudgeDecision::Pass);
  }
}

TEST(PassJudge, VelocityEqualToSlowThresholdIsNotSlow) {
  const double d = 0.5;  // inside the judge line at 2 m/s, and reachable
  {
    TrafficLightJudge judge(no_hysteresis());
    const auto r = judged_red(judge, d, 2.0);
    EXPECT_GE(r.judge_dist, d);
    EXPECT_EQ(r.zone, JudgeZone::PassThroughYellow);
    EXPECT_EQ(r.decision, JudgeDecision::Pass);
  }
  {
    TrafficLightJudge judge(no_hysteresis());
    const auto r = judged_red(judge, d, std::nextafter(2.0, 0.0));
    EXPECT_EQ(r.zone, JudgeZone::Slow);
    EXPECT_EQ(r.decision, JudgeDecision::Stop);
  }
}

TEST(PassJudge, ZonesAndDecisions) {
  struct Case {
    double d, v;
    JudgeZone zone;
    JudgeDecision decision;
  };
  // v = 10: judge line 25.62 m, yellow lamp line 27.5 m (no dilemma zone);
  // v = 12: judge line 35.04 m, yellow lamp line 33.0 m (dilemma zone 33.0 <= d <= 35.04).
  const std::vector<Case> cases = {
      {60.0, 10.0, JudgeZone::Stoppable, JudgeDecision::Stop},
      {26.5, 10.0, JudgeZone::OptionalZone, JudgeDecision::Stop},   // Decision: optional zone stops
      {20.0, 10.0, JudgeZone::PassThroughYellow, JudgeDecision::Pass},
      {34.0, 12.0, JudgeZone::DilemmaZone, JudgeDecision::EmergencyStop},  // Decision
      {30.0, 12.0, JudgeZone::PassThroughYellow, JudgeDecision::Pass},
      {1.0, 1.5, JudgeZone::Slow, JudgeDecision::Stop},
      {-1.0, 5.0, JudgeZone::PassThroughYellow, JudgeDecision::Pass},  // past the stop point, moving
      {-1.0, 1.0, JudgeZone::Slow, JudgeDecision::Stop},               // past it, slow: stop behind
  };
  for (const auto& c : cases) {
    TrafficLightJudge judge(no_hysteresis());
    const auto r = judged_red(judge, c.d, c.v);
    const std::string reason = explain(r, red_at(0.1, c.d, c.v), judge.parameters());
    EXPECT_EQ(r.zone, c.zone) << c.d << " " << c.v << ": " << reason;
    EXPECT_EQ(r.decision, c.decision) << c.d << " " << c.v << ": " << reason;
    EXPECT_FALSE(reason.empty());
  }
}

TEST(PassJudge, RedInReachIsPassedToo) {
  // docs/behaviour.md §L2.5/§L2.6: the pass judge does not look at the color.
  TrafficLightJudge judge(no_hysteresis());
  const auto r = judged_red(judge, 20.0, 10.0);
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
  const std::string reason = explain(r, red_at(0.1, 20.0, 10.0), judge.parameters());
  EXPECT_NE(reason.find("can pass through"), std::string::npos) << reason;
}

TEST(PassJudge, DisabledAlwaysStopsAndCannotStopMeansEmergency) {
  TrafficLightJudgeParameters p = no_hysteresis();
  p.enable_pass_judge = false;
  {
    TrafficLightJudge judge(p);
    const auto r = judged_red(judge, 20.0, 10.0);
    EXPECT_EQ(r.zone, JudgeZone::PassThroughYellow);
    EXPECT_EQ(r.decision, JudgeDecision::EmergencyStop);
  }
  {
    TrafficLightJudge judge(p);
    EXPECT_EQ(judged_red(judge, 60.0, 10.0).decision, JudgeDecision::Stop);
  }
}

TEST(PassJudge, StopKindIsFixedWhenTheStopIsInserted) {
  // A normal stop stays Stop in its last metres (judge line with dead time > d, v above 2 m/s) ...
  {
    TrafficLightJudge judge(no_hysteresis());
    ASSERT_EQ(judged_red(judge, 60.0, 10.0).decision, JudgeDecision::Stop);
    const auto r = judge.step(red_at(0.2, 1.0, 2.5, -1.0));
    EXPECT_EQ(r.zone, JudgeZone::PassThroughYellow);
    EXPECT_EQ(r.decision, JudgeDecision::Stop);
  }
  // ... and an emergency stop stays EmergencyStop while it brakes into a stoppable state.
  {
    TrafficLightJudge judge(no_hysteresis());
    ASSERT_EQ(judged_red(judge, 34.0, 12.0).decision, JudgeDecision::EmergencyStop);
    const auto r = judge.step(red_at(0.2, 20.0, 3.0, -5.0));
    EXPECT_EQ(r.zone, JudgeZone::Stoppable);
    EXPECT_EQ(r.decision, JudgeDecision::EmergencyStop);
    // After a go cycle a new stop is classified afresh.
    judge.step(green_at(0.3, 19.0, 3.0));
    judge.step(red_at(0.4, 18.0, 3.0));
    EXPECT_EQ(judge.step(red_at(0.5, 18.0, 3.0)).decision, JudgeDecision::Stop);
  }
}

TEST(PassJudge, JudgeLineUsesTheCommonParameters) {
  TrafficLightJudgeParameters p;
  p.max_accel = -4.0;
  p.max_jerk = -10.0;
  p.delay_response_time = 0.2;
  TrafficLightJudge judge(p);
  const auto r = judge.step(green_at(0.0, 50.0, 15.0));
  EXPECT_EQ(r.judge_dist, calc_judge_line_dist_with_jerk_limit(15.0, 0.0, -4.0, -10.0, 0.2));
  EXPECT_EQ(r.yellow_lamp_line, 15.0 * 2.75);
}

// ---- misc ---------------------------------------------------------------------------------------

TEST(TrafficLightJudge, DistanceToStopPointSubtractsTheMargin) {
  EXPECT_EQ(distance_to_stop_point(30.0, 0.0), 30.0);
  EXPECT_EQ(distance_to_stop_point(30.0, 1.5), 28.5);
}

TEST(TrafficLightJudge, InvalidParametersThrow) {
  const auto bad = [](auto mutate) {
    TrafficLightJudgeParameters p;
    mutate(p);
    EXPECT_THROW(TrafficLightJudge{p}, std::invalid_argument);
  };
  bad([](auto& p) { p.tl_state_timeout = -1.0; });
  bad([](auto& p) { p.stop_time_hysteresis = std::numeric_limits<double>::quiet_NaN(); });
  bad([](auto& p) { p.max_jerk = 0.0; });
  bad([](auto& p) { p.max_accel = 0.0; });
  bad([](auto& p) { p.yellow_lamp_period = -0.1; });
  bad([](auto& p) {
    p.restart_suppression.min_behind_distance_to_stop = 2.0;
    p.restart_suppression.max_behind_distance_to_stop = 1.0;
  });
}

TEST(TrafficLightJudge, InvalidInputThrowsAndLeavesTheStateAlone) {
  TrafficLightJudge judge(no_hysteresis());
  judged_red(judge, 60.0, 10.0);
  ASSERT_TRUE(judge.is_prev_state_stop());
  EXPECT_THROW(judge.step(red_at(std::numeric_limits<double>::quiet_NaN(), 59.0, 10.0)), std::invalid_argument);
  EXPECT_THROW(judge.step(red_at(0.2, std::numeric_limits<double>::infinity(), 10.0)), std::invalid_argument);
  EXPECT_THROW(judge.step(input(0.2, 50.0, 10.0, obs({}, std::numeric_limits<double>::quiet_NaN()))),
               std::invalid_argument);
  EXPECT_TRUE(judge.is_prev_state_stop());
  EXPECT_EQ(judge.step(red_at(0.2, 59.0, 10.0)).decision, JudgeDecision::Stop);
}

// Found by tests/fuzz/fuzz_traffic_light_judge: a finite but huge stamp overflowed now - stamp
// (signed overflow, UB) when converted to nanoseconds. Times now saturate at +-4e9 s.
TEST(TrafficLightJudge, HugeFiniteTimesSaturate) {
  TrafficLightJudge judge(no_hysteresis());
  const double huge = std::numeric_limits<double>::max();
  // A stamp far in the past: timed out (a stop), not an overflow.
  EXPECT_EQ(judge.step(input(0.1, 50.0, 10.0, obs({el(C::Green)}, -huge))).verdict, SignalVerdict::TimedOut);
  // A stamp far in the future: not timed out, the green is looked at.
  EXPECT_EQ(judge.step(input(0.2, 50.0, 10.0, obs({el(C::Green)}, huge))).verdict, SignalVerdict::Go);
  // now itself huge, with the timer running from a normal time.
  TrafficLightJudge other(no_hysteresis());
  other.step(red_at(0.1, 60.0, 10.0));
  const TrafficLightJudgeResult r = other.step(input(huge, 59.0, 10.0, obs({el(C::Red)}, -huge)));
  EXPECT_TRUE(r.is_stop_signal);
  EXPECT_GE(r.stop_signal_elapsed, 0.0);
  TrafficLightJudgeParameters p = no_hysteresis();
  p.tl_state_timeout = 1e300;
  p.stop_time_hysteresis = 1e300;
  TrafficLightJudge saturated(p);
  EXPECT_EQ(saturated.step(input(huge, 50.0, 10.0, obs({el(C::Red)}, huge))).verdict, SignalVerdict::Stop);
}

TEST(TrafficLightJudge, ResetForgetsEverything) {
  TrafficLightJudgeParameters p = no_hysteresis();
  p.is_simulation = false;
  TrafficLightJudge judge(p);
  judged_red(judge, 60.0, 10.0);
  judge.step(red_at(0.2, -3.0, 10.0));
  judge.reset();
  EXPECT_EQ(judge.state(), JudgeState::Approach);
  EXPECT_FALSE(judge.is_prev_state_stop());
  EXPECT_EQ(judge.step(input(0.3, 50.0, 10.0, std::nullopt)).verdict, SignalVerdict::NeverReceived);
}

}  // namespace
}  // namespace signalsim
