// docs/behaviour.md §T8.2 "Lane change", §T8.3, §T12.1.14: LC_SIGNAL, the activation distance, the waiting and
// running variants, the blinker-on timestamp and the prepare-time shortening.
#include <gtest/gtest.h>

#include "behavior_test_helpers.hpp"
#include "turn_signal/behavior_modules.hpp"

namespace signalsim {
namespace {

using test::ego_front;
using test::request;
using test::same_info;
using Phase = LaneChangeSignal::Phase;

using test::kParams;

LaneChangeSignal::Input lc_input(Phase phase = Phase::Running) {
  LaneChangeSignal::Input in;
  in.phase = phase;
  in.direction = TurnIndicator::EnableLeft;
  in.lane_changing_start = 100.0;
  in.lane_changing_end = 150.0;
  in.boundary_crossing = 125.0;
  in.previous_path_front = 0.0;
  in.previous_path_end = 300.0;
  return in;
}

TEST(LaneChangeSignal, LcSignalSections) {
  const auto info = LaneChangeSignal::lc_signal(TurnIndicator::EnableRight, 10.0, 60.0, 35.0, kParams);
  EXPECT_EQ(info.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(info.source, RequestSource::LaneChange);
  EXPECT_EQ(info.desired_start, 10.0);
  EXPECT_EQ(info.required_start, 10.0);
  EXPECT_EQ(info.desired_end, 60.0);
  EXPECT_EQ(info.required_end, 35.0);  // boundary crossing (signalsim default)
  BehaviorSignalParameters spec_82;
  spec_82.lane_change_required_end_at_boundary = false;
  EXPECT_EQ(LaneChangeSignal::lc_signal(TurnIndicator::EnableRight, 10.0, 60.0, 35.0, spec_82).required_end, 60.0);
  EXPECT_EQ(LaneChangeSignal::lc_signal(TurnIndicator::EnableRight, 10.0, 60.0, std::nullopt, kParams).required_end,
            60.0);
}

TEST(LaneChangeSignal, ActivatesAtThePrepareDistanceBeforeTheLateralMotion) {
  LaneChangeSignal module;
  const auto previous = request(TurnIndicator::NoCommand, 0, 300, 0, 300, RequestSource::Avoidance);
  // v = 10 -> prep = max(30, 10) = 30. front_to_start = 100 - s_front.
  EXPECT_PRED2(same_info, module.update(previous, lc_input(), ego_front(69.0, 10.0), 0.0, kParams), previous);
  EXPECT_FALSE(module.active());
  EXPECT_FALSE(module.blinker_on_since().has_value());
  const auto ego = ego_front(70.0, 10.0);  // 30 == 30: on
  const auto out = module.update(previous, lc_input(), ego, 1.0, kParams);
  EXPECT_TRUE(module.active());
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(out.source, RequestSource::LaneChange);
  EXPECT_EQ(out.desired_start, ego.s_base);  // LC_SIGNAL(ego pose, lane_changing_end)
  EXPECT_EQ(out.required_start, ego.s_base);
  EXPECT_EQ(out.desired_end, 150.0);
  EXPECT_EQ(out.required_end, 125.0);
  EXPECT_EQ(module.blinker_on_since(), 1.0);
}

TEST(LaneChangeSignal, ActivationFloorAndLatch) {
  LaneChangeSignal module;
  // v = 0 -> prep = 10.
  EXPECT_EQ(module.update(TurnSignalInfo{}, lc_input(), ego_front(89.5, 0.0), 0.0, kParams).turn,
            TurnIndicator::NoCommand);
  EXPECT_EQ(module.update(TurnSignalInfo{}, lc_input(), ego_front(90.0, 0.0), 0.1, kParams).turn,
            TurnIndicator::EnableLeft);
  // Latched: a later step that would be "too early" (e.g. after a replan further ahead) stays on.
  auto later = lc_input();
  later.lane_changing_start = 200.0;
  EXPECT_EQ(module.update(TurnSignalInfo{}, later, ego_front(91.0, 0.0), 0.2, kParams).turn,
            TurnIndicator::EnableLeft);
  module.reset();
  EXPECT_FALSE(module.active());
  EXPECT_EQ(module.update(TurnSignalInfo{}, later, ego_front(91.0, 0.0), 0.3, kParams).turn,
            TurnIndicator::NoCommand);
}

TEST(LaneChangeSignal, NoDirectionPassesThePreviousRequest) {
  LaneChangeSignal module;
  auto in = lc_input();
  for (const auto d : {TurnIndicator::NoCommand, TurnIndicator::Disable}) {
    in.direction = d;
    const auto previous = request(TurnIndicator::EnableRight, 0, 300, 0, 300, RequestSource::Avoidance);
    EXPECT_PRED2(same_info, module.update(previous, in, ego_front(95.0, 10.0), 0.0, kParams), previous);
  }
}

TEST(LaneChangeSignal, RunningOverwritesAndTracksTheBlinkerTimestamp) {
  LaneChangeSignal module;
  const auto ego = ego_front(95.0, 10.0);
  EXPECT_EQ(module.update(TurnSignalInfo{}, lc_input(), ego, 1.0, kParams).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(module.blinker_on_since(), 1.0);
  EXPECT_EQ(module.update(TurnSignalInfo{}, lc_input(), ego, 2.0, kParams).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(module.blinker_on_since(), 1.0);  // kept, not restarted

  // A previous RIGHT request that ended before the ego pose: OVERWRITE keeps it (the new desired
  // start lies after its end) and the timestamp is cleared because the output is not ours.
  const auto ended = request(TurnIndicator::EnableRight, 0, 50, 0, 50, RequestSource::Avoidance);
  EXPECT_PRED2(same_info, module.update(ended, lc_input(), ego, 3.0, kParams), ended);
  EXPECT_FALSE(module.blinker_on_since().has_value());
  EXPECT_EQ(module.update(TurnSignalInfo{}, lc_input(), ego, 4.0, kParams).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(module.blinker_on_since(), 4.0);

  // A previous request still running past the ego: the lane change replaces it.
  const auto running = request(TurnIndicator::EnableRight, 0, 200, 0, 200, RequestSource::Avoidance);
  EXPECT_EQ(module.update(running, lc_input(), ego, 5.0, kParams).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(module.blinker_on_since(), 4.0);
}

TEST(LaneChangeSignal, WaitingForApprovalGuards) {
  const auto previous = request(TurnIndicator::NoCommand, 0, 300, 0, 300, RequestSource::Avoidance);
  const auto ego = ego_front(95.0, 10.0);
  for (int guard = 0; guard < 3; ++guard) {
    LaneChangeSignal module;
    auto in = lc_input(Phase::WaitingApproval);
    if (guard == 0) in.is_normal_type = false;
    if (guard == 1) in.has_current_lanes = false;
    if (guard == 2) in.previous_path_empty = true;
    EXPECT_PRED2(same_info, module.update(previous, in, ego, 0.0, kParams), previous) << guard;
  }
}

TEST(LaneChangeSignal, WaitingForApprovalSignalsIntentionAsSoonAsPossible) {
  const auto ego = ego_front(95.0, 10.0);
  LaneChangeSignal module;
  auto out = module.update(TurnSignalInfo{}, lc_input(Phase::WaitingApproval), ego, 2.0, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(out.desired_start, ego.s_base);
  EXPECT_EQ(out.desired_end, 150.0);
  EXPECT_EQ(out.required_end, 125.0);
  EXPECT_EQ(module.blinker_on_since(), 2.0);

  auto no_path = lc_input(Phase::WaitingApproval);
  no_path.has_valid_path = false;  // PR #8571: up to the end of the previous path
  out = module.update(TurnSignalInfo{}, no_path, ego, 3.0, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(out.desired_start, ego.s_base);
  EXPECT_EQ(out.desired_end, 300.0);
  EXPECT_EQ(out.required_end, 300.0);
}

TEST(LaneChangeSignal, WaitingForApprovalTerminalVariant) {
  const auto ego = ego_front(95.0, 10.0);
  auto in = lc_input(Phase::WaitingApproval);
  in.lane_changing_end = 290.0;
  in.boundary_crossing = 285.0;
  in.current_dist_buffer_min = 5.0;
  // start = path end - (5 + min_length_for_turn_signal_activation 10 + base_link_to_front 3.7) = 281.3
  const auto previous = request(TurnIndicator::EnableRight, 0, 300, 0, 300, RequestSource::Avoidance);
  LaneChangeSignal module;
  const auto out = module.update(previous, in, ego, 1.0, kParams);
  EXPECT_EQ(out.turn, TurnIndicator::EnableLeft);
  EXPECT_DOUBLE_EQ(out.desired_start, 281.3);
  EXPECT_DOUBLE_EQ(out.required_start, 281.3);
  EXPECT_EQ(out.desired_end, 290.0);
  EXPECT_EQ(out.required_end, 285.0);
  EXPECT_EQ(module.blinker_on_since(), 1.0);

  // The previous request ends before the terminal start: OVERWRITE keeps it, timestamp cleared.
  const auto short_previous = request(TurnIndicator::EnableRight, 0, 250, 0, 250, RequestSource::Avoidance);
  EXPECT_PRED2(same_info, module.update(short_previous, in, ego, 2.0, kParams), short_previous);
  EXPECT_FALSE(module.blinker_on_since().has_value());

  // A path shorter than the buffer starts the terminal signal at the path front.
  in.previous_path_front = 290.0;
  const auto clamped = module.update(previous, in, ego, 3.0, kParams);
  EXPECT_EQ(clamped.desired_start, 290.0);
}

TEST(LaneChangeSignal, PrepareDurationShortenedByTheBlinkerOnTime) {
  LaneChangeSignal module;
  EXPECT_EQ(module.actual_prepare_duration(0.0, 10.0, kParams), 4.0);  // blinker off: max_prepare_duration
  module.update(TurnSignalInfo{}, lc_input(), ego_front(95.0, 10.0), 10.0, kParams);
  ASSERT_EQ(module.blinker_on_since(), 10.0);
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(10.0, 10.0, kParams), 4.0);
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(11.0, 10.0, kParams), 3.0);
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(12.0, 10.0, kParams), 2.0);
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(13.0, 10.0, kParams), 2.0);  // floor min_prepare_duration
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(60.0, 10.0, kParams), 2.0);
  // Below min_lane_changing_velocity the floor is the time to reach it.
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(13.0, 0.0, kParams), 2.78);
  EXPECT_NEAR(module.actual_prepare_duration(13.0, 0.78, kParams), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(13.0, 0.28, kParams), 2.5);
  BehaviorSignalParameters no_acc;
  no_acc.max_longitudinal_acc = 0.0;
  EXPECT_DOUBLE_EQ(module.actual_prepare_duration(13.0, 0.0, no_acc), 4.0);
  module.reset();
  EXPECT_EQ(module.actual_prepare_duration(13.0, 10.0, kParams), 4.0);
}

}  // namespace
}  // namespace signalsim
