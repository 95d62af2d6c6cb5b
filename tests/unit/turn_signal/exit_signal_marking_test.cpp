// Exit-signal marking (signalsim option): enable_exit_turn_signal on the ring lanelets from the
// previous exit (or the entry) to the ego's exit.
#include "turn_signal/exit_signal_marking.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "drive.hpp"
#include "route_sketch.hpp"

namespace signalsim {
namespace {

using test::roundabout_route;
using ::testing::ElementsAreArray;

std::vector<std::size_t> marked(const RouteMap& route) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const auto it = route.at(i).params.find("enable_exit_turn_signal");
    if (it != route.at(i).params.end() && it->second == "true") out.push_back(i);
  }
  return out;
}

TEST(ExitSignalMarking, FirstExitMarksTheRingFromTheEntry) {
  auto r = roundabout_route(1);
  const RouteMap route = mark_exit_signal_lanes(r.sketch.build());
  EXPECT_THAT(marked(route), ElementsAreArray({r.ix.ring[0]}));  // r01
}

TEST(ExitSignalMarking, SecondExitMarksFromThePreviousExit) {
  auto r = roundabout_route(2);
  const RouteMap route = mark_exit_signal_lanes(r.sketch.build());
  // Exit 1 branches off in junction N1 (r01 and :N1_2_0 have leaves_ring_at_end): marking starts
  // strictly after the junction, at the ring lane leaving it.
  EXPECT_THAT(marked(route), ElementsAreArray({r.ix.ring[2]}));  // r12
}

TEST(ExitSignalMarking, ThirdExitMarksFromThePreviousExitOnly) {
  auto r = roundabout_route(3);
  const RouteMap route = mark_exit_signal_lanes(r.sketch.build());
  EXPECT_THAT(marked(route), ElementsAreArray({r.ix.ring[4]}));  // r23
}

TEST(ExitSignalMarking, StrictlyAfterTheLastBranchingLanelet) {
  // Only the ring lane r01 has the flag (a hand-made map without flags on junction lanes): marking
  // starts right after it, junction lane included.
  auto r = roundabout_route(2);
  r.sketch.at(r.ix.ring[1]).leaves_ring_at_end = false;
  EXPECT_THAT(marked(mark_exit_signal_lanes(r.sketch.build())), ElementsAreArray({r.ix.ring[1], r.ix.ring[2]}));
}

TEST(ExitSignalMarking, NoPreviousExitMarksEverythingAfterTheEntry) {
  auto r = roundabout_route(3);
  for (std::size_t i : {0, 1, 2, 3}) r.sketch.at(r.ix.ring[i]).leaves_ring_at_end = false;  // junctions 1, 2: no exit
  const RouteMap route = mark_exit_signal_lanes(r.sketch.build());
  EXPECT_THAT(marked(route), ElementsAreArray(r.ix.ring));
  // Junction 1 has an exit, junction 2 none: from the ring lane leaving junction 1.
  r.sketch.at(r.ix.ring[0]).leaves_ring_at_end = true;
  r.sketch.at(r.ix.ring[1]).leaves_ring_at_end = true;
  EXPECT_THAT(marked(mark_exit_signal_lanes(r.sketch.build())),
              ElementsAreArray({r.ix.ring[2], r.ix.ring[3], r.ix.ring[4]}));
}

TEST(ExitSignalMarking, ExistingParamIsKeptAndNothingElseChanges) {
  auto r = roundabout_route(3);
  r.sketch.at(r.ix.ring[4]).params["enable_exit_turn_signal"] = "false";  // the net says no
  r.sketch.at(r.ix.ring[0]).params["enable_exit_turn_signal"] = "true";   // the net says yes
  r.sketch.at(r.ix.ring[4]).params["other"] = "x";
  const RouteMap before = r.sketch.build();
  const RouteMap after = mark_exit_signal_lanes(before);
  EXPECT_THAT(marked(after), ElementsAreArray({r.ix.ring[0]}));
  EXPECT_EQ(after.at(r.ix.ring[4]).params.at("enable_exit_turn_signal"), "false");
  EXPECT_EQ(after.at(r.ix.ring[4]).params.at("other"), "x");
  ASSERT_EQ(after.size(), before.size());
  for (std::size_t i = 0; i < before.size(); ++i) {
    EXPECT_EQ(after.at(i).lane_id, before.at(i).lane_id);
    EXPECT_DOUBLE_EQ(after.at(i).s_start, before.at(i).s_start);
    EXPECT_EQ(after.at(i).roundabout_role, before.at(i).roundabout_role);
  }
  // Entry, exit and lanes outside the roundabout are never marked.
  for (std::size_t i : {std::size_t{0}, r.ix.entry, r.ix.exit, r.ix.out})
    EXPECT_FALSE(after.at(i).params.contains("enable_exit_turn_signal")) << i;
}

