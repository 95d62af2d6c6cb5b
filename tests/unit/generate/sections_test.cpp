// The sections generate reads from a route (sections.hpp): docs/behaviour.md §T4.2 grouping, §T5.2 entries with
// exit tags, §T5.3 exits with the enable_exit_turn_signal chain, the lane changes.
#include "law/sections.hpp"

#include <gtest/gtest.h>

#include "route_fixture.hpp"

namespace signalsim::generate {
using namespace law;  // the rules: sections, speeds, expectations (src/law)
namespace {

TEST(Sections, ALeftTurnsTwoInternalLanesAreOneTurnNamedByItsJunction) {
  test::RouteFixture f;
  f.lane("a", 100.0);
  f.internal("A", 3, 5.0, TurnDirection::Left);
  f.internal("A", 15, 14.0, TurnDirection::Left);
  f.lane("b", 100.0);
  f.internal("B", 2, 9.0, TurnDirection::Right);
  f.lane("c", 100.0);
  f.internal("C", 1, 12.0, TurnDirection::Straight);
  f.lane("d", 100.0);
  const auto sections = route_sections(f.build(), {}, {});
  ASSERT_EQ(sections.size(), 2u);  // the straight junction C asks for nothing
  EXPECT_EQ(sections[0].kind, SectionKind::Turn);
  EXPECT_EQ(sections[0].side, Side::Left);
  EXPECT_EQ(sections[0].target.junction, "A");
  EXPECT_DOUBLE_EQ(sections[0].start, 100.0);
  EXPECT_DOUBLE_EQ(sections[0].end, 119.0);
  EXPECT_EQ(sections[0].lanelets, (std::vector<std::string>{":A_3_0", ":A_15_0"}));
  EXPECT_EQ(sections[1].side, Side::Right);
  EXPECT_EQ(sections[1].target.junction, "B");
  EXPECT_DOUBLE_EQ(sections[1].search_distance, 30.0);
}

TEST(Sections, AJunctionTheRouteMeetsTwiceIsNotNamed) {
  test::RouteFixture f;
  f.lane("a", 100.0);
  f.internal("A", 1, 10.0, TurnDirection::Left);
  f.lane("b", 100.0);
  f.internal("A", 7, 10.0, TurnDirection::Left);  // the same junction again, another connection
  f.lane("c", 100.0);
  const auto sections = route_sections(f.build(), {}, {});
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[0].target.junction, "");
  EXPECT_EQ(sections[0].target.lanelet, ":A_1_0");  // one lanelet, on the route once
}

TEST(Sections, TurnSignalDistanceOverridesTheSearch) {
  test::RouteFixture f;
  f.lane("a", 100.0);
  f.internal("A", 1, 10.0, TurnDirection::Right).turn_signal_distance = 45.0;
  f.lane("b", 100.0);
  const auto sections = route_sections(f.build(), {}, {});
  ASSERT_EQ(sections.size(), 1u);
  ASSERT_TRUE(sections[0].search_override);
  EXPECT_DOUBLE_EQ(*sections[0].search_override, 45.0);
}

// in (100 m), entry :RS_0_0, ring ring_SE, internal :RE_2_0, ring ring_EN (marked), exit :RN_1_0, out_N.
RouteMap roundabout(bool tagged) {
  test::RouteFixture f;
  f.lane("in_S", 100.0);
  Lanelet& entry = f.internal("RS", 0, 8.0, TurnDirection::Right);
  entry.roundabout_role = RoundaboutRole::Entry;
  entry.roundabout_id = "0";
  if (tagged) entry.params["exit_turn_signal_right"] = "[:RE_1_0, out_N]";
  Lanelet& ring1 = f.lane("ring_SE", 17.7);
  ring1.roundabout_role = RoundaboutRole::Internal;
  ring1.roundabout_id = "0";
  Lanelet& mid = f.internal("RE", 2, 13.1, TurnDirection::Straight);
  mid.roundabout_role = RoundaboutRole::Internal;
  mid.roundabout_id = "0";
  Lanelet& ring2 = f.lane("ring_EN", 17.7);
  ring2.roundabout_role = RoundaboutRole::Internal;
  ring2.roundabout_id = "0";
  ring2.params["enable_exit_turn_signal"] = "true";
  Lanelet& exit = f.internal("RN", 1, 8.1, TurnDirection::Right);
  exit.roundabout_role = RoundaboutRole::Exit;
  exit.roundabout_id = "0";
  f.lane("out_N", 200.0);
  return f.build();
}

TEST(Sections, RoundaboutEntryAndExitTakeTheCountrysSidesAndTheChainStart) {
  SectionParameters kr;
  kr.on_entry = "Left";
  kr.on_exit = "Right";
  const auto sections = route_sections(roundabout(false), kr, {});
  ASSERT_EQ(sections.size(), 2u);  // the ring's internal lanes ask for nothing; dir r on them is ignored
  EXPECT_EQ(sections[0].kind, SectionKind::RoundaboutEntry);
  EXPECT_EQ(sections[0].side, Side::Left);
  EXPECT_EQ(sections[0].target.junction, "RS");
  EXPECT_EQ(sections[1].kind, SectionKind::RoundaboutExit);
  EXPECT_EQ(sections[1].side, Side::Right);
  EXPECT_NEAR(sections[1].start, 100.0 + 8.0 + 17.7 + 13.1 + 17.7, 1e-9);
  // docs/behaviour.md §T5.3: the exit's desired start is the front of the enable_exit_turn_signal chain (ring_EN).
  EXPECT_NEAR(sections[1].exit_desired_start, 100.0 + 8.0 + 17.7 + 13.1, 1e-9);

  SectionParameters de;
  de.on_exit = "Right";  // entry "None": no entry request
  EXPECT_EQ(route_sections(roundabout(false), de, {})[0].side, Side::None);
}

TEST(Sections, AnExitTagOnTheEntryNamingTheExitTakenGivesTheEntryItsSide) {
  SectionParameters de;
  de.on_exit = "Right";
  // The tag lists the normal edge the exit leads onto (signalsim's SUMO names, docs/behaviour.md §T5.2).
  EXPECT_EQ(route_sections(roundabout(true), de, {})[0].side, Side::Right);
}

TEST(Sections, LaneChangesAreSectionsOfEitherSideSortedWithTheOthers) {
  test::RouteFixture f;
  f.lane("a", 150.0);
  f.internal("A", 1, 10.0, TurnDirection::Left);
  f.lane("b", 150.0);
  const auto sections = route_sections(f.build(), {}, {{"a", "a_1", 20.0 - 3.7, 0.0, 150.0}});
  ASSERT_EQ(sections.size(), 2u);
  EXPECT_EQ(sections[0].kind, SectionKind::LaneChange);
  EXPECT_EQ(sections[0].side, Side::Either);
  EXPECT_DOUBLE_EQ(sections[0].end, 150.0);
  EXPECT_EQ(sections[1].kind, SectionKind::Turn);
}

}  // namespace
}  // namespace signalsim::generate
