// The expectation numbers of generate (expectation_rules.hpp) for hand-made routes, each worked out by
// hand from the spec in the comments (docs/behaviour.md §T4.1 search = 3 s x v + 30 m; base_link 3.7 m behind the
// front; kSpeedSlack 0.3 m/s; kMargin 0.5 m; numbers rounded inwards to 0.1 m; the activation scan's
// 0.1 m grid may move a lead by one tenth).
#include "law/expectation_rules.hpp"

#include <algorithm>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "route_fixture.hpp"

namespace signalsim::generate {
using namespace law;  // the rules: sections, speeds, expectations (src/law)
namespace {

using Kind = GeneratedExpectation::Kind;
constexpr double kB2f = 3.7;
const SpeedLimits kEgo{13.89, 1.0, 1.0};

struct Derived {
  RouteMap route;
  std::vector<Section> sections;
  Derivation d;
};

Derived derive(const test::RouteFixture& f, std::vector<StopPoint> stops = {},
               std::vector<LaneChangeFact> lane_changes = {}, SectionParameters sp = {},
               std::vector<LightFact> lights = {}) {
  Derived out;
  out.route = f.build();
  out.sections = route_sections(out.route, sp, lane_changes);
  const SpeedProfile speed(out.route, 0.0, 13.8, kEgo, 0.1, std::move(stops));
  RuleParameters rules;
  rules.base_link_to_front = kB2f;
  out.d = derive_expectations(out.sections, {0.0, out.route.length(), std::move(lights)}, speed, rules);
  return out;
}

std::vector<GeneratedExpectation> of_kind(const Derivation& d, Kind kind) {
  std::vector<GeneratedExpectation> out;
  std::copy_if(d.expectations.begin(), d.expectations.end(), std::back_inserter(out),
               [&](const GeneratedExpectation& e) { return e.kind == kind; });
  return out;
}

std::vector<std::string> never(const Derivation& d) {
  std::vector<std::string> out;
  for (const auto& e : of_kind(d, Kind::BlinkerNever)) out.push_back(e.blinker);
  return out;
}

// a 200 m, left turn :J_0_0 15 m, b 300 m; 13.89 m/s everywhere, the ego at its top speed.
test::RouteFixture one_left_turn() {
  test::RouteFixture f;
  f.lane("a", 200.0);
  f.internal("J", 0, 15.0, TurnDirection::Left, 13.89);
  f.lane("b", 300.0);
  return f;
}

TEST(ExpectationRules, LeadIsTheSearchDistanceAtTheLowestPlannedSpeed) {
  const Derived r = derive(one_left_turn());
  const auto through = of_kind(r.d, Kind::ThroughJunction);
  ASSERT_EQ(through.size(), 1u);
  EXPECT_EQ(through[0].target, "J");
  EXPECT_EQ(through[0].blinker, "left");
  // search = 3 s x (13.89 - 0.3) m/s + 30 m = 70.77 m; less the 0.5 m margin: 70.27 -> 70.2.
  EXPECT_NEAR(through[0].lead, 70.2, 0.1 + 1e-9);
  EXPECT_THAT(through[0].why, testing::HasSubstr("search 3.0 s x 13.6 m/s + 30.0 m = 70.8 m"));
  // Possible from 200 - (3 x 14.19 + 30) = 127.43; until base_link leaves the turn, 215 + 3.7 = 218.7.
  const auto quiet = of_kind(r.d, Kind::NoBlinker);
  ASSERT_EQ(quiet.size(), 2u);
  EXPECT_DOUBLE_EQ(quiet[0].from_s, 1.0);    // departure + 1 m
  EXPECT_DOUBLE_EQ(quiet[0].to_s, 126.9);    // 127.43 - 0.5
  EXPECT_DOUBLE_EQ(quiet[1].from_s, 219.2);  // 218.7 + 0.5
  EXPECT_DOUBLE_EQ(quiet[1].to_s, 514.0);    // route end 515 - 1
  EXPECT_EQ(never(r.d), (std::vector<std::string>{"right", "hazard"}));
  EXPECT_TRUE(of_kind(r.d, Kind::NeverRunsRed).empty());  // no light on the route
  EXPECT_EQ(of_kind(r.d, Kind::Arrives).size(), 1u);
}

TEST(ExpectationRules, ALightBeforeTheTurnLeavesOnlyTheSearchDistanceAtRest) {
  // The ego may be braking for the light at the turn (its stop line at 200): v may be 0 where the
  // search reaches, so only 30 m are certain: 30 - 0.5 -> 29.5 (29.4 on the scan's grid).
  std::vector<LightFact> lights = {{"J", 200.0}};
  const Derived r = derive(one_left_turn(), {{200.0, light_braking_distance(14.19), "light J"}}, {}, {}, lights);
  const auto through = of_kind(r.d, Kind::ThroughJunction);
  ASSERT_EQ(through.size(), 1u);
  EXPECT_NEAR(through[0].lead, 29.45, 0.05 + 1e-9);
  EXPECT_THAT(through[0].why, testing::HasSubstr("it may be braking for light J"));
  EXPECT_EQ(of_kind(r.d, Kind::NeverRunsRed).size(), 1u);
}

TEST(ExpectationRules, CloseOppositeTurnsSwitchAtTheFirstTurnsRequiredEnd) {
  // Left at A [100, 114], 40 m of b, right at B [154, 163] (docs/behaviour.md §T6.3 pattern 1, close_turns).
  test::RouteFixture f;
  f.lane("a", 100.0);
  f.internal("A", 0, 14.0, TurnDirection::Left, 13.89);
  f.lane("b", 40.0);
  f.internal("B", 0, 9.0, TurnDirection::Right, 13.89);
  f.lane("c", 200.0);
  const Derived r = derive(f);
  // B may be queued from 154 - 72.57 = 81.4, before base_link leaves A (117.7): FIRST_ACTIVE drops A
  // at its required end, which is not before A's start: A is certain only until base_link reaches
  // 100 - 0.5, the front at 100 + 3.7 - 0.5 = 103.2; stated to 102.7. From 100 - 70.77 = 29.23.
  const auto on = of_kind(r.d, Kind::BlinkerOn);
  ASSERT_EQ(on.size(), 1u);
  EXPECT_EQ(on[0].blinker, "left");
  EXPECT_NEAR(on[0].from_s, 29.8, 0.1 + 1e-9);
  EXPECT_DOUBLE_EQ(on[0].to_s, 102.7);
  EXPECT_THAT(on[0].why, testing::HasSubstr("FIRST_ACTIVE"));
  // B is certain once A's request has ended, base_link past 114: front 117.7 + 0.5 = 118.2, so a
  // lead of 154 - 118.2 - 0.5 = 35.3 m (its search alone would give 70.2).
  const auto through = of_kind(r.d, Kind::ThroughJunction);
  ASSERT_EQ(through.size(), 1u);
  EXPECT_EQ(through[0].target, "B");
  EXPECT_EQ(through[0].blinker, "right");
  EXPECT_DOUBLE_EQ(through[0].lead, 35.3);
  EXPECT_THAT(through[0].why, testing::HasSubstr("after base_link leaves the left turn at A"));
  EXPECT_EQ(never(r.d), (std::vector<std::string>{"hazard"}));
}

TEST(ExpectationRules, ATurnAfterARoundaboutExitWaitsForTheExitsEnd) {
  // kr: exit :X_0_0 [100, 108] (right), then a left turn at Y [130, 145] in another module.
  test::RouteFixture f;
  Lanelet& ring = f.lane("ring", 100.0);
  ring.roundabout_role = RoundaboutRole::Internal;
  ring.roundabout_id = "0";
  Lanelet& exit = f.internal("X", 0, 8.0, TurnDirection::Right, 13.89);
  exit.roundabout_role = RoundaboutRole::Exit;
  exit.roundabout_id = "0";
  f.lane("b", 22.0);
  f.internal("Y", 0, 15.0, TurnDirection::Left, 13.89);
  f.lane("c", 200.0);
  SectionParameters kr;
  kr.on_entry = "Left";
  kr.on_exit = "Right";
  const Derived r = derive(f, {}, {}, kr);
  // The exit: from its start (no search distance, docs/behaviour.md §T5.3) until base_link leaves it: 111.7;
  // PRIOR_WINS keeps it until the front reaches the turn (130) anyway. Stated from 100.5 to 111.2.
  const auto on = of_kind(r.d, Kind::BlinkerOn);
  ASSERT_EQ(on.size(), 1u);
  EXPECT_EQ(on[0].blinker, "right");
  EXPECT_DOUBLE_EQ(on[0].from_s, 100.5);
  EXPECT_DOUBLE_EQ(on[0].to_s, 111.2);
  // The turn: certain after the exit's desired end (111.7 + 0.5): lead 130 - 112.2 - 0.5 = 17.3.
  const auto through = of_kind(r.d, Kind::ThroughJunction);
  ASSERT_EQ(through.size(), 1u);
  EXPECT_EQ(through[0].target, "Y");
  EXPECT_DOUBLE_EQ(through[0].lead, 17.3);
}

TEST(ExpectationRules, ALaneChangeBeforeTheTurnLeavesItOnlyTheJunction) {
  // A lane change on a (its earliest start at base_link s 150): its blinker, of either side, may be
  // on from 150 - 3 x 14.19 - 0.5 = 106.9 until the front leaves a (200, + 0.5). The turn is certain
  // only after that: from 201.0 + 0.5 to 218.7 - 0.5.
  const Derived r = derive(one_left_turn(), {}, {{"a", "a_0", 150.0, 0.0, 200.0}});
  const auto on = of_kind(r.d, Kind::BlinkerOn);
  ASSERT_EQ(on.size(), 1u);
  EXPECT_DOUBLE_EQ(on[0].from_s, 201.5);
  EXPECT_DOUBLE_EQ(on[0].to_s, 218.2);
  const auto quiet = of_kind(r.d, Kind::NoBlinker);
  ASSERT_FALSE(quiet.empty());
  EXPECT_DOUBLE_EQ(quiet[0].to_s, 106.4);  // the lane change's possible start, less 0.5
  EXPECT_EQ(never(r.d), (std::vector<std::string>{"hazard"}));  // a lane change may show either side
}

TEST(ExpectationRules, NoTurnMeansNeitherBlinkerAndOneLongQuietStretch) {
  test::RouteFixture f;
  f.lane("a", 200.0);
  f.internal("J", 0, 15.0, TurnDirection::Straight, 13.89);
  f.lane("b", 300.0);
  const Derived r = derive(f);
  const auto quiet = of_kind(r.d, Kind::NoBlinker);
  ASSERT_EQ(quiet.size(), 1u);
  EXPECT_DOUBLE_EQ(quiet[0].from_s, 1.0);
  EXPECT_DOUBLE_EQ(quiet[0].to_s, 514.0);
  EXPECT_EQ(never(r.d), (std::vector<std::string>{"left", "right", "hazard"}));
}

TEST(ExpectationRules, NoEntrySignalWhereTheCountryGivesNone) {
  // de: entry None. The entry :E_0_0 [200, 208] is followed by 100 m of ring and a right exit:
  // no blinker from 30 m before the entry until base_link leaves it, unless a longer quiet stretch
  // already says so (here it does: the whole approach is quiet).
  test::RouteFixture f;
  f.lane("a", 200.0);
  Lanelet& entry = f.internal("E", 0, 8.0, TurnDirection::Right, 13.89);
  entry.roundabout_role = RoundaboutRole::Entry;
  entry.roundabout_id = "0";
  Lanelet& ring = f.lane("ring", 100.0);
  ring.roundabout_role = RoundaboutRole::Internal;
  ring.roundabout_id = "0";
  Lanelet& exit = f.internal("X", 0, 8.0, TurnDirection::Right, 13.89);
  exit.roundabout_role = RoundaboutRole::Exit;
  exit.roundabout_id = "0";
  f.lane("b", 200.0);
  SectionParameters de;
  de.on_exit = "Right";
  const Derived r = derive(f, {}, {}, de);
  const auto quiet = of_kind(r.d, Kind::NoBlinker);
  ASSERT_EQ(quiet.size(), 2u);  // no third stretch for the entry: the first covers it
  EXPECT_DOUBLE_EQ(quiet[0].from_s, 1.0);
  EXPECT_DOUBLE_EQ(quiet[0].to_s, 307.5);  // up to the exit's start (308) less the margin
  EXPECT_DOUBLE_EQ(quiet[1].from_s, 320.2);  // base_link leaves the exit: 316 + 3.7 + 0.5
  EXPECT_EQ(never(r.d), (std::vector<std::string>{"left", "hazard"}));
}

TEST(ExpectationRules, NoEntrySignalIsStatedOnItsOwnWhenTheStretchIsShort) {
  // de: a right turn at T [100, 110], 20 m, the entry :E_0_0 [130, 138], 12 m of ring, the exit
  // [150, 158]. Between the turn's end (base_link leaves it: 113.7, + 0.5) and the exit's start (150,
  // - 0.5) only 35.3 m are quiet, less than the 50 m a no_blinker stretch needs; the entry's own
  // stretch, 30 m before it until base_link leaves it (141.7), is stated: [114.2, 141.7].
  test::RouteFixture f;
  f.lane("a", 100.0);
  f.internal("T", 0, 10.0, TurnDirection::Right, 13.89);
  f.lane("b", 20.0);
  Lanelet& entry = f.internal("E", 0, 8.0, TurnDirection::Right, 13.89);
  entry.roundabout_role = RoundaboutRole::Entry;
  entry.roundabout_id = "0";
  Lanelet& ring = f.lane("ring", 12.0);
  ring.roundabout_role = RoundaboutRole::Internal;
  ring.roundabout_id = "0";
  Lanelet& exit = f.internal("X", 0, 8.0, TurnDirection::Right, 13.89);
  exit.roundabout_role = RoundaboutRole::Exit;
  exit.roundabout_id = "0";
  f.lane("c", 200.0);
  SectionParameters de;
  de.on_exit = "Right";
  const Derived r = derive(f, {}, {}, de);
  const auto quiet = of_kind(r.d, Kind::NoBlinker);
  // The 100 m approach leaves 26.9 m before the turn's possible start (too short too); after the
  // exit (base_link leaves it at 161.7, + 0.5) the rest is quiet.
  ASSERT_EQ(quiet.size(), 2u);
  EXPECT_DOUBLE_EQ(quiet[0].from_s, 162.2);
  EXPECT_DOUBLE_EQ(quiet[1].from_s, 114.2);
  EXPECT_DOUBLE_EQ(quiet[1].to_s, 141.7);
  EXPECT_THAT(quiet[1].why, testing::HasSubstr("no entry signal"));
}

TEST(ExpectationRules, RoundingIsInwards) {
  EXPECT_DOUBLE_EQ(floor_tenth(29.49), 29.4);
  EXPECT_DOUBLE_EQ(ceil_tenth(29.41), 29.5);
  EXPECT_DOUBLE_EQ(floor_tenth(29.4), 29.4);  // exact tenths stay
  EXPECT_DOUBLE_EQ(ceil_tenth(29.4), 29.4);
}

}  // namespace
}  // namespace signalsim::generate
