// RESOLVE (docs/behaviour.md §T6.1): validity, ordering and the fold, on hand-made requests.
#include "turn_signal/resolver.hpp"

#include <gtest/gtest.h>

#include "test_helpers.hpp"

namespace signalsim {
namespace {

using test::ego_at_base;
using test::request;
using test::kLeft;
using test::kRight;
using test::kEmpty;

TEST(SectionDistances, StartsFromTheFrontEndsFromBaseLink) {
  const EgoOnRoute ego{.s_front = 14.5, .s_base = 10.0, .speed = 0.0};
  const SectionDistances d = section_distances(request(kLeft, 20.0, 30.0, 25.0, 28.0), ego);
  EXPECT_DOUBLE_EQ(d.desired_start, 5.5);
  EXPECT_DOUBLE_EQ(d.required_start, 10.5);
  EXPECT_DOUBLE_EQ(d.desired_end, 20.0);
  EXPECT_DOUBLE_EQ(d.required_end, 18.0);
}

TEST(Resolver, NothingValidGivesDisableNotNoCommand) {
  const ResolvedTurnSignal r = resolve_turn_signal(ego_at_base(0.0), kEmpty, kEmpty, kEmpty);
  EXPECT_EQ(r.command, TurnIndicator::Disable);
  EXPECT_EQ(r.source, RequestSource::None);
}

TEST(Resolver, SingleValidCandidateIsReturnedWithItsSource) {
  const auto lane_change = request(kRight, 0.0, 50.0, 10.0, 40.0, RequestSource::LaneChange);
  const ResolvedTurnSignal r = resolve_turn_signal(ego_at_base(5.0), kEmpty, kEmpty, lane_change);
  EXPECT_EQ(r.command, kRight);
  EXPECT_EQ(r.source, RequestSource::LaneChange);
}

TEST(Resolver, TurnsOnWhenTheFrontIsExactlyOnTheDesiredStart) {
  const auto behaviour = request(kLeft, 11.0, 50.0, 20.0, 40.0, RequestSource::Avoidance);
  EXPECT_EQ(resolve_turn_signal(ego_at_base(9.5), kEmpty, kEmpty, behaviour).command, TurnIndicator::Disable);
  EXPECT_EQ(resolve_turn_signal(ego_at_base(10.0), kEmpty, kEmpty, behaviour).command, kLeft);  // ds == 0
}

TEST(Resolver, StaysOnWithBaseLinkExactlyOnTheDesiredEndAndDropsAfter) {
  const auto behaviour = request(kLeft, 0.0, 10.0, 0.0, 10.0, RequestSource::Avoidance);
  EXPECT_EQ(resolve_turn_signal(ego_at_base(10.0), kEmpty, kEmpty, behaviour).command, kLeft);  // de == 0
  EXPECT_EQ(resolve_turn_signal(ego_at_base(10.001), kEmpty, kEmpty, behaviour).command,
            TurnIndicator::Disable);  // de < 0
}

TEST(Resolver, NoCommandAndDisableCandidatesAreFilteredOut) {
  const auto ego = ego_at_base(20.0);
  // These would win if they counted: earliest desired start, behaviour's required section inside theirs.
  const auto disable = request(TurnIndicator::Disable, 0.0, 100.0, 25.0, 90.0, RequestSource::Intersection);
  const auto no_command = request(TurnIndicator::NoCommand, 0.0, 100.0, 25.0, 90.0, RequestSource::RoundaboutEntry);
  const auto behaviour = request(kRight, 10.0, 50.0, 30.0, 40.0, RequestSource::PullOver);
  const ResolvedTurnSignal r = resolve_turn_signal(ego, disable, no_command, behaviour);
  EXPECT_EQ(r.command, kRight);
  EXPECT_EQ(r.source, RequestSource::PullOver);
  // Sanity check: the same request as ENABLE_LEFT does win.
  auto enabled = disable;
  enabled.turn = kLeft;
  EXPECT_EQ(resolve_turn_signal(ego, enabled, no_command, behaviour).command, kLeft);
  // Only filtered requests: DISABLE.
  EXPECT_EQ(resolve_turn_signal(ego, disable, no_command, kEmpty).command, TurnIndicator::Disable);
}

// Identical required sections with ego inside: PRIOR_WINS keeps whichever is sorted first.
class ResolverTie : public ::testing::Test {
 protected:
  static TurnSignalInfo with(TurnIndicator turn, RequestSource source, double desired_start = 10.0) {
    return request(turn, desired_start, 100.0, 20.0, 80.0, source);
  }
  const EgoOnRoute ego = ego_at_base(30.0);
};

TEST_F(ResolverTie, EqualDesiredStartsPreferIntersectionThenRoundaboutThenBehaviour) {
  const auto i = with(kLeft, RequestSource::Intersection);
  const auto rb = with(kRight, RequestSource::RoundaboutExit);
  const auto b = with(kRight, RequestSource::Avoidance);
  EXPECT_EQ(resolve_turn_signal(ego, i, rb, b).source, RequestSource::Intersection);
  EXPECT_EQ(resolve_turn_signal(ego, i, kEmpty, b).source, RequestSource::Intersection);
  EXPECT_EQ(resolve_turn_signal(ego, kEmpty, rb, b).source, RequestSource::RoundaboutExit);
  const auto rb_left = with(kLeft, RequestSource::RoundaboutEntry);
  EXPECT_EQ(resolve_turn_signal(ego, i, rb_left, kEmpty).source, RequestSource::Intersection);
}

TEST_F(ResolverTie, TieRuleUsesTheCandidateSlotNotTheRequestSource) {
  // A behaviour-type source passed in the intersection slot still ranks first on a tie.
  const auto in_intersection_slot = with(kLeft, RequestSource::LaneChange);
  const auto in_behaviour_slot = with(kRight, RequestSource::Intersection);
  const ResolvedTurnSignal r = resolve_turn_signal(ego, in_intersection_slot, kEmpty, in_behaviour_slot);
  EXPECT_EQ(r.command, kLeft);
  EXPECT_EQ(r.source, RequestSource::LaneChange);
}

TEST_F(ResolverTie, EarlierDesiredStartBeatsSlotOrder) {
  const auto i = with(kLeft, RequestSource::Intersection, 10.0);
  const auto b = with(kRight, RequestSource::Avoidance, 9.0);  // passed earlier -> prior
  EXPECT_EQ(resolve_turn_signal(ego, i, kEmpty, b).command, kRight);
}

TEST(Resolver, FoldsThreeCandidatesInDesiredStartOrder) {
  const auto ego = ego_at_base(55.0);  // front 56
  // Sorted: roundabout (ds -56), intersection (-46), behaviour (-36).
  const auto roundabout = request(kLeft, 0.0, 100.0, 20.0, 40.0, RequestSource::RoundaboutExit);  // passed
  const auto intersection = request(kRight, 10.0, 100.0, 50.0, 70.0, RequestSource::Intersection);
  const auto behaviour = request(kLeft, 20.0, 100.0, 60.0, 65.0, RequestSource::LaneChange);
  // roundabout vs intersection: prior's required section passed, subsequent started -> intersection.
  // intersection vs behaviour: behaviour's required section inside the intersection's -> intersection.
  const ResolvedTurnSignal r = resolve_turn_signal(ego, intersection, roundabout, behaviour);
  EXPECT_EQ(r.command, kRight);
  EXPECT_EQ(r.source, RequestSource::Intersection);
}

TEST(Resolver, NeverThrowsOnDegenerateRequests) {
  const auto zero = request(kLeft, 0.0, 0.0, 0.0, 0.0);
  EXPECT_NO_THROW(resolve_turn_signal(ego_at_base(0.0, 0.0), zero, zero, zero));
  EXPECT_EQ(resolve_turn_signal(ego_at_base(0.0, 0.0), zero, zero, zero).command, kLeft);
}

}  // namespace
}  // namespace signalsim
