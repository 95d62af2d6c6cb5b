// RESOLVE (docs/behaviour.md §T6) with a roundabout entry or exit and an intersection turn on the same route,
// through the whole decider: the command and the winning source at positions along s.
#include <gtest/gtest.h>

#include "drive.hpp"
#include "route_sketch.hpp"
#include "turn_signal/exit_signal_marking.hpp"

namespace signalsim {
namespace {

using test::add_roundabout;
using test::roundabout_params;
using test::kLeft;
using test::kRight;
constexpr auto kOff = TurnIndicator::Disable;

// A right turn lanelet (an internal lane with dir "r") and the road after it.
std::size_t add_right_turn(test::RouteSketch& sketch, const std::string& junction) {
  const std::size_t index = sketch.size();
  sketch.arc(":" + junction + "_0_0", 10.0, -90.0).turn_direction = TurnDirection::Right;
  sketch.straight(junction + "_after_0", 100.0);
  return index;
}

#define EXPECT_SIGNAL(decision, command, from)   \
  do {                                           \
    const TurnSignalDecision& d_ = (decision);   \
    EXPECT_EQ(d_.turn, command);                 \
    EXPECT_EQ(d_.source, from);                  \
  } while (false)

TEST(RoundaboutResolver, JapanExitThenRightTurnSoonAfter) {
  // Exit blinker (marked from the entry: first exit) and a right turn 20 m after the exit. The turn
  // comes within 30 m while the exit blinker is on; the exit was first (prior) and its required
  // section comes first, so it keeps the blinker until its desired end, then the turn takes over.
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto rb = add_roundabout(sketch, 1, "0", "N", {}, 20.0);
  const std::size_t turn = add_right_turn(sketch, "J");
  const RouteMap route = mark_exit_signal_lanes(sketch.build());
  const double ring = route.at(rb.ring[0]).s_start;
  const double exit_end = route.at(rb.exit).s_end();
  const double turn_start = route.at(turn).s_start;
  ASSERT_LT(turn_start - 30.0, exit_end);  // both requests overlap

  test::Drive drive(route, roundabout_params("None", "Left"), 50.0);
  EXPECT_SIGNAL(drive.to_front(ring), kOff, RequestSource::None);
  EXPECT_SIGNAL(drive.to_front(ring + 0.5), kLeft, RequestSource::RoundaboutExit);
  const auto& both = drive.to_front(turn_start - 29.5);
  EXPECT_SIGNAL(both, kLeft, RequestSource::RoundaboutExit);
  EXPECT_EQ(both.intersection.turn, kRight);  // the turn request exists and is valid, but loses
  EXPECT_SIGNAL(drive.to_base(exit_end), kLeft, RequestSource::RoundaboutExit);
  EXPECT_SIGNAL(drive.to_base(exit_end + 0.01), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_base(route.at(turn).s_end()), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_base(route.at(turn).s_end() + 0.01), kOff, RequestSource::None);
}

TEST(RoundaboutResolver, RightTurnThenKoreanEntryLeft) {
  // South Korea: entry Left, exit Right. A right turn 15 m before the entry: the turn (prior, required
  // section first) keeps the blinker until base_link leaves it, then the entry's Left, nothing on the
  // ring, the exit's Right.
  test::RouteSketch sketch;
  sketch.straight("a_0", 100.0);
  sketch.arc(":J_0_0", 10.0, -90.0).turn_direction = TurnDirection::Right;
  sketch.straight("in0_0", 15.0);
  const auto rb = add_roundabout(sketch, 1);
  const RouteMap route = sketch.build();
  const double turn_end = route.at(1).s_end();
  const Lanelet& entry = route.at(rb.entry);
  const Lanelet& exit = route.at(rb.exit);
  ASSERT_LT(entry.s_start - 30.0, turn_end);  // the entry comes within reach while in the turn

  test::Drive drive(route, roundabout_params("Left", "Right"), 50.0);
  EXPECT_SIGNAL(drive.to_front(70.0), kOff, RequestSource::None);
  EXPECT_SIGNAL(drive.to_front(70.5), kRight, RequestSource::Intersection);
  const auto& both = drive.to_front(entry.s_start - 29.5);
  EXPECT_SIGNAL(both, kRight, RequestSource::Intersection);
  EXPECT_EQ(both.roundabout.turn, kLeft);
  EXPECT_SIGNAL(drive.to_base(turn_end), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_base(turn_end + 0.01), kLeft, RequestSource::RoundaboutEntry);
  EXPECT_SIGNAL(drive.to_base(entry.s_end()), kLeft, RequestSource::RoundaboutEntry);
  EXPECT_SIGNAL(drive.to_base(entry.s_end() + 0.01), kOff, RequestSource::None);
  EXPECT_SIGNAL(drive.to_front(exit.s_start), kOff, RequestSource::None);
  EXPECT_SIGNAL(drive.to_front(exit.s_start + 0.01), kRight, RequestSource::RoundaboutExit);
  EXPECT_SIGNAL(drive.to_base(exit.s_end() + 0.01), kOff, RequestSource::None);
}

TEST(RoundaboutResolver, EarlyTurnRequestLetsTheEntryAndExitSignalFirst) {
  // Pattern 4 (docs/behaviour.md §T6.3): a right turn 20 m after the first exit carries turn_signal_distance
  // 200 m, so its desired start is earlier than everything else, but the roundabout's required
  // sections start first: entry Left, then exit Right, take the blinker while the front has not
  // reached the turn.
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto rb = add_roundabout(sketch, 1, "0", "N", {}, 20.0);
  const std::size_t turn = add_right_turn(sketch, "J");
  sketch.at(turn).turn_signal_distance = 200.0;
  const RouteMap route = sketch.build();
  const Lanelet& entry = route.at(rb.entry);
  const Lanelet& exit = route.at(rb.exit);

  test::Drive drive(route, roundabout_params("Left", "Right"), 10.0);
  EXPECT_SIGNAL(drive.last(), kRight, RequestSource::Intersection);  // within 200 m from the start
  EXPECT_SIGNAL(drive.to_front(entry.s_start - 30.0), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_front(entry.s_start - 29.5), kLeft, RequestSource::RoundaboutEntry);
  EXPECT_SIGNAL(drive.to_base(entry.s_end()), kLeft, RequestSource::RoundaboutEntry);
  EXPECT_SIGNAL(drive.to_base(entry.s_end() + 0.01), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_front(exit.s_start), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_front(exit.s_start + 0.01), kRight, RequestSource::RoundaboutExit);
  EXPECT_SIGNAL(drive.to_base(exit.s_end() + 0.01), kRight, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_base(route.at(turn).s_end() + 0.01), kOff, RequestSource::None);
}

TEST(RoundaboutResolver, PersistentEntryAgainstALeftTurnInsideItsSection) {
  // A persistent entry (Right, valid to the exit's end) against a left turn 5 m after the exit that
  // comes within 30 m while on the ring. The entry is prior; its required section (the entry) is
  // passed and the turn's has not started (the "gap" rule of PRIOR_WINS): the entry keeps the blinker.
  // When the front passes the exit start, the exit request (DISABLE, on_exit None) pops the entry from
  // the roundabout queue and is itself filtered out by RESOLVE: the turn's Left takes over.
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto rb = add_roundabout(sketch, 2, "0", "N", {}, 5.0);
  const std::size_t turn = sketch.size();
  sketch.arc(":J_0_0", 10.0, 90.0).turn_direction = TurnDirection::Left;
  sketch.straight("J_after_0", 100.0);
  const RouteMap route = sketch.build();
  const Lanelet& exit = route.at(rb.exit);

  test::Drive drive(route, roundabout_params("Right", "None", true), 50.0);
  EXPECT_SIGNAL(drive.to_front(route.at(turn).s_start - 29.5), kRight, RequestSource::RoundaboutEntry);
  EXPECT_SIGNAL(drive.to_front(exit.s_start), kRight, RequestSource::RoundaboutEntry);
  // The exit request (DISABLE, on_exit None) pops the entry and is filtered out: the turn is left.
  EXPECT_SIGNAL(drive.to_front(exit.s_start + 0.01), kLeft, RequestSource::Intersection);
  EXPECT_SIGNAL(drive.to_base(route.at(turn).s_end() + 0.01), kOff, RequestSource::None);
}

}  // namespace
}  // namespace signalsim
