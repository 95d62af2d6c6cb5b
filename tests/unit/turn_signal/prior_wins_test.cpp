// Boundary cases of PRIOR_WINS derived from docs/behaviour.md §T6.2 (strict vs non-strict comparisons).
#include "turn_signal/resolver.hpp"

#include <gtest/gtest.h>

namespace signalsim {
namespace {

constexpr double kTiny = 1e-9;

// ps == 0: the front is exactly on the prior's required start, neither "before" nor "inside".
TEST(PriorWins, PriorStartExactlyReachedInsideSubsequentSection) {
  // P5 (pe < se): the prior keeps the blinker before and inside its section, but not at ps == 0.
  EXPECT_TRUE(prior_wins(kTiny, 5.0, -3.0, 10.0));
  EXPECT_FALSE(prior_wins(0.0, 5.0, -3.0, 10.0));
  EXPECT_TRUE(prior_wins(-kTiny, 5.0, -3.0, 10.0));
}

TEST(PriorWins, PriorStartExactlyReachedHandsBackInPattern4) {
  // P4 (pe >= se): the subsequent one until the front reaches the prior start, inclusive.
  EXPECT_FALSE(prior_wins(kTiny, 10.0, -3.0, 5.0));
  EXPECT_TRUE(prior_wins(0.0, 10.0, -3.0, 5.0));
}

TEST(PriorWins, PriorStartExactlyReachedWhileSubsequentAheadKeepsPrior) {
  // ps < ss with ps == 0 means ss > 0: the gap rule keeps the prior.
  EXPECT_TRUE(prior_wins(0.0, -1.0, 2.0, 10.0));
}

// se == pe: "subsequent inside prior" needs se < pe strictly.
TEST(PriorWins, EqualRequiredEndsWhenPriorStartsFirst) {
  EXPECT_TRUE(prior_wins(-10.0, -1.0, -5.0, -1.5));  // se < pe: P3 keeps the prior
  EXPECT_FALSE(prior_wins(-10.0, -1.0, -5.0, -1.0)); // se == pe: both passed -> subsequent
}

TEST(PriorWins, EqualRequiredEndsWhenSubsequentStartsFirst) {
  EXPECT_TRUE(prior_wins(2.0, 5.0, -3.0, 5.5));   // pe < se: P5, before prior -> prior
  EXPECT_FALSE(prior_wins(2.0, 5.0, -3.0, 5.0));  // pe == se: P4, before prior -> subsequent
}

// ps == ss: "prior starts first" needs ps < ss strictly, otherwise the P4/P5 branch decides.
TEST(PriorWins, EqualRequiredStarts) {
  EXPECT_TRUE(prior_wins(2.0 - 1e-3, 10.0, 2.0, 5.0));  // P3: subsequent inside prior
  EXPECT_FALSE(prior_wins(2.0, 10.0, 2.0, 5.0));        // P4: before prior -> subsequent
  EXPECT_TRUE(prior_wins(2.0, 5.0, 2.0, 10.0));         // P5: before prior -> prior
  EXPECT_TRUE(prior_wins(-2.0, 10.0, -2.0, 5.0));       // P4 after the (shared) start -> prior
}

TEST(PriorWins, PriorRequiredEndIsInclusive) {
  EXPECT_TRUE(prior_wins(-5.0, 0.0, -1.0, 10.0));     // base_link exactly on the prior's end
  EXPECT_FALSE(prior_wins(-5.0, -kTiny, -1.0, 10.0)); // just past it
}

TEST(PriorWins, SubsequentStartReachedExactlyEndsTheGap) {
  EXPECT_TRUE(prior_wins(-5.0, -1.0, kTiny, 10.0));  // both sections disjoint, subsequent ahead
  EXPECT_FALSE(prior_wins(-5.0, -1.0, 0.0, 10.0));   // front exactly on the subsequent start
}

}  // namespace
}  // namespace signalsim
