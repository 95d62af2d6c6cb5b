// Roundabout requests (docs/behaviour.md §T5.1-§T5.3) on synthetic routes: collection, entries, exits, the exit
// used, tags, persistence, the enable_exit_turn_signal chain, erase rules and FIRST_ACTIVE.
#include "turn_signal/roundabout_requests.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "route_sketch.hpp"
#include "turn_signal/required_end.hpp"

namespace signalsim {
namespace {

using test::add_roundabout;
using test::sketch_ego_base;
using test::sketch_ego_front;
using test::roundabout_params;
using test::roundabout_route;
using ::testing::ElementsAre;
using test::kLeft;
using test::kRight;

RouteMap::Window everything(const RouteMap& route) { return {0, route.size()}; }

// ---- helpers ---------------------------------------------------------------------------------------

TEST(RoundaboutTags, SplitOnBracketsCommasAndSpaces) {
  EXPECT_THAT(split_exit_tag("[301599, 301600]"), ElementsAre("301599", "301600"));
  EXPECT_THAT(split_exit_tag("301599"), ElementsAre("301599"));
  EXPECT_THAT(split_exit_tag("a,b c]d[e"), ElementsAre("a", "b", "c", "d", "e"));
  EXPECT_THAT(split_exit_tag("  [ :R1_1_0 ,, out2 ]  "), ElementsAre(":R1_1_0", "out2"));
  EXPECT_TRUE(split_exit_tag("").empty());
  EXPECT_TRUE(split_exit_tag("[ , ]").empty());
}

TEST(RoundaboutTags, CommandSettingsAreCaseSensitive) {
  EXPECT_EQ(roundabout_command("Left"), kLeft);
  EXPECT_EQ(roundabout_command("Right"), kRight);
  EXPECT_EQ(roundabout_command("None"), TurnIndicator::Disable);
  EXPECT_EQ(roundabout_command("left"), TurnIndicator::Disable);
  EXPECT_EQ(roundabout_command("RIGHT"), TurnIndicator::Disable);
  EXPECT_EQ(roundabout_command(""), TurnIndicator::Disable);
}

TEST(RoundaboutTags, ExitNamesAreTheExitLaneAndTheEdgeItLeadsOnto) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  EXPECT_THAT(exit_names(route, r.ix.exit), ElementsAre(":N2_1_0", "out2"));
  // An Internal lanelet (the route ends on the ring) is named by its lane id only.
  EXPECT_THAT(exit_names(route, r.ix.ring.back()), ElementsAre("r12_0"));
}

TEST(RoundaboutTags, TagListsLaneIdOrEdgeId) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  const auto names = exit_names(route, r.ix.exit);
  Lanelet entry;
  entry.params["exit_turn_signal_left"] = "[301599, :N2_1_0]";
  entry.params["exit_turn_signal_right"] = "out2";
  EXPECT_TRUE(exit_tag_lists(entry, "exit_turn_signal_left", names));
  EXPECT_TRUE(exit_tag_lists(entry, "exit_turn_signal_right", names));
  entry.params["exit_turn_signal_left"] = "[:N1_1_0, out1, out2_0, N2_1_0, :N2_1]";  // other exits / near misses
  EXPECT_FALSE(exit_tag_lists(entry, "exit_turn_signal_left", names));
  EXPECT_FALSE(exit_tag_lists(entry, "exit_turn_signal_missing", names));
}

TEST(RoundaboutExitUsed, LastRoundaboutLaneletBeforeLeaving) {
  for (int k = 1; k <= 3; ++k) {
    auto r = roundabout_route(k);
    const RouteMap route = r.sketch.build();
    const RoundaboutConnection entry = roundabout_connection_at(route, r.ix.entry);
    EXPECT_EQ(roundabout_exit_used(route, entry), std::optional<std::size_t>(r.ix.exit)) << "exit " << k;
  }
}

TEST(RoundaboutExitUsed, RouteEndingOnTheRingGivesTheLastRingLanelet) {
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  add_roundabout(sketch, 2);
  const RouteMap full = sketch.build();
  std::vector<Lanelet> lanelets(full.lanelets().begin(), full.lanelets().end());
  lanelets.resize(5);  // in0, entry, r01, :N1_2_0, r12
  const RouteMap route(lanelets);
  EXPECT_EQ(roundabout_exit_used(route, roundabout_connection_at(route, 1)), std::optional<std::size_t>(4));
}

