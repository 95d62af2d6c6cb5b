// Backward length of P in roundabouts (docs/behaviour.md §T5.4), alone and inside the decider.
#include "turn_signal/roundabout_backward_length.hpp"

#include <gtest/gtest.h>

#include "drive.hpp"
#include "route_sketch.hpp"

namespace signalsim {
namespace {

using test::roundabout_route;

// Route indices of roundabout_route(3): 0 in0, 1 entry, 2 r01, 3 :N1_2_0, 4 r12, 5 :N2_2_0, 6 r23,
// 7 exit, 8 out3. The entry's start is stored on the approach (s = 66.3, index 0).
struct Fixture {
  test::RoundaboutRoute r = roundabout_route(3);
  RouteMap route = r.sketch.build();
  std::map<std::size_t, double> stored{{r.ix.entry, 66.3}};
  double length(std::size_t current, int depth, double default_length = 10.0) const {
    return roundabout_backward_length(route, current, default_length, depth, stored);
  }
};

TEST(RoundaboutBackwardLength, FromTheStoredStartLaneletToTheEndOfTheCurrentLanelet) {
  const Fixture f;
  // Candidate = full lengths from the lanelet holding the stored start (the approach, s = 0) through
  // the current lanelet.
  for (std::size_t current : {f.r.ix.ring[0], f.r.ix.ring[2], f.r.ix.ring[4], f.r.ix.exit}) {
    EXPECT_NEAR(f.length(current, 50), f.route.at(current).s_end(), 1e-9) << current;
  }
}

TEST(RoundaboutBackwardLength, DepthLimit) {
  const Fixture f;
  // The approach is found when the entry (depth = current - 1) is expanded: needs current - 1 < depth.
  EXPECT_NEAR(f.length(f.r.ix.ring[0], 2), f.route.at(f.r.ix.ring[0]).s_end(), 1e-9);  // r01: entry at depth 1
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.ring[1], 2), 10.0);  // :N1_2_0: entry at depth 2, not expanded
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.ring[4], 2), 10.0);
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.ring[4], 5), 10.0);  // r23 (index 6): entry at depth 5
  EXPECT_NEAR(f.length(f.r.ix.ring[4], 6), f.route.at(f.r.ix.ring[4]).s_end(), 1e-9);
  EXPECT_NEAR(f.length(f.r.ix.ring[4], 50), f.route.at(f.r.ix.ring[4]).s_end(), 1e-9);
  EXPECT_NEAR(f.length(f.r.ix.exit, -1), f.route.at(f.r.ix.exit).s_end(), 1e-9);  // unlimited
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.ring[0], 0), 10.0);  // depth 0: the current lanelet is not expanded
}

TEST(RoundaboutBackwardLength, OnlyOnRingAndExitLanelets) {
  const Fixture f;
  EXPECT_DOUBLE_EQ(f.length(0, 50), 10.0);             // approach
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.entry, 50), 10.0);  // entry
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.out, 50), 10.0);    // after the roundabout
}

TEST(RoundaboutBackwardLength, NeverShorterThanTheDefault) {
  const Fixture f;
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.ring[0], 50, 500.0), 500.0);
}

TEST(RoundaboutBackwardLength, NothingStoredOrStoredInsideTheEntry) {
  Fixture f;
  f.stored.clear();
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.exit, 50), 10.0);
  // Quirk kept from the reference: the entry is visited before it could be counted.
  f.stored[f.r.ix.entry] = f.route.at(f.r.ix.entry).s_start + 1.0;
  EXPECT_DOUBLE_EQ(f.length(f.r.ix.exit, 50), 10.0);
}

TEST(RoundaboutBackwardLength, StoredStartFurtherBack) {
  test::RouteSketch sketch;
  sketch.straight("a_0", 100.0);
  sketch.straight("in0_0", 20.0);
  const auto ix = test::add_roundabout(sketch, 2);
  const RouteMap route = sketch.build();
  const std::map<std::size_t, double> stored{{ix.entry, 95.0}};  // on a_0, two lanelets before the entry
  EXPECT_NEAR(roundabout_backward_length(route, ix.exit, 10.0, 50, stored), route.at(ix.exit).s_end(), 1e-9);
  const std::map<std::size_t, double> closer{{ix.entry, 105.0}};  // on in0_0
  EXPECT_NEAR(roundabout_backward_length(route, ix.exit, 10.0, 50, closer),
              route.at(ix.exit).s_end() - route.at(1).s_start, 1e-9);
}

TEST(RoundaboutBackwardLength, EntriesOfAnotherRoundaboutDoNotCount) {
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto first = test::add_roundabout(sketch, 1, "0", "N", {}, 15.0);
  const auto second = test::add_roundabout(sketch, 2, "1", "M");
  const RouteMap route = sketch.build();
  const std::map<std::size_t, double> stored{{first.entry, 66.3}};
  EXPECT_DOUBLE_EQ(roundabout_backward_length(route, second.ring[2], 10.0, -1, stored), 10.0);
  // The second roundabout's own entry, stored on the link between them.
  const std::map<std::size_t, double> own{{second.entry, route.at(first.out).s_start + 1.0}};
  EXPECT_NEAR(roundabout_backward_length(route, second.ring[2], 10.0, -1, own),
              route.at(second.ring[2]).s_end() - route.at(first.out).s_start, 1e-9);
}

TEST(RoundaboutBackwardLength, DeciderKeepsThePersistentEntryOnTheShortPath) {
  // P reaches only 20 m behind base_link. Without §T5.4 the entry leaves P on the ring and its
  // persistent blinker drops; with it P reaches back to the stored start and the blinker stays.
  auto r = roundabout_route(3);
  const RouteMap route = r.sketch.build();
  auto params = test::roundabout_params("Right", "Left", true);
  params.turn_signal_path_backward_length = 20.0;
  const double probe = route.at(r.ix.ring[4]).s_start + 5.0;  // base_link on r23, ~70 m past the entry

  test::Drive extended(route, params, 50.0);
  const auto& d = extended.to_base(probe);
  EXPECT_EQ(d.turn, TurnIndicator::EnableRight);
  EXPECT_EQ(d.source, RequestSource::RoundaboutEntry);
  EXPECT_NEAR(d.path_backward_length, route.at(r.ix.ring[4]).s_end(), 1e-9);  // from the approach's start

  params.turn_signal_roundabout_backward_depth = 0;
  test::Drive fixed(route, params, 50.0);
  const auto& lost = fixed.to_base(probe);
  EXPECT_EQ(lost.turn, TurnIndicator::Disable);
  EXPECT_DOUBLE_EQ(lost.path_backward_length, 20.0);
}

TEST(RoundaboutBackwardLength, DeciderDefaultAwayFromRoundabouts) {
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  test::Drive drive(route, test::roundabout_params("Left", "Left"), 10.0);
  EXPECT_DOUBLE_EQ(drive.last().path_backward_length, 100.0);
}

}  // namespace
}  // namespace signalsim