TEST(ExitSignalMarking, RouteEndingOnTheRingIsLeftAlone) {
  auto r = roundabout_route(3);
  const RouteMap full = r.sketch.build();
  std::vector<Lanelet> lanelets(full.lanelets().begin(), full.lanelets().begin() + 6);  // up to :N2_2_0
  EXPECT_TRUE(marked(mark_exit_signal_lanes(RouteMap(lanelets))).empty());
}

TEST(ExitSignalMarking, EachRoundaboutOfTheRouteSeparately) {
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto first = test::add_roundabout(sketch, 1, "0", "N", {}, 15.0);
  const auto second = test::add_roundabout(sketch, 3, "1", "M");
  const RouteMap route = mark_exit_signal_lanes(sketch.build());
  EXPECT_THAT(marked(route), ElementsAreArray({first.ring[0], second.ring[4]}));
}

TEST(ExitSignalMarking, RouteStartingOnTheRing) {
  auto r = roundabout_route(3);
  const RouteMap full = r.sketch.build();
  // Start on :N1_2_0 (no entry on the route): :N1_2_0, r12, :N2_2_0, r23, exit, out3.
  std::vector<Lanelet> lanelets(full.lanelets().begin() + 3, full.lanelets().end());
  double s = 0.0;
  for (Lanelet& l : lanelets) {
    l.s_start = s;
    s += l.length;
  }
  EXPECT_THAT(marked(mark_exit_signal_lanes(RouteMap(lanelets))), ElementsAreArray({3u}));  // r23
  lanelets[1].leaves_ring_at_end = false;
  lanelets[2].leaves_ring_at_end = false;
  EXPECT_THAT(marked(mark_exit_signal_lanes(RouteMap(lanelets))), ElementsAreArray({1u, 2u, 3u}));  // after :N1_2_0
  lanelets[0].leaves_ring_at_end = false;
  EXPECT_THAT(marked(mark_exit_signal_lanes(RouteMap(lanelets))), ElementsAreArray({0u, 1u, 2u, 3u}));
}

TEST(ExitSignalMarking, JapanExitBlinkerFromThePreviousExit) {
  // Japan: on_entry None, on_exit Left. The exit blinker starts when the front leaves the junction of
  // the previous exit (the entry for the first exit) and ends when base_link leaves the exit lanelet.
  for (int k = 1; k <= 3; ++k) {
    auto r = roundabout_route(k);
    const RouteMap route = mark_exit_signal_lanes(r.sketch.build());
    const double start = route.at(r.ix.ring_lanes.back()).s_start;  // the ring lane the exit leaves from
    const double end = route.at(r.ix.exit).s_end();
    test::Drive drive(route, test::roundabout_params("None", "Left"), 50.0);
    EXPECT_EQ(drive.to_front(start).turn, TurnIndicator::Disable) << k;
    const auto& on = drive.to_front(start + 0.01);
    EXPECT_EQ(on.turn, TurnIndicator::EnableLeft) << k;
    EXPECT_EQ(on.source, RequestSource::RoundaboutExit) << k;
    EXPECT_DOUBLE_EQ(on.roundabout.desired_start, start) << k;
    EXPECT_EQ(drive.to_base(end).turn, TurnIndicator::EnableLeft) << k;
    EXPECT_EQ(drive.to_base(end + 0.01).turn, TurnIndicator::Disable) << k;
  }
}

}  // namespace
}  // namespace signalsim