TEST(RoundaboutExitUsed, NoneWhenTheEntryHasNoRoundaboutOrTheRouteLeavesAtOnce) {
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  Lanelet& entry = sketch.arc(":N0_0_0", 10.0, -60.0);
  entry.roundabout_role = RoundaboutRole::Entry;
  entry.roundabout_id = "0";
  sketch.straight("elsewhere_0", 50.0);
  RouteMap route = sketch.build();
  EXPECT_EQ(roundabout_exit_used(route, roundabout_connection_at(route, 1)), std::nullopt);
  sketch.at(1).roundabout_id.clear();
  sketch.at(2).roundabout_role = RoundaboutRole::Internal;
  route = sketch.build();
  EXPECT_EQ(roundabout_exit_used(route, roundabout_connection_at(route, 1)), std::nullopt);
}

TEST(RoundaboutConnections, EntriesAndExitsOnceInPathOrder) {
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto first = add_roundabout(sketch, 1, "0", "N", {}, 15.0);
  const auto second = add_roundabout(sketch, 2, "1", "M");
  const RouteMap route = sketch.build();
  const auto all = roundabout_connections(route, everything(route));
  ASSERT_EQ(all.size(), 4u);
  EXPECT_EQ(all[0].front_index, first.entry);
  EXPECT_EQ(all[0].role, RoundaboutRole::Entry);
  EXPECT_EQ(all[1].front_index, first.exit);
  EXPECT_EQ(all[1].role, RoundaboutRole::Exit);
  EXPECT_EQ(all[2].front_index, second.entry);
  EXPECT_EQ(all[3].front_index, second.exit);
  // Only what lies in the window.
  const auto later = roundabout_connections(route, {first.out, route.size()});
  ASSERT_EQ(later.size(), 2u);
  EXPECT_EQ(later[0].front_index, second.entry);
}

TEST(RoundaboutConnections, AConnectionSplitIntoTwoInternalLanesIsOneEntry) {
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  for (const char* id : {":N0_0_0", ":N0_4_0"}) {
    Lanelet& part = sketch.arc(id, 10.0, -30.0);
    part.roundabout_role = RoundaboutRole::Entry;
    part.roundabout_id = "0";
  }
  Lanelet& ring = sketch.arc("r01_0", 20.0, 80.0);
  ring.roundabout_role = RoundaboutRole::Internal;
  ring.roundabout_id = "0";
  const RouteMap route = sketch.build();
  const auto all = roundabout_connections(route, {2, route.size()});  // the window starts in the second part
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].front_index, 1u);
  EXPECT_EQ(all[0].back_index, 2u);

  RoundaboutRequests requests;
  const auto info = requests.update(route, everything(route), sketch_ego_front(80.0), roundabout_params("Left", "None"));
  EXPECT_EQ(info.turn, kLeft);
  EXPECT_DOUBLE_EQ(info.required_start, route.at(1).s_start);
  EXPECT_DOUBLE_EQ(info.desired_end, route.at(2).s_end());
  EXPECT_THAT(requests.desired_starts(), ElementsAre(std::pair<const std::size_t, double>(1u, 80.0 - test::kB2F)));
}

TEST(RoundaboutChain, EarliestContiguousEnableExitTurnSignalPredecessor) {
  auto r = roundabout_route(3);
  EXPECT_EQ(exit_signal_chain_start(r.sketch.build(), r.ix.exit), std::nullopt);
  r.sketch.at(r.ix.ring[3]).params["enable_exit_turn_signal"] = "true";  // :N2_2_0
  r.sketch.at(r.ix.ring[4]).params["enable_exit_turn_signal"] = "true";  // r23_0
  EXPECT_EQ(exit_signal_chain_start(r.sketch.build(), r.ix.exit), std::optional<std::size_t>(r.ix.ring[3]));
  // The chain must be contiguous: r12 alone (before a gap) does not count.
  r.sketch.at(r.ix.ring[3]).params["enable_exit_turn_signal"] = "false";
  r.sketch.at(r.ix.ring[2]).params["enable_exit_turn_signal"] = "true";
  EXPECT_EQ(exit_signal_chain_start(r.sketch.build(), r.ix.exit), std::optional<std::size_t>(r.ix.ring[4]));
  // Exactly "true".
  r.sketch.at(r.ix.ring[4]).params["enable_exit_turn_signal"] = "True";
  EXPECT_EQ(exit_signal_chain_start(r.sketch.build(), r.ix.exit), std::nullopt);
}

