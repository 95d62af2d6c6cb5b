// docs/behaviour.md §T8, §T6.4: the modules chained in Autoware's order into one behaviour request.
#include <gtest/gtest.h>

#include "behavior_test_helpers.hpp"
#include "turn_signal/behavior_modules.hpp"
#include "turn_signal/resolver.hpp"

namespace signalsim {
namespace {

using test::ego_front;
using test::is_empty;

using test::kParams;

AvoidanceSignal::Input avoid(double s0, double s1, double a, double b) {
  AvoidanceSignal::Input in;
  in.shift_lines = {AvoidanceShiftLine{.id = 1, .s_start = s0, .s_end = s1, .shift_start = a, .shift_end = b}};
  in.signal = test::shift_input();
  in.signal.current_shift_length = a;
  in.planned_shift_at_ego = a;
  return in;
}

LaneChangeSignal::Input lane_change(TurnIndicator direction, double start, double end) {
  LaneChangeSignal::Input in;
  in.direction = direction;
  in.lane_changing_start = start;
  in.lane_changing_end = end;
  in.previous_path_end = 300.0;
  return in;
}

TEST(MergeBehaviorRequests, NoModuleRunningIsEmpty) {
  BehaviorModules modules;
  EXPECT_TRUE(is_empty(merge_behavior_requests(modules, {}, ego_front(50.0), kParams)));
}

TEST(MergeBehaviorRequests, SingleModulePassesThrough) {
  BehaviorModules modules;
  const auto in = avoid(100, 120, 0, 2);
  BehaviorRequests r;
  r.avoidance = &in;
  const auto merged = merge_behavior_requests(modules, r, ego_front(95.0), kParams);
  EXPECT_EQ(merged.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(merged.source, RequestSource::Avoidance);
}

TEST(MergeBehaviorRequests, LaneChangeAfterAvoidanceOverwrites) {
  BehaviorModules modules;
  const auto a = avoid(100, 120, 0, 2);
  const auto lc = lane_change(TurnIndicator::EnableRight, 100, 150);
  BehaviorRequests r;
  r.avoidance = &a;
  r.lane_change = &lc;
  r.now = 1.0;
  // LC_SIGNAL(ego pose, ...) starts at base_link, before the avoidance's desired end -> it wins.
  const auto merged = merge_behavior_requests(modules, r, ego_front(95.0, 10.0), kParams);
  EXPECT_EQ(merged.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(merged.source, RequestSource::LaneChange);
  EXPECT_EQ(modules.lane_change.blinker_on_since(), 1.0);
}

TEST(MergeBehaviorRequests, InactiveLaneChangeKeepsTheAvoidanceRequest) {
  BehaviorModules modules;
  const auto a = avoid(100, 120, 0, 2);
  const auto lc = lane_change(TurnIndicator::EnableRight, 300, 350);  // far beyond the prep distance
  BehaviorRequests r;
  r.avoidance = &a;
  r.lane_change = &lc;
  const auto merged = merge_behavior_requests(modules, r, ego_front(95.0, 10.0), kParams);
  EXPECT_EQ(merged.source, RequestSource::Avoidance);
  EXPECT_FALSE(modules.lane_change.active());
}

TEST(MergeBehaviorRequests, PullOutFirstThenPullOver) {
  BehaviorModules modules;
  PullOutSignal::Input out;
  out.pull_out_start = 10.0;
  out.pull_out_end = 40.0;
  out.shift_at_start = -2.5;
  out.signal = test::shift_input();
  out.signal.lane.right_half_width = 3.5;
  out.signal.current_shift_length = -2.5;
  PullOverSignal::Input over;
  over.pull_over_start = 200.0;
  over.pull_over_end = 230.0;
  over.shift_at_end = -2.5;
  over.signal = test::shift_input();
  BehaviorRequests r;
  r.pull_out = &out;
  r.pull_over = &over;
  // Near the start: the pull out signals; the pull over is far away -> its NONE (path span
  // [0, 300]) would replace it by OVERWRITE. Autoware behaves the same way; in practice the two
  // modules do not run together.
  auto merged = merge_behavior_requests(modules, r, ego_front(8.0), kParams);
  EXPECT_EQ(merged.turn, TurnIndicator::NoCommand);
  EXPECT_EQ(merged.source, RequestSource::PullOver);
  r.pull_over = nullptr;
  merged = merge_behavior_requests(modules, r, ego_front(8.0), kParams);
  EXPECT_EQ(merged.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(merged.source, RequestSource::PullOut);
}

TEST(MergeBehaviorRequests, HazardFromABackwardPullOutReachesTheDecider) {
  BehaviorModules modules;
  PullOutSignal::Input out;
  out.pull_out_start = 10.0;
  out.pull_out_end = 40.0;
  out.shift_at_start = -2.5;
  out.driving_forward = false;
  out.signal = test::shift_input();
  BehaviorRequests r;
  r.pull_out = &out;
  const auto merged = merge_behavior_requests(modules, r, ego_front(8.0, -1.0), kParams);
  EXPECT_EQ(merged.hazard, HazardLights::Enable);
}

TEST(MergeBehaviorRequests, MergedRequestResolvesToTheBlinker) {
  // End to end with the resolver: the avoidance request is eligible from the moment the front is
  // within max(3v, 10) of the shift start until base_link passes the shift end.
  BehaviorModules modules;
  const auto a = avoid(100, 120, 0, 2);
  BehaviorRequests r;
  r.avoidance = &a;
  for (const double front : {80.0, 95.0, 110.0, 123.6, 123.8}) {
    const auto ego = ego_front(front, 5.0);
    const auto merged = merge_behavior_requests(modules, r, ego, kParams);
    const auto resolved = resolve_turn_signal(ego, TurnSignalInfo{}, TurnSignalInfo{}, merged);
    const bool expect_on = front >= 85.0 && ego.s_base <= 120.0;
    EXPECT_EQ(resolved.command, expect_on ? TurnIndicator::EnableLeft : TurnIndicator::Disable) << front;
  }
}

}  // namespace
}  // namespace signalsim
