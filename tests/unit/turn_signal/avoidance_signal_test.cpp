// docs/behaviour.md §T8.2 "Avoidance", §T8.3, §T12.1.13: target-line selection, deviation guard, ignore set,
// OVERWRITE with the previous module's request; the blinker while waiting for approval per
// candidate_path_turn_signal (Autoware's planWaitingApproval).
#include <gtest/gtest.h>

#include "behavior_test_helpers.hpp"
#include "turn_signal/behavior_modules.hpp"

namespace signalsim {
namespace {

using test::ego_front;
using test::request;
using test::same_info;

using test::kParams;

AvoidanceShiftLine line(std::uint64_t id, double s0, double s1, double a, double b) {
  return AvoidanceShiftLine{.id = id, .s_start = s0, .s_end = s1, .shift_start = a, .shift_end = b};
}

/// Ego with base_link at s_base.
EgoOnRoute ego_base(double s_base, double speed) { return ego_front(s_base + test::kB2F, speed); }

// ---- target selection ---------------------------------------------------------------------------

TEST(AvoidanceTargetLine, NoLinesNoTarget) {
  EXPECT_FALSE(AvoidanceSignal::target_line({}, ego_base(0.0, 10.0), kParams).has_value());
}

TEST(AvoidanceTargetLine, SingleLineIsTheTarget) {
  const auto t = AvoidanceSignal::target_line({line(1, 100, 120, 0, 2)}, ego_base(150.0, 10.0), kParams);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(t->id, 1u);
}

TEST(AvoidanceTargetLine, NearLineWhileItsStartIsAhead) {
  const std::vector<AvoidanceShiftLine> lines{line(1, 100, 120, 0, 2), line(2, 125, 145, 2, 0)};
  EXPECT_EQ(AvoidanceSignal::target_line(lines, ego_base(99.0, 10.0), kParams)->id, 1u);
  // s1's start exactly at base_link is not "ahead": the far line is considered (125 - 100 = 25 < 30).
  EXPECT_EQ(AvoidanceSignal::target_line(lines, ego_base(100.0, 10.0), kParams)->id, 2u);
}

TEST(AvoidanceTargetLine, FarLineWithinSpeedTimesMaxPrepareTimeStrict) {
  // v = 10 m/s, max_prepare_time = 3 s -> 30 m.
  const std::vector<AvoidanceShiftLine> near_far{line(1, 90, 110, 0, 2), line(2, 129, 149, 2, 0)};
  EXPECT_EQ(AvoidanceSignal::target_line(near_far, ego_base(100.0, 10.0), kParams)->id, 2u);  // 29 < 30
  const std::vector<AvoidanceShiftLine> at_limit{line(1, 90, 110, 0, 2), line(2, 130, 150, 2, 0)};
  EXPECT_EQ(AvoidanceSignal::target_line(at_limit, ego_base(100.0, 10.0), kParams)->id, 1u);  // 30 not < 30
  EXPECT_EQ(AvoidanceSignal::target_line(near_far, ego_base(100.0, 0.0), kParams)->id, 1u);  // standstill
  BehaviorSignalParameters longer;
  longer.max_prepare_time = 4.0;
  EXPECT_EQ(AvoidanceSignal::target_line(at_limit, ego_base(100.0, 10.0), longer)->id, 2u);
}

TEST(AvoidanceTargetLine, SameSideLinesAreSkipped) {
  const std::vector<AvoidanceShiftLine> lines{line(1, 90, 100, 0, 1), line(2, 105, 115, 1, 2),
                                              line(3, 120, 130, 2, 0)};
  EXPECT_EQ(AvoidanceSignal::target_line(lines, ego_base(100.0, 10.0), kParams)->id, 3u);
  // Without an opposite line the first line stays the target, however far the ego is.
  const std::vector<AvoidanceShiftLine> same{line(1, 90, 100, 0, 1), line(2, 105, 115, 1, 2)};
  EXPECT_EQ(AvoidanceSignal::target_line(same, ego_base(110.0, 10.0), kParams)->id, 1u);
}

TEST(AvoidanceTargetLine, ZeroRelativeShiftCountsAsOppositeSide) {
  const std::vector<AvoidanceShiftLine> lines{line(1, 90, 100, 0, 1), line(2, 110, 120, 1, 1)};
  EXPECT_EQ(AvoidanceSignal::target_line(lines, ego_base(100.0, 10.0), kParams)->id, 2u);
  const std::vector<AvoidanceShiftLine> zero_first{line(1, 90, 100, 1, 1), line(2, 110, 120, 1, 3)};
  EXPECT_EQ(AvoidanceSignal::target_line(zero_first, ego_base(100.0, 10.0), kParams)->id, 2u);
}

TEST(AvoidanceTargetLine, DecidedAtTheFirstOppositeLineOnly) {
  // s2 is opposite but far: s1 wins, although s3 (also opposite to s1) would be near enough.
  const std::vector<AvoidanceShiftLine> lines{line(1, 90, 100, 0, 2), line(2, 200, 210, 2, 0),
                                              line(3, 110, 120, 0, -2)};
  EXPECT_EQ(AvoidanceSignal::target_line(lines, ego_base(100.0, 10.0), kParams)->id, 1u);
}

// ---- update ---------------------------------------------------------------------------------------

AvoidanceSignal::Input avoidance_input(std::vector<AvoidanceShiftLine> lines, double current = 0.0) {
  AvoidanceSignal::Input in;
  in.shift_lines = std::move(lines);
  in.signal = test::shift_input();
  in.signal.current_shift_length = current;
  in.planned_shift_at_ego = current;
  return in;
}

TEST(AvoidanceSignal, SignalsTheTargetLineAndStampsTheSource) {
  AvoidanceSignal module;
  const auto ego = ego_front(95.0);
  const auto out = module.update(TurnSignalInfo{}, avoidance_input({line(1, 100, 120, 0, 2)}), ego, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(out.source, RequestSource::Avoidance);
  EXPECT_EQ(out.desired_start, ego.s_base);
  EXPECT_EQ(out.required_start, 100.0);
  EXPECT_EQ(out.required_end, 120.0);
}

TEST(AvoidanceSignal, ReturnShiftGetsItsOwnRequest) {
  // The "second section": after the shift out, the return line becomes the target (opposite side).
  AvoidanceSignal module;
  const std::vector<AvoidanceShiftLine> lines{line(1, 100, 120, 0, 2), line(2, 140, 160, 2, 0)};
  const auto out = module.update(TurnSignalInfo{}, avoidance_input(lines, 2.0), ego_base(125.0, 5.0), kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(out.required_start, 140.0);
  EXPECT_EQ(out.desired_end, 160.0);
}

TEST(AvoidanceSignal, NothingToDoPassesThePreviousRequest) {
  AvoidanceSignal module;
  const auto previous = request(TurnIndicator::EnableRight, 0, 50, 10, 40, RequestSource::PullOut);
  const auto ego = ego_base(100.0, 5.0);
  EXPECT_PRED2(same_info, module.update(previous, avoidance_input({}), ego, kParams), previous);
  // A line that ended behind base_link is dropped; one ending exactly at it is kept.
  EXPECT_PRED2(same_info, module.update(previous, avoidance_input({line(1, 70, 99.5, 0, 2)}), ego, kParams), previous);
  const auto kept = module.update(TurnSignalInfo{}, avoidance_input({line(1, 80, 100, 0, 2)}), ego, kParams);
  EXPECT_EQ(kept.source, RequestSource::Avoidance);
}

TEST(AvoidanceSignal, LargeLateralDeviationPassesThePreviousRequest) {
  AvoidanceSignal module;
  const auto previous = request(TurnIndicator::EnableRight, 0, 50, 10, 40, RequestSource::PullOut);
  auto in = avoidance_input({line(1, 100, 120, 0, 2)});
  in.signal.current_shift_length = 1.25;
  in.planned_shift_at_ego = 0.0;  // 1.25 > 1.0
  EXPECT_PRED2(same_info, module.update(previous, in, ego_front(95.0), kParams), previous);
  in.signal.current_shift_length = -1.0;  // |-1.0| is not > 1.0: processed
  const auto out = module.update(TurnSignalInfo{}, in, ego_front(95.0), kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
}

TEST(AvoidanceSignal, IgnoredLinesStayIgnoredUntilReset) {
  AvoidanceSignal module;
  const auto ego = ego_front(95.0);
  // Too small a shift: ignored, and the id is latched.
  auto small = module.update(TurnSignalInfo{}, avoidance_input({line(7, 100, 120, 0, 0.2)}), ego, kParams);
  EXPECT_EQ(small.turn, TurnIndicator::NoCommand);
  EXPECT_TRUE(module.is_ignored(7));
  // The same id now with a large shift: still ignored -> the previous request passes through.
  const auto previous = request(TurnIndicator::EnableRight, 0, 50, 10, 40, RequestSource::PullOut);
  EXPECT_PRED2(same_info, module.update(previous, avoidance_input({line(7, 100, 120, 0, 2)}), ego, kParams),
               previous);
  // Another id is evaluated.
  EXPECT_EQ(module.update(TurnSignalInfo{}, avoidance_input({line(8, 100, 120, 0, 2)}), ego, kParams).turn,
            TurnIndicator::EnableLeft);
  module.reset();
  EXPECT_FALSE(module.is_ignored(7));
  EXPECT_EQ(module.update(TurnSignalInfo{}, avoidance_input({line(7, 100, 120, 0, 2)}), ego, kParams).turn,
            TurnIndicator::EnableLeft);
}

TEST(AvoidanceSignal, TooEarlyIsNotLatched) {
  AvoidanceSignal module;
  const auto out = module.update(TurnSignalInfo{}, avoidance_input({line(3, 100, 120, 0, 2)}), ego_front(50.0), kParams);
  EXPECT_EQ(out.turn, TurnIndicator::NoCommand);
  EXPECT_FALSE(module.is_ignored(3));
  EXPECT_EQ(module.update(TurnSignalInfo{}, avoidance_input({line(3, 100, 120, 0, 2)}), ego_front(95.0), kParams).turn,
            TurnIndicator::EnableLeft);
}

TEST(AvoidanceSignal, ModuleForcesAvoidanceFlags) {
  AvoidanceSignal module;
  auto in = avoidance_input({line(1, 100, 120, 0, 2)});
  in.signal.is_pull_out = true;  // ignored by the module: the hatched test applies
  in.signal.left_hatched_road_marking_only = true;
  EXPECT_EQ(module.update(TurnSignalInfo{}, in, ego_front(95.0), kParams).turn, TurnIndicator::NoCommand);
  EXPECT_TRUE(module.is_ignored(1));
}

TEST(AvoidanceSignal, OverwritesThePreviousRequest) {
  const auto ego = ego_front(95.0);
  // Previous LEFT until 200; the avoidance RIGHT starts before that -> the avoidance wins.
  const auto previous = request(TurnIndicator::EnableLeft, 0, 200, 10, 150, RequestSource::PullOut);
  AvoidanceSignal a;
  EXPECT_EQ(a.update(previous, avoidance_input({line(1, 100, 120, 0, -2)}), ego, kParams).turn,
            TurnIndicator::EnableRight);
  // A NONE (too early) spans the whole path from its front: it also replaces the previous request.
  AvoidanceSignal b;
  const auto none = b.update(previous, avoidance_input({line(1, 100, 120, 0, -2)}), ego_front(50.0), kParams);
  EXPECT_EQ(none.turn, TurnIndicator::NoCommand);
  EXPECT_EQ(none.source, RequestSource::Avoidance);
  // A previous request that ended before the avoidance path starts is kept.
  auto in = avoidance_input({line(1, 100, 120, 0, -2)});
  in.signal.path_front = 80.0;
  const auto ended = request(TurnIndicator::EnableLeft, 0, 70, 10, 60, RequestSource::PullOut);
  AvoidanceSignal c;
  EXPECT_PRED2(same_info, c.update(ended, in, ego_front(50.0), kParams), ended);
}

// ---- waiting for approval (planWaitingApproval) --------------------------------------------------

AvoidanceSignal::Input waiting(CandidateTurnSignalPolicy policy) {
  auto in = avoidance_input({line(1, 100, 120, 0, 2), line(2, 140, 160, 2, 0)});
  in.phase = AvoidanceSignal::Phase::WaitingApproval;
  in.policy = policy;
  return in;
}

// A previous request the avoidance's own would overwrite (it ends after the shift starts).
TurnSignalInfo overwritten() { return request(TurnIndicator::EnableRight, 0, 200, 10, 150, RequestSource::PullOut); }

TEST(AvoidanceWaitingApproval, NoneAndStopOnApprovalPassThePreviousRequest) {
  for (const auto policy : {CandidateTurnSignalPolicy::None, CandidateTurnSignalPolicy::StopOnApproval}) {
    AvoidanceSignal module;
    // Moving and at rest, the front within the prep distance of the shift start: still the previous
    // request (EMPTY, or one the registered lines' request would replace).
    EXPECT_PRED2(same_info, module.update(TurnSignalInfo{}, waiting(policy), ego_front(95.0, 5.0), kParams),
                 TurnSignalInfo{});
    EXPECT_PRED2(same_info, module.update(TurnSignalInfo{}, waiting(policy), ego_front(99.0, 0.0), kParams),
                 TurnSignalInfo{});
    EXPECT_PRED2(same_info, module.update(overwritten(), waiting(policy), ego_front(99.0, 0.0), kParams), overwritten());
    EXPECT_TRUE(module.ignored_ids().empty());
  }
  // Registered, the same lines replace that request.
  AvoidanceSignal running;
  auto in = waiting(CandidateTurnSignalPolicy::None);
  in.phase = AvoidanceSignal::Phase::Running;
  EXPECT_EQ(running.update(overwritten(), in, ego_front(99.0, 0.0), kParams).turn, TurnIndicator::EnableLeft);
}

TEST(AvoidanceWaitingApproval, StoppedCandidateSignalsOnlyBelowPointThreeMetresPerSecond) {
  AvoidanceSignal module;
  const auto in = waiting(CandidateTurnSignalPolicy::StoppedCandidate);
  const auto at_rest = module.update(TurnSignalInfo{}, in, ego_front(99.0, 0.29), kParams);
  EXPECT_EQ(at_rest.turn, TurnIndicator::EnableLeft);  // the candidate shift out, as if registered
  EXPECT_EQ(at_rest.source, RequestSource::Avoidance);
  EXPECT_EQ(at_rest.required_start, 100.0);
  EXPECT_EQ(at_rest.required_end, 120.0);
  EXPECT_PRED2(same_info, module.update(overwritten(), in, ego_front(99.0, 0.3), kParams), overwritten());  // not < 0.3
  EXPECT_PRED2(same_info, module.update(TurnSignalInfo{}, in, ego_front(99.0, -0.3), kParams), TurnSignalInfo{});
  EXPECT_EQ(module.update(TurnSignalInfo{}, in, ego_front(99.0, -0.29), kParams).turn, TurnIndicator::EnableLeft);
}

TEST(AvoidanceWaitingApproval, AllCandidateSignalsWhileMovingWithTheRegisteredRules) {
  AvoidanceSignal module;
  const auto in = waiting(CandidateTurnSignalPolicy::AllCandidate);
  // §T8.1 prep distance at 5 m/s: max(15, 10) = 15 m before the shift start.
  EXPECT_EQ(module.update(TurnSignalInfo{}, in, ego_front(85.0, 5.0), kParams).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(module.update(TurnSignalInfo{}, in, ego_front(84.9, 5.0), kParams).turn, TurnIndicator::NoCommand);
  // The same request the registered lines give.
  AvoidanceSignal registered;
  auto running = in;
  running.phase = AvoidanceSignal::Phase::Running;
  EXPECT_PRED2(same_info, module.update(TurnSignalInfo{}, in, ego_front(95.0, 5.0), kParams),
               registered.update(TurnSignalInfo{}, running, ego_front(95.0, 5.0), kParams));
}

TEST(AvoidanceWaitingApproval, ACandidateIgnoreIsLatchedForGood) {
  // A candidate too small to signal is ignored as a registered one would be; after approval it stays ignored.
  AvoidanceSignal module;
  auto in = waiting(CandidateTurnSignalPolicy::AllCandidate);
  in.shift_lines = {line(5, 100, 120, 0, 0.2)};
  EXPECT_EQ(module.update(TurnSignalInfo{}, in, ego_front(95.0), kParams).turn, TurnIndicator::NoCommand);
  EXPECT_TRUE(module.is_ignored(5));
  in.phase = AvoidanceSignal::Phase::Running;
  const auto previous = request(TurnIndicator::EnableRight, 0, 50, 10, 40, RequestSource::PullOut);
  EXPECT_PRED2(same_info, module.update(previous, in, ego_front(95.0), kParams), previous);
}

TEST(AvoidanceWaitingApproval, PolicyNamesAreAutowares) {
  EXPECT_EQ(candidate_turn_signal_policy("none"), CandidateTurnSignalPolicy::None);
  EXPECT_EQ(candidate_turn_signal_policy("stopped_candidate"), CandidateTurnSignalPolicy::StoppedCandidate);
  EXPECT_EQ(candidate_turn_signal_policy("all_candidate"), CandidateTurnSignalPolicy::AllCandidate);
  EXPECT_EQ(candidate_turn_signal_policy("stop_on_approval"), CandidateTurnSignalPolicy::StopOnApproval);
  EXPECT_FALSE(candidate_turn_signal_policy("None").has_value());
}

}  // namespace
}  // namespace signalsim