// ---- §T5.2 entries ----------------------------------------------------------------------------------

TEST(RoundaboutEntry, OnEntryNoneGivesNoRequestAndStoresNothing) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  RoundaboutRequests requests;
  const double e = route.at(r.ix.entry).s_start;
  for (double front = e - 29.0; front < route.at(r.ix.exit).s_start; front += 1.0) {
    const auto info = requests.update(route, everything(route), sketch_ego_front(front), roundabout_params("None", "None"));
    EXPECT_EQ(info.turn, TurnIndicator::NoCommand) << front;
    EXPECT_TRUE(requests.desired_starts().empty()) << front;
  }
}

TEST(RoundaboutEntry, LeftOrRightFromTheStoredStartToTheEntryEnd) {
  for (const auto& [setting, command] : {std::pair{"Left", kLeft}, std::pair{"Right", kRight}}) {
    auto r = roundabout_route(2);
    const RouteMap route = r.sketch.build();
    const Lanelet& entry = route.at(r.ix.entry);
    RoundaboutRequests requests;
    const auto params = roundabout_params(setting, "None");
    // Strictly within the search distance (30 m at v = 0) of the front.
    EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(entry.s_start - 30.0), params).turn,
              TurnIndicator::NoCommand);
    const auto info = requests.update(route, everything(route), sketch_ego_front(entry.s_start - 29.99), params);
    EXPECT_EQ(info.turn, command);
    EXPECT_EQ(info.source, RequestSource::RoundaboutEntry);
    EXPECT_DOUBLE_EQ(info.desired_start, entry.s_start - 29.99 - test::kB2F);  // the ego pose (s_base) then
    EXPECT_DOUBLE_EQ(info.required_start, entry.s_start);
    EXPECT_DOUBLE_EQ(info.desired_end, entry.s_end());
    EXPECT_DOUBLE_EQ(info.required_end, entry.s_start + required_end_arc_length(entry.shape, 15.0));
    EXPECT_LT(info.required_end, entry.s_end());
  }
}

TEST(RoundaboutEntry, SearchDistanceGrowsWithSpeedAndTheStartIsRemembered) {
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  const double e = route.at(r.ix.entry).s_start;
  RoundaboutRequests requests;
  const auto params = roundabout_params("Left", "None");
  // 3 s * 10 m/s + 30 m = 60 m.
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(e - 60.0, 10.0), params).turn, TurnIndicator::NoCommand);
  const double stored = requests.update(route, everything(route), sketch_ego_front(e - 59.9, 10.0), params).desired_start;
  EXPECT_DOUBLE_EQ(stored, e - 59.9 - test::kB2F);
  // Braking shrinks the search distance: the start stays where it was.
  EXPECT_DOUBLE_EQ(requests.update(route, everything(route), sketch_ego_front(e - 45.0, 1.0), params).desired_start, stored);
  // Once registered, the entry is never filtered by distance again (even from far behind).
  const auto far = requests.update(route, everything(route), sketch_ego_front(1.0, 0.0), params);
  EXPECT_EQ(far.turn, kLeft);
  EXPECT_DOUBLE_EQ(far.desired_start, stored);
}

TEST(RoundaboutEntry, TurnSignalDistanceOverridesTheSearch) {
  auto r = roundabout_route(1);
  r.sketch.at(r.ix.entry).turn_signal_distance = 10.0;
  const RouteMap route = r.sketch.build();
  const double e = route.at(r.ix.entry).s_start;
  RoundaboutRequests requests;
  const auto params = roundabout_params("Right", "None");
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(e - 10.0, 10.0), params).turn, TurnIndicator::NoCommand);
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(e - 9.9, 10.0), params).turn, kRight);
}

