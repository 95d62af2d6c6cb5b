// The table of `signalsim compare` from a synthetic route and two synthetic runs (no SUMO): items in
// route order, one row per item and driver with that driver's metrics, error rows, notes, the CSV
// and the screen summary.
#include <gtest/gtest.h>

#include <functional>

#include "route_lanelets.hpp"
#include "batch/comparison.hpp"
#include "core/csv.hpp"
#include "report/metrics.hpp"

namespace signalsim {
namespace {

using test::lanelet;

// a_0 with light T at its end | left turn J | b_0 | roundabout entry R, ring, exit R | d_0
RouteMap comparison_route() {
  std::vector<Lanelet> ls = {
      lanelet("a_0", 0, 100),
      lanelet(":J_0_0", 100, 15, TurnDirection::Left, "J"),
      lanelet("b_0", 115, 145),
      lanelet(":R_0_0", 260, 5, TurnDirection::Straight, "R", RoundaboutRole::Entry),
      lanelet("ring_0", 265, 20, TurnDirection::None, "", RoundaboutRole::Internal),
      lanelet(":R_1_0", 285, 7, TurnDirection::Straight, "R", RoundaboutRole::Exit),
      lanelet("d_0", 292, 108),
  };
  ls[0].traffic_light = TrafficLightLink{"T", 0};
  return RouteMap(std::move(ls));
}

// 1 m per 0.1 s step from s = 0 to 399, the blinker as `blinker_at(s)` says, light T green.
RunRecord comparison_record(const std::function<Blinker(double)>& blinker_at) {
  RunRecord r;
  r.base_link_to_front = 3.7;
  for (int i = 0; i < 400; ++i) {
    TimelineRow row;
    row.time = 0.1 * (i + 1);
    row.s_front = i;
    row.speed = 10.0;
    row.blinker = blinker_at(i);
    if (i < 102) {
      row.tl_id = "T";
      row.tl_state = 'G';
    }
    r.rows.push_back(row);
  }
  r.arrived = true;
  return r;
}

DriverRun finished(const std::string& driver, const RunRecord& rec, const std::string& status = "passed") {
  Scenario scenario;
  scenario.step_length = 0.1;
  DriverRun run;
  run.driver = driver;
  run.status = status;
  run.run_dir = "runs/0000-x-" + driver;
  run.summary["status"] = status;
  run.summary["counts"] = {{"off_route_steps", rec.off_route_steps}};
  run.summary["metrics"] = metrics_json(scenario, comparison_route(), rec);
  run.summary["expectations"] = nlohmann::ordered_json::array({{{"passed", true}}, {{"passed", false}}});
  nlohmann::ordered_json off_plan = nlohmann::ordered_json::array();
  for (const OffPlanStretch& o : rec.off_plan)
    off_plan.push_back({{"lane", o.lane}, {"planned_lane", o.planned_lane}, {"s_from", o.s_from}, {"s_to", o.s_to}});
  run.summary["off_plan"] = off_plan;
  return run;
}

// signalsim: left from 40 through J, left on the exit from 280. SUMO: left from 3 (97 m before J),
// right on the entry and on the exit (a left exit is asked for: missed), a lane change on a_1.
ScenarioComparison both() {
  ScenarioComparison sc;
  sc.scenario = "synthetic";
  sc.base_link_to_front = 3.7;
  sc.items = compared_items(comparison_route(), TurnSignalParameters());
  sc.runs.push_back(finished("signalsim", comparison_record([](double s) {
    return (s >= 40 && s <= 118) || (s >= 280 && s <= 295) ? Blinker::Left : Blinker::None;
  })));
  RunRecord sumo = comparison_record([](double s) {
    if (s >= 3 && s < 115) return Blinker::Left;
    if ((s >= 240 && s < 265) || (s >= 270 && s < 292)) return Blinker::Right;
    return Blinker::None;
  });
  sumo.off_plan.push_back({"a_1", "a_0", 20.0, 80.0, 60});
  sc.runs.push_back(finished("sumo", sumo, "failed"));
  return sc;
}

std::map<std::string, std::string> cells(const std::vector<std::string>& row) {
  std::map<std::string, std::string> out;
  for (std::size_t i = 0; i < row.size(); ++i) out[comparison_columns()[i]] = row[i];
  return out;
}

TEST(Comparison, ItemsInRouteOrderTheStopLineBeforeTheTurnAtTheSameS) {
  const auto items = compared_items(comparison_route(), TurnSignalParameters());
  ASSERT_EQ(items.size(), 4u);
  EXPECT_EQ(items[0].name, "light1");
  EXPECT_EQ(items[0].id, "T");
  EXPECT_DOUBLE_EQ(items[0].s, 100.0);
  EXPECT_EQ(items[1].name, "turn1");
  EXPECT_EQ(items[1].id, "J");
  EXPECT_DOUBLE_EQ(items[1].s, 100.0);
  EXPECT_EQ(items[1].blinker, Blinker::Left);
  EXPECT_EQ(items[2].name, "roundabout_entry1");
  EXPECT_EQ(items[2].blinker, Blinker::None);
  EXPECT_EQ(items[3].name, "roundabout_exit1");
  EXPECT_EQ(items[3].blinker, Blinker::Left);  // the schema default turn_signal_roundabout_on_exit
}

TEST(Comparison, OneRowPerItemAndDriverWithThatDriversMetrics) {
  const auto rows = comparison_rows({both()});
  ASSERT_EQ(rows.size(), 8u);
  auto light_sumo = cells(rows[1]), turn_sig = cells(rows[2]), turn_sumo = cells(rows[3]);
  auto entry_sumo = cells(rows[5]), exit_sig = cells(rows[6]), exit_sumo = cells(rows[7]);
  EXPECT_EQ(cells(rows[0])["section"], "light1");
  EXPECT_EQ(cells(rows[0])["driver"], "signalsim");
  EXPECT_EQ(light_sumo["driver"], "sumo");
  EXPECT_EQ(light_sumo["state_at_line"], "G");
  EXPECT_EQ(light_sumo["red_light_violation"], "false");
  EXPECT_EQ(turn_sig["s"], "100.0");
  EXPECT_EQ(turn_sig["blinker"], "left");
  EXPECT_EQ(turn_sig["lead_distance"], "60.0");
  EXPECT_EQ(turn_sig["missed"], "false");
  EXPECT_EQ(turn_sig["blinker_at_start"], "left");
  EXPECT_EQ(turn_sig["expectations"], "1/2");
  EXPECT_EQ(turn_sig["notes"], "");
  EXPECT_EQ(turn_sumo["lead_distance"], "97.0");
  EXPECT_EQ(turn_sumo["status"], "failed");
  // The lane change on a_1 happened on the turn's approach: noted there, and on the light's.
  EXPECT_EQ(turn_sumo["notes"], "on a_1 (planned a_0) at s 20.0-80.0");
  EXPECT_EQ(light_sumo["notes"], "on a_1 (planned a_0) at s 20.0-80.0");
  EXPECT_EQ(entry_sumo["blinker"], "none");
  EXPECT_EQ(entry_sumo["blinker_at_start"], "right");
  EXPECT_EQ(entry_sumo["lead_distance"], "");
  EXPECT_EQ(entry_sumo["notes"], "") << "the lane change is before the previous section's end";
  EXPECT_EQ(exit_sig["missed"], "false");
  EXPECT_EQ(exit_sig["lead_distance"], "5.0");
  EXPECT_EQ(exit_sumo["missed"], "true");
  EXPECT_EQ(exit_sumo["blinker_at_start"], "right");
  EXPECT_EQ(exit_sumo["time_on"], "0.0");
  EXPECT_EQ(exit_sumo["run_dir"], "runs/0000-x-sumo");
}

TEST(Comparison, ARunThatDidNotFinishGivesAnErrorRowForEveryItem) {
  ScenarioComparison sc = both();
  sc.runs[1] = DriverRun{"sumo", "error", "SUMO could not load the simulation", "runs/0000-x-sumo", {}};
  const auto rows = comparison_rows({sc});
  ASSERT_EQ(rows.size(), 8u);
  for (std::size_t i = 1; i < rows.size(); i += 2) {
    auto r = cells(rows[i]);
    EXPECT_EQ(r["driver"], "sumo");
    EXPECT_EQ(r["status"], "error");
    EXPECT_EQ(r["error"], "SUMO could not load the simulation");
    EXPECT_EQ(r["lead_distance"], "");
    EXPECT_FALSE(r["section"].empty());
  }
  EXPECT_EQ(cells(rows[2])["lead_distance"], "60.0") << "the other driver's rows stand";
  // Neither run finished and the route has no items: still one row per driver.
  ScenarioComparison empty;
  empty.scenario = "empty";
  empty.runs = {DriverRun{"signalsim", "error", "timed out", "", {}},
                DriverRun{"sumo", "passed", "", "", {{"expectations", nlohmann::ordered_json::array()}}}};
  const auto none = comparison_rows({empty});
  ASSERT_EQ(none.size(), 2u);
  EXPECT_EQ(cells(none[0])["status"], "error");
  EXPECT_EQ(cells(none[1])["notes"], "no sections or lights on the route");
}

TEST(Comparison, MetricsThatDoNotMatchTheRouteAreAnErrorNotAGap) {
  ScenarioComparison sc = both();
  sc.runs[1].summary["metrics"]["sections"] = nlohmann::ordered_json::array();
  const auto rows = comparison_rows({sc});
  auto turn_sumo = cells(rows[3]);
  EXPECT_EQ(turn_sumo["status"], "error");
  EXPECT_EQ(turn_sumo["error"], "the run's metrics have no turn1 at J");
}

TEST(Comparison, CsvAndScreen) {
  ScenarioComparison sc = both();
  sc.runs[1].summary["off_plan"][0]["lane"] = "a,1";  // quoted in the CSV
  const std::string csv = comparison_csv({sc});
  const auto table = parse_csv(csv);
  ASSERT_EQ(table.size(), 9u);  // header, 8 rows
  EXPECT_EQ(table[0], comparison_columns());
  EXPECT_NE(csv.find("\"on a,1 (planned a_0) at s 20.0-80.0\""), std::string::npos);
  EXPECT_EQ(csv, comparison_csv({sc}));
  const std::string screen = comparison_screen({both()});
  EXPECT_NE(screen.find("turn1"), std::string::npos);
  EXPECT_NE(screen.find("lead 60.0 m 6.0 s"), std::string::npos) << screen;
  EXPECT_NE(screen.find("lead 97.0 m 9.7 s *"), std::string::npos) << screen;
  EXPECT_NE(screen.find("missed (right on)"), std::string::npos) << screen;
  EXPECT_NE(screen.find("right on"), std::string::npos) << screen;
  EXPECT_NE(screen.find("* SUMO drove off the planned lanes"), std::string::npos) << screen;
  EXPECT_EQ(std::count(screen.begin(), screen.end(), '\n'), 6) << screen;  // header, 4 items, the footnote
  const std::string short_screen = comparison_screen({both()}, 2);
  EXPECT_NE(short_screen.find("... 2 more in comparison.csv"), std::string::npos) << short_screen;
}

}  // namespace
}  // namespace signalsim
