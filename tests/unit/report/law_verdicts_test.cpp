// The law's verdicts (report/law_verdicts.hpp) on hand-made records: a 200 m approach, a 15 m left turn
// through junction J, 300 m beyond, the ego at 10 m/s with base_link 3.7 m behind the front and a step of
// 0.1 s (one row a metre). The turn's search is 3 s x 10 m/s + 30 m = 60 m: the reference's left blinker
// is on once the front is past s 140 until base_link leaves the turn (front past 218.7). Each rule passes
// for that blinker and fails for a blinker that breaks it.
#include "report/law_verdicts.hpp"

#include <functional>
#include <set>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "route_fixture.hpp"

namespace signalsim {
namespace {

constexpr double kB2f = 3.7;

RouteMap left_turn_route(bool light = false) {
  test::RouteFixture f;
  Lanelet& a = f.lane("a", 200.0);
  if (light) a.traffic_light = TrafficLightLink{"L", 0};
  f.internal("J", 0, 15.0, TurnDirection::Left, 13.89);
  f.lane("b", 300.0);
  return f.build();
}

// One row a metre from s 0 to 515 at 10 m/s, the blinker as `blinker(s)` says.
RunRecord drive(const std::function<Blinker(double)>& blinker, double speed = 10.0) {
  RunRecord r;
  r.base_link_to_front = kB2f;
  r.arrived = true;
  for (int i = 0; i <= 515; ++i) {
    TimelineRow row;
    row.time = 0.1 * i;
    row.s_front = i;
    row.speed = speed;
    row.blinker = blinker(i);
    r.rows.push_back(row);
  }
  return r;
}

Blinker reference(double s) { return s > 140.0 && s <= 218.7 ? Blinker::Left : Blinker::None; }

using Failed = std::set<std::pair<std::string, std::string>>;  // (id, rule)

Failed failed(const RunRecord& record, bool light = false) {
  const Scenario scenario;
  Failed out;
  for (const LawVerdict& v : law_verdicts(scenario, left_turn_route(light), record))
    if (!v.passed) out.insert({v.id, v.rule});
  return out;
}

TEST(LawVerdicts, TheReferenceBlinkerPassesEveryRule) {
  const Scenario scenario;
  const std::vector<LawVerdict> verdicts = law_verdicts(scenario, left_turn_route(), drive(reference));
  std::set<std::pair<std::string, std::string>> rules;
  for (const LawVerdict& v : verdicts) {
    EXPECT_TRUE(v.passed) << v.id << " " << v.rule << ": " << v.detail;
    rules.insert({v.section + " " + v.id, v.rule});
  }
  const std::set<std::pair<std::string, std::string>> expected = {
      {"turn J", "lead"},   {"turn J", "through"}, {"turn J", "wrong_side"}, {"turn J", "flicker"},
      {"route start", "off"}, {"turn J", "off"},   {"route ", "never_right"}, {"route ", "never_hazard"}};
  EXPECT_EQ(rules, expected);
  EXPECT_EQ(law_failed(verdicts), 0);
}

TEST(LawVerdicts, ALateBlinkerFailsTheLead) {
  EXPECT_EQ(failed(drive([](double s) { return s > 160.0 && s <= 218.7 ? Blinker::Left : Blinker::None; })),
            (Failed{{"J", "lead"}}));
}

TEST(LawVerdicts, TheWrongSideFailsTheSectionAndTheSideNoSectionAsksFor) {
  EXPECT_EQ(failed(drive([](double s) { return reference(s) == Blinker::Left ? Blinker::Right : Blinker::None; })),
            (Failed{{"J", "lead"}, {"J", "through"}, {"J", "wrong_side"}, {"", "never_right"}}));
}

TEST(LawVerdicts, OffAndOnAgainInsideTheSectionIsAFlicker) {
  EXPECT_EQ(failed(drive([](double s) { return s >= 205.0 && s <= 206.0 ? Blinker::None : reference(s); })),
            (Failed{{"J", "through"}, {"J", "flicker"}}));
}

TEST(LawVerdicts, ABlinkerLeftOnAfterTheDesiredEndFailsOff) {
  EXPECT_EQ(failed(drive([](double s) { return s > 140.0 && s <= 260.0 ? Blinker::Left : Blinker::None; })),
            (Failed{{"J", "off"}}));
}

TEST(LawVerdicts, HazardLightsFailNeverHazard) {
  EXPECT_EQ(failed(drive([](double s) { return s > 20.0 && s < 40.0 ? Blinker::Hazard : reference(s); })),
            (Failed{{"start", "off"}, {"", "never_hazard"}}));
}

// The light L at the end of a: the judge's input red from s 100 on (at 10 m/s the jerk-limited judge line
// is about 25 m), crossed at s 200.
RunRecord red_crossing(const std::string& observed) {
  RunRecord r = drive(reference);
  for (TimelineRow& row : r.rows) {
    if (row.s_front >= 200.0) break;
    row.tl_id = "L";
    row.tl_state = 'r';
    if (row.s_front >= 100.0) row.tl_observed = observed;
  }
  r.red_violations.push_back({"L", 20.0, 200.0});
  return r;
}

TEST(LawVerdicts, CrossingARedTheJudgeWasGivenWhileItCouldStopFails) {
  EXPECT_EQ(failed(red_crossing("red"), true), (Failed{{"L", "stop"}}));
  EXPECT_EQ(failed(red_crossing("amber"), true), (Failed{{"L", "stop"}}));
}

TEST(LawVerdicts, CrossingARedTheJudgeNeverSawPasses) {
  EXPECT_EQ(failed(red_crossing(""), true), Failed{});  // nothing received: pass (is_simulation, §L1.3)
}

TEST(LawVerdicts, ARedSeenTooLateToStopPasses) {
  RunRecord r = red_crossing("");
  for (TimelineRow& row : r.rows)
    if (row.s_front >= 190.0 && row.s_front < 200.0) row.tl_observed = "red";  // 10 m: within the judge line
  EXPECT_EQ(failed(r, true), Failed{});
}

TEST(LawVerdicts, EachApproachOfALightIsJudgedOnItsOwnRows) {
  // One light L controls two junctions of the route: the end of a (line 200) and the end of b (line
  // 515). Before 200 the rows show L red for b's line (the judge's stop point 515): a's own link is
  // green, crossing 200 breaks no rule; b's approach is judged too.
  test::RouteFixture f;
  f.lane("a", 200.0).traffic_light = TrafficLightLink{"L", 0};
  f.internal("J", 0, 15.0, TurnDirection::Left, 13.89);
  f.lane("b", 300.0).traffic_light = TrafficLightLink{"L", 1};
  const RouteMap route = f.build();
  RunRecord r = drive(reference);
  for (TimelineRow& row : r.rows) {
    row.tl_id = "L";
    row.tl_observed = row.s_front < 200.0 ? "red" : "green";
    row.stop_distance = 515.0 - row.s_front;  // the stop point of b's line (stop_margin 0)
  }
  const Scenario scenario;
  int judged = 0;
  for (const LawVerdict& v : law_verdicts(scenario, route, r))
    if (v.section == "light") {
      ++judged;
      EXPECT_TRUE(v.passed) << v.detail;
    }
  EXPECT_EQ(judged, 2) << "both lines of L";
}

// A lane change to the right on b, approved with the front at s 300, its lateral motion (base_link)
// from 320 to 360: the right blinker is due from the approval until base_link ends the motion.
RunRecord lane_change(double on_from) {
  RunRecord r = drive([&](double s) {
    if (s >= on_from && s <= 360.0 + kB2f) return Blinker::Right;
    return reference(s);
  });
  r.maneuver_lines.push_back({"lane_change", "b", 320.0, 360.0, Blinker::Right});
  LaneChangeRecord lc;
  lc.edge = "b";
  lc.phase = "done";
  lc.approval_s_base = 300.0 - kB2f;
  lc.start = 320.0;
  lc.end = 360.0;
  r.lane_changes.push_back(lc);
  return r;
}

TEST(LawVerdicts, ALaneChangeBlinkerIsDueFromItsApproval) {
  EXPECT_EQ(failed(lane_change(290.0)), Failed{});
  EXPECT_EQ(failed(lane_change(310.0)), (Failed{{"b", "on"}}));
}

TEST(LawVerdicts, ARunSumoDroveHasNoVerdicts) {
  RunRecord r = drive(reference);
  r.driver = Driver::Sumo;
  const Scenario scenario;
  EXPECT_TRUE(law_verdicts(scenario, left_turn_route(), r).empty());
  EXPECT_TRUE(law_json(r, {}).is_null());
}

}  // namespace
}  // namespace signalsim
