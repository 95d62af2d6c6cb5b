// docs/behaviour.md §T6.4: OVERWRITE and USE_PRIOR_INFO, the merge helpers used by the behaviour modules.
#include <gtest/gtest.h>

#include "test_helpers.hpp"
#include "turn_signal/resolver.hpp"

namespace signalsim {
namespace {

using test::ego_at_base;
using test::request;
using test::kLeft;
using test::kRight;

bool same(const TurnSignalInfo& a, const TurnSignalInfo& b) { return test::same_info(a, b); }

// ---- OVERWRITE -------------------------------------------------------------------------------------

TEST(OverwriteTurnSignal, InactiveOriginalIsReplaced) {
  const auto ego = ego_at_base(0.0);
  const auto next = request(kRight, 80.0, 90.0, 80.0, 90.0, RequestSource::LaneChange);
  for (const TurnIndicator inactive : {TurnIndicator::NoCommand, TurnIndicator::Disable}) {
    const auto original = request(inactive, 0.0, 10.0, 0.0, 10.0, RequestSource::Avoidance);
    EXPECT_PRED2(same, overwrite_turn_signal(ego, original, next), next);
  }
}

TEST(OverwriteTurnSignal, OriginalKeptWhenTheNewOneStartsAfterItEnds) {
  const auto ego = ego_at_base(5.0);
  const auto original = request(kLeft, 0.0, 50.0, 10.0, 40.0, RequestSource::Avoidance);
  EXPECT_PRED2(same, overwrite_turn_signal(ego, original, request(kRight, 50.5, 90.0, 60.0, 80.0)), original);
}

TEST(OverwriteTurnSignal, NewOneWinsWhenItStartsAtOrBeforeTheOriginalEnd) {
  const auto ego = ego_at_base(5.0);
  const auto original = request(kLeft, 0.0, 50.0, 10.0, 40.0, RequestSource::Avoidance);
  const auto touching = request(kRight, 50.0, 90.0, 60.0, 80.0, RequestSource::LaneChange);
  const auto overlapping = request(kRight, 30.0, 90.0, 60.0, 80.0, RequestSource::LaneChange);
  EXPECT_PRED2(same, overwrite_turn_signal(ego, original, touching), touching);
  EXPECT_PRED2(same, overwrite_turn_signal(ego, original, overlapping), overlapping);
}

// ---- USE_PRIOR_INFO --------------------------------------------------------------------------------

using test::kEmpty;

TEST(UsePriorTurnSignal, EmptyWhenNeitherDesiredStartIsReached) {
  const auto original = request(kLeft, 20.0, 50.0, 30.0, 40.0);
  const auto next = request(kRight, 30.0, 60.0, 40.0, 50.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(10.0), original, next), kEmpty);
}

TEST(UsePriorTurnSignal, OnlyTheStartedOneWhenTheOtherHasNotStarted) {
  const auto original = request(kLeft, 20.0, 50.0, 30.0, 40.0);
  const auto next = request(kRight, 30.0, 60.0, 40.0, 50.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(19.0), original, next), original);  // ds == 0 counts
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(19.0), next, original), original);
}

TEST(UsePriorTurnSignal, PassedDesiredEndsAreDropped) {
  const auto original = request(kLeft, 0.0, 50.0, 10.0, 40.0);
  const auto next = request(kRight, 0.0, 60.0, 10.0, 50.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(55.0), original, next), next);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(55.0), next, original), next);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(60.5), original, next), kEmpty);
}

TEST(UsePriorTurnSignal, BaseLinkExactlyOnTheDesiredEndKeepsTheRequest) {
  // Equal required starts and the original's required end not before next's: the original is kept
  // while both count, so the result tells whether the original still counts.
  const auto original = request(kLeft, 0.0, 50.0, 10.0, 50.0);
  const auto next = request(kRight, 0.0, 60.0, 10.0, 45.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(50.0), original, next), original);  // de == 0
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(50.001), original, next), next);   // de < 0
}

TEST(UsePriorTurnSignal, EarlierDesiredStartIsThePrior) {
  const auto original = request(kLeft, 0.0, 100.0, 30.0, 50.0);  // prior
  const auto next = request(kRight, 10.0, 100.0, 40.0, 70.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(20.0), original, next), original);  // before R1
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(60.0), original, next), next);      // R1 passed
  // Swapped roles: the prior is the second argument now.
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(20.0), next, original), original);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(60.0), next, original), next);
}

TEST(UsePriorTurnSignal, EqualDesiredStartsMakeTheOriginalThePrior) {
  // Pattern-4 geometry: the subsequent wins until the front reaches the prior's required start.
  const auto a = request(kLeft, 10.0, 100.0, 50.0, 70.0);
  const auto b = request(kRight, 10.0, 100.0, 30.0, 45.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(20.0), a, b), b);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(20.0), b, a), b);  // b prior, front before its start
  // Identical sections, ego inside them: PRIOR_WINS keeps the prior, which must be the original.
  const auto left = request(kLeft, 10.0, 100.0, 30.0, 70.0);
  const auto right = request(kRight, 10.0, 100.0, 30.0, 70.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(40.0), left, right), left);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(40.0), right, left), right);
}

TEST(UsePriorTurnSignal, IgnoresTheCommands) {
  const auto original = request(TurnIndicator::NoCommand, 0.0, 100.0, 30.0, 50.0);
  const auto next = request(kRight, 10.0, 100.0, 40.0, 70.0);
  EXPECT_PRED2(same, use_prior_turn_signal(ego_at_base(20.0), original, next), original);
}

}  // namespace
}  // namespace signalsim
