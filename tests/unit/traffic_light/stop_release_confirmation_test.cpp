// stop_release_confirmation_time (signalsim's own parameter, beyond the reference): a latched stop
// (docs/behaviour.md §L1.2 step 3.10, is_prev_state_stop) is released only once the judge has looked at no stop
// signal for that long without a break. With 0 (the default) one go cycle releases it (step 3.9), as
// in the reference. Times are integer nanoseconds (docs/behaviour.md §L1.5 choice), steps of 0.1 s.
#include <gtest/gtest.h>

#include <stdexcept>

#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {
namespace {

using C = SignalColor;

SignalObservation seen(C color, double stamp) {
  return SignalObservation{{SignalElement{color, SignalShape::Circle, SignalStatus::SolidOn, 1.0}}, stamp};
}

TrafficLightJudgeInput at(double now, double d, double v, std::optional<SignalObservation> o) {
  TrafficLightJudgeInput in;
  in.now = now;
  in.distance_to_stop_point = d;
  in.velocity = v;
  in.observation = std::move(o);
  return in;
}
TrafficLightJudgeInput red(double now, double d = 60.0, double v = 10.0) { return at(now, d, v, seen(C::Red, now)); }
TrafficLightJudgeInput green(double now, double d = 60.0, double v = 10.0) {
  return at(now, d, v, seen(C::Green, now));
}

TrafficLightJudgeParameters confirmation(double seconds) {
  TrafficLightJudgeParameters p;
  p.stop_release_confirmation_time = seconds;
  return p;
}

// Red at t = 0.0, 0.1, 0.2 s, 60 m before the stop point at 10 m/s: the third cycle has held the
// stop signal 0.2 s > stop_time_hysteresis 0.1 s and latches a normal stop (docs/behaviour.md §L1.5, §L2.6).
void latch_stop(TrafficLightJudge& judge) {
  judge.step(red(0.0));
  judge.step(red(0.1));
  const TrafficLightJudgeResult r = judge.step(red(0.2));
  ASSERT_EQ(r.decision, JudgeDecision::Stop);
  ASSERT_TRUE(r.is_prev_state_stop);
}

TEST(StopReleaseConfirmation, DefaultIsTheReference) {
  EXPECT_EQ(TrafficLightJudgeParameters{}.stop_release_confirmation_time, 0.0);
}

TEST(StopReleaseConfirmation, NegativeOrNonFiniteIsRejected) {
  EXPECT_THROW(TrafficLightJudge{confirmation(-0.1)}, std::invalid_argument);
  EXPECT_THROW(TrafficLightJudge{confirmation(std::numeric_limits<double>::infinity())}, std::invalid_argument);
}

TEST(StopReleaseConfirmation, OneMisreadGreenReleasesTheStopWithZero) {
  // docs/behaviour.md §L1.2 step 3.9: one go cycle clears is_prev_state_stop; the next red needs the
  // hysteresis again before the stop returns.
  TrafficLightJudge judge;
  latch_stop(judge);
  const auto misread = judge.step(green(0.3));
  EXPECT_EQ(misread.decision, JudgeDecision::Pass);
  EXPECT_FALSE(misread.is_prev_state_stop);
  EXPECT_FALSE(misread.release_pending);
  EXPECT_EQ(judge.step(red(0.4)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red(0.5)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(red(0.6)).decision, JudgeDecision::Stop);
}

TEST(StopReleaseConfirmation, OneMisreadGreenDoesNotReleaseTheStopWithHalfASecond) {
  TrafficLightJudge judge(confirmation(0.5));
  latch_stop(judge);
  const auto misread = judge.step(green(0.3, 59.0));
  EXPECT_EQ(misread.decision, JudgeDecision::Stop);
  ASSERT_TRUE(misread.stop_point_distance.has_value());
  EXPECT_DOUBLE_EQ(*misread.stop_point_distance, 59.0);
  EXPECT_TRUE(misread.is_prev_state_stop);
  EXPECT_TRUE(misread.release_pending);
  EXPECT_EQ(misread.verdict, SignalVerdict::Go);
  EXPECT_EQ(misread.release_elapsed, 0.0);
  const auto back = judge.step(red(0.4, 58.0));
  EXPECT_EQ(back.decision, JudgeDecision::Stop) << "the latch bypasses the hysteresis: no pass cycle";
  EXPECT_FALSE(back.release_pending);
}

TEST(StopReleaseConfirmation, MisreadNearTheLineCrossesOnRedOnlyWithoutTheFilter) {
  // The failure of the reference: latched far away, a misread green 10 m before the stop point at
  // 10 m/s releases the latch; when the red is judged again the pass judge runs as for a new stop
  // (judge line about 23 m >= d, d < yellow lamp line 27.5 m: pass through, docs/behaviour.md §L2.6).
  for (const double t : {0.0, 0.5}) {
    SCOPED_TRACE(t);
    TrafficLightJudge judge(confirmation(t));
    latch_stop(judge);
    judge.step(green(0.3, 10.0));
    JudgeDecision last = JudgeDecision::None;
    for (int k = 4; k <= 8; ++k) last = judge.step(red(k * 0.1, 10.0)).decision;
    if (t == 0.0) {
      EXPECT_EQ(last, JudgeDecision::Pass) << "released: the red is now passed through";
    } else {
      EXPECT_EQ(last, JudgeDecision::Stop) << "held: the stop decided at 60 m stands";
    }
  }
}

TEST(StopReleaseConfirmation, ReleasesAfterExactlyTheConfirmationTimeOfContinuousGreen) {
  for (const double t : {0.3, 0.5, 1.0}) {
    SCOPED_TRACE(t);
    TrafficLightJudge judge(confirmation(t));
    latch_stop(judge);
    // Green from 1.0 s on; `now` accumulated as a float sum, as a step loop does.
    double now = 1.0;
    int steps = 0;
    TrafficLightJudgeResult r;
    for (;; ++steps, now += 0.1) {
      r = judge.step(green(now));
      if (r.decision != JudgeDecision::Stop) break;
      ASSERT_TRUE(r.release_pending);
      ASSERT_LT(steps, 100);
    }
    EXPECT_EQ(r.decision, JudgeDecision::Pass);
    EXPECT_FALSE(r.is_prev_state_stop);
    EXPECT_FALSE(r.release_pending);
    // Held at elapsed 0, 0.1, ..., t - 0.1; released at the step where t has elapsed exactly.
    EXPECT_EQ(steps, static_cast<int>(t * 10 + 0.5));
    EXPECT_NEAR(r.release_elapsed, t, 1e-9);
  }
}

TEST(StopReleaseConfirmation, AStopSignalSeenAgainRestartsTheClock) {
  TrafficLightJudge judge(confirmation(0.5));
  latch_stop(judge);
  for (int k = 10; k <= 13; ++k) EXPECT_EQ(judge.step(green(k * 0.1)).decision, JudgeDecision::Stop);
  EXPECT_EQ(judge.step(red(1.4)).decision, JudgeDecision::Stop);
  // Without the restart 1.5 s would release (0.5 s after 1.0 s); the clock now starts at 1.5 s.
  for (int k = 15; k <= 19; ++k) {
    const auto r = judge.step(green(k * 0.1));
    EXPECT_EQ(r.decision, JudgeDecision::Stop) << "t=" << k * 0.1;
    EXPECT_NEAR(r.release_elapsed, (k - 15) * 0.1, 1e-9);
  }
  EXPECT_EQ(judge.step(green(2.0)).decision, JudgeDecision::Pass);
}

TEST(StopReleaseConfirmation, AStaleGreenDoesNotCountAndATimeoutIsAStopSignal) {
  // The clock runs on the stamps of the observations looked at: a green kept in force over dropouts
  // (absent observations, docs/behaviour.md §L1.3) adds nothing, and once it is older than tl_state_timeout it
  // is a stop signal (row 2).
  TrafficLightJudge judge(confirmation(0.5));
  latch_stop(judge);
  EXPECT_TRUE(judge.step(green(1.0)).release_pending);
  for (int k = 11; k <= 20; ++k) {
    const auto r = judge.step(at(k * 0.1, 60.0, 10.0, std::nullopt));
    EXPECT_EQ(r.decision, JudgeDecision::Stop) << "t=" << k * 0.1;
    EXPECT_EQ(r.release_elapsed, 0.0);
  }
  const auto timed_out = judge.step(at(2.1, 60.0, 10.0, std::nullopt));
  EXPECT_EQ(timed_out.verdict, SignalVerdict::TimedOut);
  EXPECT_EQ(timed_out.decision, JudgeDecision::Stop);
  EXPECT_FALSE(timed_out.release_pending);

  // Fresh greens at 3.0 and 3.5 s with dropouts between: released at 3.5 s.
  EXPECT_TRUE(judge.step(green(3.0)).release_pending);
  for (int k = 31; k <= 34; ++k) EXPECT_TRUE(judge.step(at(k * 0.1, 60.0, 10.0, std::nullopt)).release_pending);
  EXPECT_EQ(judge.step(green(3.5)).decision, JudgeDecision::Pass);
}

TEST(StopReleaseConfirmation, WithZeroAStaleGreenReleasesAtOnce) {
  TrafficLightJudge judge;
  latch_stop(judge);
  EXPECT_EQ(judge.step(green(1.0)).decision, JudgeDecision::Pass);
  EXPECT_EQ(judge.step(at(1.1, 60.0, 10.0, std::nullopt)).decision, JudgeDecision::Pass);
}

TEST(StopReleaseConfirmation, WithoutALatchedStopNothingIsHeld) {
  // Not decided yet (hysteresis running): a green passes at once whatever the confirmation time.
  TrafficLightJudge judge(confirmation(1.0));
  judge.step(red(0.0));
  const auto r = judge.step(green(0.1));
  EXPECT_EQ(r.decision, JudgeDecision::Pass);
  EXPECT_FALSE(r.release_pending);
}

TEST(StopReleaseConfirmation, GoOutClearsTheClock) {
  TrafficLightJudge judge(confirmation(0.5));
  latch_stop(judge);
  judge.step(green(1.0, 1.0));
  judge.step(green(1.1, 1.0));
  EXPECT_EQ(judge.step(green(1.2, -2.5)).state, JudgeState::GoOut);
  // Re-armed (d > 1 m); the latch survives GO_OUT (docs/behaviour.md §L1.2 consequences), the clock does not.
  judge.step(green(1.3, 5.0));
  const auto r = judge.step(green(1.4, 5.0));
  EXPECT_EQ(r.decision, JudgeDecision::Stop);
  EXPECT_NEAR(r.release_elapsed, 0.0, 1e-9);
}

}  // namespace
}  // namespace signalsim
