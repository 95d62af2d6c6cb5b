// docs/behaviour.md §T6.3: the five documented conflict patterns, as the blinker sequence seen while the ego
// drives along s. Blinker 1 (prior, earlier desired start) = intersection LEFT, blinker 2 = behaviour
// RIGHT. base_link2front = 1 m. Samples sit at s_base = 0.05 + 0.5 k so that no sample lands exactly
// on a section boundary (the exact ps == 0 instant is tested separately below).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "test_helpers.hpp"
#include "turn_signal/resolver.hpp"

namespace signalsim {
namespace {

using test::ego_at_base;
using test::request;
using test::kLeft;
using test::kRight;
using test::kDisable;

struct Run {
  TurnIndicator command;
  double first_s_base;  ///< first sample of the run
  friend bool operator==(const Run&, const Run&) = default;
};

// Runs of equal output while s_base goes from 0.05 to 100.05 in 0.5 m steps.
std::vector<Run> sweep(const TurnSignalInfo& prior, const TurnSignalInfo& subsequent) {
  std::vector<Run> runs;
  for (int k = 0; k <= 200; ++k) {
    const double s_base = 0.05 + 0.5 * k;
    const TurnIndicator c = resolve_turn_signal(ego_at_base(s_base), prior, TurnSignalInfo{}, subsequent).command;
    if (runs.empty() || runs.back().command != c) runs.push_back({c, s_base});
  }
  return runs;
}

std::vector<TurnIndicator> commands(const std::vector<Run>& runs) {
  std::vector<TurnIndicator> out;
  for (const Run& r : runs) out.push_back(r.command);
  return out;
}

// Checks the command sequence and the s_base at which each run starts.
void expect_runs(const std::vector<Run>& runs, const std::vector<Run>& expected) {
  ASSERT_EQ(commands(runs), commands(expected));
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_DOUBLE_EQ(runs[i].first_s_base, expected[i].first_s_base) << i;
}

// Pattern 1: R1 [30, 50], R2 [40, 70] starts inside R1 and ends after it; desired end 1 (60) < 2 (80).
// Blinker 1 from its desired start (front 10, base 9) until R1 end (base 50), then blinker 2 until
// its desired end (base 80).
TEST(ConflictPatterns, Pattern1HandsOverAtThePriorRequiredEnd) {
  const auto b1 = request(kLeft, 10, 60, 30, 50);
  const auto b2 = request(kRight, 20, 80, 40, 70);
  expect_runs(sweep(b1, b2), {{kDisable, 0.05}, {kLeft, 9.05}, {kRight, 50.05}, {kDisable, 80.05}});
}

// Pattern 2: as pattern 1 but desired end 1 (80) > desired end 2 (70). Blinker 2 from R1 end until its
// desired end. Afterwards blinker 1 is the only valid request again, so it comes back until its own
// desired end (what the reference code does; the pattern drawing stops at desired end 2).
TEST(ConflictPatterns, Pattern2HandsOverAtThePriorRequiredEnd) {
  const auto b1 = request(kLeft, 10, 80, 30, 50);
  const auto b2 = request(kRight, 20, 70, 40, 65);
  expect_runs(sweep(b1, b2), {{kDisable, 0.05}, {kLeft, 9.05}, {kRight, 50.05}, {kLeft, 70.05}, {kDisable, 80.05}});
}

// Pattern 3: R2 [40, 60] entirely inside R1 [30, 70]: blinker 1 throughout, until desired end 1.
TEST(ConflictPatterns, Pattern3KeepsThePriorThroughout) {
  const auto b1 = request(kLeft, 10, 80, 30, 70);
  const auto b2 = request(kRight, 20, 75, 40, 60);
  expect_runs(sweep(b1, b2), {{kDisable, 0.05}, {kLeft, 9.05}, {kDisable, 80.05}});
}

// Pattern 4: R2 [30, 45] starts before R1 [50, 70] and ends before R1 ends. Blinker 1 while only it is
// valid (front 10..20), blinker 2 from its desired start until the front reaches R1 start (front 50,
// base 49), blinker 1 afterwards.
TEST(ConflictPatterns, Pattern4GivesWayUntilThePriorRequiredStart) {
  const auto b1 = request(kLeft, 10, 80, 50, 70);
  const auto b2 = request(kRight, 20, 75, 30, 45);
  expect_runs(sweep(b1, b2),
              {{kDisable, 0.05}, {kLeft, 9.05}, {kRight, 19.05}, {kLeft, 49.05}, {kDisable, 80.05}});
}

// Pattern 5: R1 [40, 50] entirely inside R2 [30, 70]: blinker 1 until R1 end (base 50), then blinker 2.
TEST(ConflictPatterns, Pattern5HandsOverAtThePriorRequiredEnd) {
  const auto b1 = request(kLeft, 10, 60, 40, 50);
  const auto b2 = request(kRight, 20, 80, 30, 70);
  expect_runs(sweep(b1, b2), {{kDisable, 0.05}, {kLeft, 9.05}, {kRight, 50.05}, {kDisable, 80.05}});
}

// Reference quirk (docs/behaviour.md §T6.2 edge): in pattern 5, at the exact instant the front is on R1's start
// (ps == 0), ego is neither before nor inside R1, so blinker 2 shows for that single instant.
TEST(ConflictPatterns, Pattern5ShowsBlinker2ExactlyOnThePriorRequiredStart) {
  const auto b1 = request(kLeft, 10, 60, 40, 50);
  const auto b2 = request(kRight, 20, 80, 30, 70);
  const auto at = [&](double s_base) { return resolve_turn_signal(ego_at_base(s_base), b1, {}, b2).command; };
  EXPECT_EQ(at(38.999), kLeft);
  EXPECT_EQ(at(39.0), kRight);  // front == 40.0 exactly
  EXPECT_EQ(at(39.001), kLeft);
}

// In pattern 4 the hand-back to blinker 1 includes the exact instant the front reaches R1's start.
TEST(ConflictPatterns, Pattern4HandsBackExactlyOnThePriorRequiredStart) {
  const auto b1 = request(kLeft, 10, 80, 50, 70);
  const auto b2 = request(kRight, 20, 75, 30, 45);
  const auto at = [&](double s_base) { return resolve_turn_signal(ego_at_base(s_base), b1, {}, b2).command; };
  EXPECT_EQ(at(48.999), kRight);
  EXPECT_EQ(at(49.0), kLeft);
}

}  // namespace
}  // namespace signalsim