TEST(RoundaboutEntry, ExitTagByLaneIdOverridesOnEntryNone) {
  const std::map<std::string, std::string> tags{{"exit_turn_signal_left", "[:N2_1_0, 301600]"}};
  auto second = roundabout_route(2, tags);
  const RouteMap route = second.sketch.build();
  RoundaboutRequests requests;
  const auto info = requests.update(route, everything(route), sketch_ego_front(95.0), roundabout_params("None", "None"));
  EXPECT_EQ(info.turn, kLeft);
  EXPECT_EQ(info.source, RequestSource::RoundaboutEntry);
  // The same tags with the first exit: not listed, on_entry None -> no request, start forgotten.
  auto first = roundabout_route(1, tags);
  const RouteMap other = first.sketch.build();
  RoundaboutRequests none;
  EXPECT_EQ(none.update(other, everything(other), sketch_ego_front(95.0), roundabout_params("None", "None")).turn,
            TurnIndicator::NoCommand);
  EXPECT_TRUE(none.desired_starts().empty());
}

TEST(RoundaboutEntry, ExitTagByEdgeIdAndLeftBeforeRight) {
  auto third = roundabout_route(3, {{"exit_turn_signal_right", "out1 out3"}});
  const RouteMap route = third.sketch.build();
  RoundaboutRequests requests;
  // The tag overrides on_entry whatever it is.
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(95.0), roundabout_params("Left", "None")).turn, kRight);

  auto both = roundabout_route(3, {{"exit_turn_signal_right", "out3"}, {"exit_turn_signal_left", ":N3_1_0"}});
  const RouteMap route2 = both.sketch.build();
  RoundaboutRequests requests2;
  EXPECT_EQ(requests2.update(route2, everything(route2), sketch_ego_front(95.0), roundabout_params("Right", "None")).turn,
            kLeft);
}

TEST(RoundaboutEntry, PersistenceKeepsTheEntryToTheEndOfTheExitLanelet) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  const Lanelet& exit = route.at(r.ix.exit);
  const double on_ring = route.at(r.ix.ring[2]).s_start + 5.0;  // base_link on r12

  RoundaboutRequests off;
  off.update(route, everything(route), sketch_ego_front(95.0), roundabout_params("Left", "Right", false));
  EXPECT_EQ(off.update(route, everything(route), sketch_ego_base(on_ring), roundabout_params("Left", "Right", false)).turn,
            TurnIndicator::NoCommand);
  EXPECT_TRUE(off.desired_starts().empty());  // desired end passed: erased

  RoundaboutRequests on;
  const auto params = roundabout_params("Left", "Right", true);
  on.update(route, everything(route), sketch_ego_front(95.0), params);
  const auto info = on.update(route, everything(route), sketch_ego_base(on_ring), params);
  EXPECT_EQ(info.turn, kLeft);
  EXPECT_EQ(info.source, RequestSource::RoundaboutEntry);
  EXPECT_DOUBLE_EQ(info.desired_end, exit.s_end());
  // The only queued item is returned although its required end (in the entry) is passed (§T12.1.6).
  EXPECT_LT(info.required_end, sketch_ego_base(on_ring).s_base);
}

TEST(RoundaboutEntry, PersistentEntryIsPoppedOnceTheExitRequestIsQueued) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  const Lanelet& exit = route.at(r.ix.exit);
  RoundaboutRequests requests;
  const auto params = roundabout_params("Left", "Right", true);
  requests.update(route, everything(route), sketch_ego_front(95.0), params);
  // The front exactly on the exit start: the exit is not queued yet (DIST - b2f >= 0).
  auto info = requests.update(route, everything(route), sketch_ego_front(exit.s_start), params);
  EXPECT_EQ(info.source, RequestSource::RoundaboutEntry);
  EXPECT_EQ(info.turn, kLeft);
  // Just past it: [entry, exit]; the entry's required end is passed -> popped.
  info = requests.update(route, everything(route), sketch_ego_front(exit.s_start + 0.01), params);
  EXPECT_EQ(info.source, RequestSource::RoundaboutExit);
  EXPECT_EQ(info.turn, kRight);
  // Base_link past the exit end: both erased.
  info = requests.update(route, everything(route), sketch_ego_base(exit.s_end() + 0.01), params);
  EXPECT_EQ(info.turn, TurnIndicator::NoCommand);
  EXPECT_TRUE(requests.desired_starts().empty());
}

