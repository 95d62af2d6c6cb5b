// Metrics from a synthetic route and timeline (no SUMO): sections, leads, flickers, lights, ride.
#include <gtest/gtest.h>

#include <functional>

#include "route_lanelets.hpp"
#include "report/metric_columns.hpp"
#include "report/metrics.hpp"

namespace signalsim {
namespace {

using test::lanelet;

// a_0 | left turn J (two internal lanes) | b_0 with light T (stopOffset 1) | straight K | c_0 |
// roundabout entry, ring, exit | d_0
RouteMap metrics_route() {
  std::vector<Lanelet> ls = {
      lanelet("a_0", 0, 100),
      lanelet(":J_0_0", 100, 5, TurnDirection::Left, "J"),
      lanelet(":J_1_0", 105, 10, TurnDirection::Left, "J"),
      lanelet("b_0", 115, 85),
      lanelet(":K_0_0", 200, 10, TurnDirection::Straight, "K"),
      lanelet("c_0", 210, 50),
      lanelet(":R_0_0", 260, 5, TurnDirection::Straight, "R", RoundaboutRole::Entry),
      lanelet("ring_0", 265, 20, TurnDirection::None, "", RoundaboutRole::Internal),
      lanelet(":R_1_0", 285, 7, TurnDirection::Straight, "R", RoundaboutRole::Exit),
      lanelet("d_0", 292, 108),
  };
  ls[3].traffic_light = TrafficLightLink{"T", 0};
  ls[3].stop_offset = 1.0;
  return RouteMap(std::move(ls));
}

// 1 m per 0.1 s step from s = 0 to 399; the blinker as `blinker_at(s)` says.
RunRecord metrics_record(const std::function<Blinker(double)>& blinker_at) {
  RunRecord r;
  r.base_link_to_front = 3.7;
  for (int i = 0; i < 400; ++i) {
    TimelineRow row;
    row.time = 0.1 * (i + 1);
    row.s_front = i;
    row.speed = 10.0;
    row.accel = i == 50 ? -2.0 : 0.0;
    row.blinker = blinker_at(i);
    if (i < 199) {
      row.tl_id = "T";
      row.tl_state = i >= 190 ? 'r' : 'G';
    }
    r.rows.push_back(row);
  }
  r.events = {{4.1, 40, "blinker", "none", "left", "intersection"},
              {12.0, 119, "blinker", "left", "none", "none"},
              {6.0, 50, "light", "none", "pass", "T"}};
  return r;
}

Blinker good_driver(double s) {
  if (s >= 40 && s <= 118) return Blinker::Left;   // until base_link leaves J (115 + 3.7)
  if (s >= 150 && s <= 154) return Blinker::Right;  // a 0.5 s flicker
  if (s >= 285 && s <= 295) return Blinker::Left;   // exit blinker from the exit start (jp default: Left)
  return Blinker::None;
}

TEST(Metrics, SectionsComeFromTurnGroupsAndRoundaboutRoles) {
  const auto sections = signal_sections(metrics_route(), TurnSignalParameters());
  ASSERT_EQ(sections.size(), 3u);
  EXPECT_EQ(sections[0].kind, "turn");
  EXPECT_EQ(sections[0].id, "J");
  EXPECT_EQ(sections[0].blinker, Blinker::Left);
  EXPECT_EQ(sections[0].s_start, 100.0);
  EXPECT_EQ(sections[0].s_end, 115.0);
  EXPECT_EQ(sections[0].lanelets, (std::vector<std::string>{":J_0_0", ":J_1_0"}));
  EXPECT_EQ(sections[1].kind, "roundabout_entry");
  EXPECT_EQ(sections[1].blinker, Blinker::None);  // turn_signal_roundabout_on_entry "None"
  EXPECT_EQ(sections[2].kind, "roundabout_exit");
  EXPECT_EQ(sections[2].blinker, Blinker::Left);  // turn_signal_roundabout_on_exit "Left"
}

// The entry's expected blinker names the exit the route takes as the decider does (docs/behaviour.md
// §T5.2): by a lane of the exit connection or by the normal edge the exit leads onto.
TEST(Metrics, EntryExpectsTheBlinkerItsExitTagGivesTheExitTaken) {
  const auto entry_blinker = [](const std::string& key, const std::string& value) {
    const RouteMap base = metrics_route();
    std::vector<Lanelet> ls(base.lanelets().begin(), base.lanelets().end());
    ls[6].params[key] = value;  // the entry :R_0_0; the route leaves by :R_1_0 onto d
    const auto sections = signal_sections(RouteMap(std::move(ls)), TurnSignalParameters());
    return sections.at(1).blinker;
  };
  EXPECT_EQ(entry_blinker("exit_turn_signal_left", "[:R_1_0]"), Blinker::Left);    // the exit lane
  EXPECT_EQ(entry_blinker("exit_turn_signal_left", "[d]"), Blinker::Left);         // the edge it leads onto
  EXPECT_EQ(entry_blinker("exit_turn_signal_right", "[x, d]"), Blinker::Right);
  EXPECT_EQ(entry_blinker("exit_turn_signal_left", "[d_0, ring]"), Blinker::None);  // names neither
}

TEST(Metrics, LeadTimeOnFlickersAndTheRide) {
  Scenario scenario;
  const RunMetrics m = compute_metrics(scenario, metrics_route(), metrics_record(good_driver));
  EXPECT_DOUBLE_EQ(m.max_decel, 2.0);
  EXPECT_DOUBLE_EQ(m.max_jerk, 20.0);
  EXPECT_EQ(m.blinker_events, 2);
  EXPECT_EQ(m.flickers, 1);
  EXPECT_EQ(m.missed_signals, 0);
  ASSERT_EQ(m.sections.size(), 3u);
  const SectionMetrics& turn = m.sections[0];
  EXPECT_TRUE(turn.reached);
  EXPECT_EQ(turn.missed, false);
  EXPECT_DOUBLE_EQ(*turn.lead_distance, 60.0);
  EXPECT_DOUBLE_EQ(*turn.lead_time, 6.0);
  EXPECT_DOUBLE_EQ(*turn.time_on, 7.9);
  EXPECT_EQ(turn.flickers, 0);
  const SectionMetrics& entry = m.sections[1];
  EXPECT_TRUE(entry.reached);
  EXPECT_FALSE(entry.missed.has_value());  // asks for no blinker
  EXPECT_EQ(entry.flickers, 1);            // the right flicker at s 150 lies before it
  const SectionMetrics& exit = m.sections[2];
  EXPECT_EQ(exit.missed, false);  // on from the step the front reached the exit
  EXPECT_DOUBLE_EQ(*exit.lead_distance, 0.0);
  EXPECT_DOUBLE_EQ(*exit.time_on, 1.1);
}

TEST(Metrics, LateAndMissingBlinkers) {
  Scenario scenario;
  const RunMetrics late = compute_metrics(scenario, metrics_route(), metrics_record([](double s) {
                                            return s >= 105 && s <= 118 ? Blinker::Left : Blinker::None;
                                          }));
  EXPECT_EQ(late.sections[0].missed, true);
  EXPECT_DOUBLE_EQ(*late.sections[0].lead_distance, -5.0);
  EXPECT_DOUBLE_EQ(*late.sections[0].lead_time, -0.5);
  EXPECT_DOUBLE_EQ(*late.sections[0].time_on, 1.4);
  EXPECT_EQ(late.missed_signals, 2);  // the turn and the exit

  const RunMetrics none = compute_metrics(scenario, metrics_route(), metrics_record([](double) { return Blinker::None; }));
  EXPECT_EQ(none.sections[0].missed, true);
  EXPECT_FALSE(none.sections[0].lead_distance.has_value());
  EXPECT_DOUBLE_EQ(*none.sections[0].time_on, 0.0);
  EXPECT_EQ(none.flickers, 0);

  RunRecord short_run = metrics_record(good_driver);
  short_run.rows.resize(200);  // the run ends before the roundabout
  const RunMetrics cut = compute_metrics(scenario, metrics_route(), short_run);
  EXPECT_FALSE(cut.sections[2].reached);
  EXPECT_FALSE(cut.sections[2].missed.has_value());
}

TEST(Metrics, LightsStopLineStateAndRedLightViolation) {
  Scenario scenario;
  const RunMetrics m = compute_metrics(scenario, metrics_route(), metrics_record(good_driver));
  ASSERT_EQ(m.lights.size(), 1u);
  EXPECT_EQ(m.lights[0].id, "T");
  EXPECT_DOUBLE_EQ(m.lights[0].stop_line_s, 199.0);
  EXPECT_TRUE(m.lights[0].reached);
  EXPECT_EQ(m.lights[0].state_at_line, "r");
  EXPECT_EQ(m.lights[0].red_light_violation, true);
  EXPECT_FALSE(m.lights[0].stop_position_error.has_value());
  EXPECT_EQ(m.red_light_violations, 1);

  // A stop 2 m before the stop point (an emergency stop in the dilemma zone), then green.
  RunRecord stop = metrics_record(good_driver);
  for (auto& row : stop.rows) {
    if (row.s_front >= 190 && row.s_front < 199) row.tl_state = row.s_front < 198 ? 'r' : 'G';
    if (row.s_front >= 150 && row.s_front < 199) {
      row.tl_decision = row.s_front < 160 ? JudgeDecision::Pass
                        : row.s_front < 198 ? JudgeDecision::EmergencyStop
                                            : JudgeDecision::Pass;
      row.zone = row.s_front == 160 ? JudgeZone::DilemmaZone : row.s_front > 160 && row.s_front < 198 ? JudgeZone::Slow
                                                                                                       : JudgeZone::None;
    }
  }
  LightStop light_stop;
  light_stop.tl_id = "T";
  light_stop.time = 19.8;
  light_stop.stop_s = 199.0;
  light_stop.rest_s = 197.0;
  light_stop.error = -2.0;
  light_stop.decision = JudgeDecision::EmergencyStop;
  light_stop.worst_level = StopLevel::Emergency;
  stop.stops.push_back(light_stop);
  const RunMetrics s = compute_metrics(scenario, metrics_route(), stop);
  EXPECT_DOUBLE_EQ(*s.lights[0].stop_position_error, -2.0);
  EXPECT_EQ(s.lights[0].red_light_violation, false);
  EXPECT_EQ(s.lights[0].decision, "emergency_stop");
  EXPECT_EQ(s.lights[0].zone, "dilemma_zone");
  EXPECT_EQ(s.lights[0].emergency_stop, true);
  EXPECT_FALSE(m.lights[0].decision.has_value());  // the first run had no judge
}

TEST(Metrics, JsonHasNullsForWhatDoesNotApply) {
  Scenario scenario;
  const auto j = metrics_json(scenario, metrics_route(), metrics_record(good_driver));
  EXPECT_EQ(j["sections"][1]["lead_distance"], nullptr);
  EXPECT_EQ(j["sections"][0]["lead_distance"], 60.0);
  EXPECT_EQ(j["lights"][0]["decision"], nullptr);
  EXPECT_EQ(j.dump().find("-0.0"), std::string::npos);
  const auto flat = flatten_metrics(j);
  EXPECT_NE(std::find(flat.begin(), flat.end(), std::make_pair(std::string("turn1.lead_distance"), std::string("60.0"))),
            flat.end());
}

}  // namespace
}  // namespace signalsim