TEST(RoundaboutEntry, PersistentEntryGivesWayToADisableExit) {
  // on_exit "None": the exit request is DISABLE but still heads the queue once the entry is popped.
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  const Lanelet& exit = route.at(r.ix.exit);
  RoundaboutRequests requests;
  const auto params = roundabout_params("Right", "None", true);
  requests.update(route, everything(route), sketch_ego_front(95.0), params);
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(exit.s_start - 1.0), params).turn, kRight);
  const auto info = requests.update(route, everything(route), sketch_ego_front(exit.s_start + 0.5), params);
  EXPECT_EQ(info.turn, TurnIndicator::Disable);
  EXPECT_EQ(info.source, RequestSource::RoundaboutExit);
}

TEST(RoundaboutEntry, WithoutPersistenceTheEntryLastsToItsOwnEnd) {
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  const Lanelet& entry = route.at(r.ix.entry);
  RoundaboutRequests requests;
  const auto params = roundabout_params("Left", "None", false);
  requests.update(route, everything(route), sketch_ego_front(95.0), params);
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_base(entry.s_end()), params).turn, kLeft);  // de == 0
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_base(entry.s_end() + 0.01), params).turn,
            TurnIndicator::NoCommand);
  EXPECT_TRUE(requests.desired_starts().empty());
}

TEST(RoundaboutEntry, OnlyEntriesInTheWindowAreCollected) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  RoundaboutRequests requests;
  const auto params = roundabout_params("Left", "None", true);
  requests.update(route, everything(route), sketch_ego_front(95.0), params);
  const auto on_ring = sketch_ego_base(route.at(r.ix.ring[1]).s_start + 1.0);
  EXPECT_EQ(requests.update(route, everything(route), on_ring, params).turn, kLeft);
  EXPECT_EQ(requests.update(route, {r.ix.ring[0], route.size()}, on_ring, params).turn, TurnIndicator::NoCommand);
}

// ---- §T5.3 exits ------------------------------------------------------------------------------------

TEST(RoundaboutExit, StartsExactlyWhenTheFrontPassesTheExitStart) {
  auto r = roundabout_route(2);
  const RouteMap route = r.sketch.build();
  const Lanelet& exit = route.at(r.ix.exit);
  RoundaboutRequests requests;
  const auto params = roundabout_params("None", "Left");
  // No search distance: nothing until the front is past the exit start, however slow or fast.
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(exit.s_start - 0.01, 15.0), params).turn,
            TurnIndicator::NoCommand);
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(exit.s_start), params).turn, TurnIndicator::NoCommand);
  const auto info = requests.update(route, everything(route), sketch_ego_front(exit.s_start + 0.01), params);
  EXPECT_EQ(info.turn, kLeft);
  EXPECT_EQ(info.source, RequestSource::RoundaboutExit);
  EXPECT_DOUBLE_EQ(info.desired_start, exit.s_start);  // the position, not the ego pose
  EXPECT_DOUBLE_EQ(info.required_start, exit.s_start);
  EXPECT_DOUBLE_EQ(info.desired_end, exit.s_end());
  EXPECT_DOUBLE_EQ(info.required_end, exit.s_start + required_end_arc_length(exit.shape, 15.0));
}

TEST(RoundaboutExit, RequiredEndUsesTheRoundaboutAngleThreshold) {
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  const Lanelet& exit = route.at(r.ix.exit);
  auto params = roundabout_params("None", "Left");
  params.turn_signal_roundabout_angle_threshold_deg = 40.0;
  params.turn_signal_intersection_angle_threshold_deg = 5.0;  // not used here
  RoundaboutRequests requests;
  const auto info = requests.update(route, everything(route), sketch_ego_front(exit.s_start + 1.0), params);
  EXPECT_DOUBLE_EQ(info.required_end, exit.s_start + required_end_arc_length(exit.shape, 40.0));
  EXPECT_LT(info.required_end, exit.s_start + required_end_arc_length(exit.shape, 15.0));
}

TEST(RoundaboutExit, EnableExitTurnSignalChainMovesTheDesiredStartBack) {
  auto r = roundabout_route(3);
  r.sketch.at(r.ix.ring[3]).params["enable_exit_turn_signal"] = "true";  // :N2_2_0
  r.sketch.at(r.ix.ring[4]).params["enable_exit_turn_signal"] = "true";  // r23_0
  const RouteMap route = r.sketch.build();
  const double chain = route.at(r.ix.ring[3]).s_start;
  const Lanelet& exit = route.at(r.ix.exit);
  RoundaboutRequests requests;
  const auto params = roundabout_params("None", "Left");
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_front(chain), params).turn, TurnIndicator::NoCommand);
  const auto info = requests.update(route, everything(route), sketch_ego_front(chain + 0.01), params);
  EXPECT_EQ(info.turn, kLeft);
  EXPECT_DOUBLE_EQ(info.desired_start, chain);        // the chain's start, stored as that position
  EXPECT_DOUBLE_EQ(info.required_start, exit.s_start);  // the required section is still the exit's
  EXPECT_DOUBLE_EQ(info.desired_end, exit.s_end());
  EXPECT_EQ(requests.desired_starts().at(r.ix.exit), chain);
}

TEST(RoundaboutExit, OnExitNoneIsADisableRequest) {
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  RoundaboutRequests requests;
  const auto info =
      requests.update(route, everything(route), sketch_ego_front(route.at(r.ix.exit).s_start + 1.0), roundabout_params("None", "None"));
  EXPECT_EQ(info.turn, TurnIndicator::Disable);
  EXPECT_EQ(info.source, RequestSource::RoundaboutExit);
}

TEST(RoundaboutExit, ErasedOnceBaseLinkPassesTheExitEnd) {
  auto r = roundabout_route(1);
  const RouteMap route = r.sketch.build();
  const Lanelet& exit = route.at(r.ix.exit);
  RoundaboutRequests requests;
  const auto params = roundabout_params("None", "Right");
  requests.update(route, everything(route), sketch_ego_front(exit.s_start + 1.0), params);
  EXPECT_TRUE(requests.desired_starts().contains(r.ix.exit));
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_base(exit.s_end()), params).turn, kRight);  // still (>= 0)
  EXPECT_EQ(requests.update(route, everything(route), sketch_ego_base(exit.s_end() + 0.01), params).turn,
            TurnIndicator::NoCommand);
  EXPECT_TRUE(requests.desired_starts().empty());
}

// ---- queue order -----------------------------------------------------------------------------------

TEST(RoundaboutQueue, AllEntriesBeforeAllExits) {
  // Two roundabouts 15 m apart. While the ego leaves the first one, the second one's entry is already
  // within reach: the queue is [entry 2, exit 1], not path order, and entry 2 heads it.
  test::RouteSketch sketch;
  sketch.straight("in0_0", 100.0);
  const auto first = add_roundabout(sketch, 1, "0", "N", {}, 15.0);
  const auto second = add_roundabout(sketch, 1, "1", "M");
  const RouteMap route = sketch.build();
  const Lanelet& exit1 = route.at(first.exit);
  ASSERT_LT(route.at(second.entry).s_start - (exit1.s_start + 1.0), 30.0);
  RoundaboutRequests requests;
  const auto params = roundabout_params("Right", "Left");
  requests.update(route, everything(route), sketch_ego_front(exit1.s_start - 1.0), params);
  const auto info = requests.update(route, everything(route), sketch_ego_front(exit1.s_start + 1.0), params);
  EXPECT_EQ(info.source, RequestSource::RoundaboutEntry);
  EXPECT_EQ(info.turn, kRight);
  EXPECT_DOUBLE_EQ(info.required_start, route.at(second.entry).s_start);
  // With on_entry None the second entry gives no request: the exit is what remains.
  RoundaboutRequests japan;
  const auto jp = roundabout_params("None", "Left");
  const auto exit_info = japan.update(route, everything(route), sketch_ego_front(exit1.s_start + 1.0), jp);
  EXPECT_EQ(exit_info.source, RequestSource::RoundaboutExit);
  EXPECT_EQ(exit_info.turn, kLeft);
}

}  // namespace
}  // namespace signalsim
