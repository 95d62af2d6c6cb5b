// A sweep file's plot: is checked before any run: its x and y name swept keys, its metric a numeric
// results.csv column (the names flatten_metrics gives), which some run's route can produce.
#include <gtest/gtest.h>

#include <string>

#include "batch/run_list.hpp"
#include "batch/sweep_file.hpp"
#include "batch/sweep_check.hpp"
#include "batch/sweep_plot_check.hpp"
#include "report/metric_columns.hpp"
#include "report/metrics.hpp"
#include "scenario/input_error.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::data_dir;
using test::error_of;
using test::TempDir;


bool is_number(const std::string& text) {
  try {
    std::size_t used = 0;
    (void)std::stod(text, &used);
    return used == text.size();
  } catch (const std::exception&) {
    return false;
  }
}

TEST(SweepPlot, TheMetricMustBeANumericColumnOfWhatFlattenMetricsWrites) {
  // One section of each kind and one light with every field set: the columns results.csv can have.
  RunMetrics m;
  for (const char* kind : {"turn", "roundabout_entry", "roundabout_exit"}) {
    SectionMetrics s;
    s.section.kind = kind;
    s.section.id = "J";
    s.section.blinker = Blinker::Left;
    s.reached = true;
    s.lead_distance = 12.5;
    s.lead_time = 1.5;
    s.time_on = 4.0;
    s.flickers = 1;
    s.missed = false;
    m.sections.push_back(s);
  }
  LightMetrics light;
  light.id = "C";
  light.reached = true;
  light.state_at_line = "G";
  light.red_light_violation = false;
  light.stop_position_error = 0.02;
  light.decision = "stop";
  light.zone = "stoppable";
  light.emergency_stop = false;
  m.lights.push_back(light);
  const auto cells = flatten_metrics(to_json(m));
  ASSERT_EQ(cells.size(), 9u + 3u * 7u + 7u);  // run-level: 9 (the ride 4, then 5 counts)
  // Accepted exactly when the cell holds a number, or is a light's true/false outcome (shown as the
  // share of runs where it is true).
  for (const auto& [column, text] : cells) {
    const bool outcome = column == "light1.red_light_violation" || column == "light1.emergency_stop";
    EXPECT_EQ(plot_metric_problem(column).empty(), is_number(text) || outcome)
        << column << " = " << text << ": " << plot_metric_problem(column);
  }
  for (const char* column : {"expectations_passed", "expectations_total", "wall_time", "turn12.lead_distance",
                             "lane_change1.lead_time", "avoidance2.lead_distance", "pull_out1.time_on",
                             "pull_over1.flickers"})
    EXPECT_EQ(plot_metric_problem(column), "") << column;
  for (const char* column : {"status", "run", "turn0.lead_distance", "turn01.lead_distance", ".lead_distance",
                             "lane_change1.prepare", "turn1.lead"})
    EXPECT_NE(plot_metric_problem(column), "") << column;
  EXPECT_EQ(plot_metric_problem("turn1.blinker"),
            "'turn1.blinker' holds text or true/false, not numbers: a heat map cannot show it (numeric fields of "
            "turn<n>: lead_distance, lead_time, time_on, flickers)");
}

TEST(SweepPlot, BadPlotIsRefusedWhenTheFileIsRead) {
  TempDir dir;
  const auto load = [&](const std::string& text) {
    const std::string path = dir.write("bad.yaml", "scenarios: " + data_dir() + "/turns.yaml\n" + text);
    return error_of([&] { load_sweep(path); });
  };
  const std::string at = dir.path() + "/bad.yaml:";
  const std::string grid = "grid:\n  country: [jp, de]\n  seed: [1, 2]\n";  // lines 2-4
  EXPECT_EQ(load(grid + "plot: {metric: turn1.lead_time, x: seed, y: country}\n"), "");
  EXPECT_EQ(load(grid + "plot: {x: scenario}\n"), "");
  EXPECT_EQ(load(grid + "plot:\n  metric: turn1.lead_time\n  x: ego.max_speed\n"),
            at + "7: plot.x: 'ego.max_speed' is not a swept key (swept: country, seed; or scenario)");
  EXPECT_EQ(load(grid + "plot:\n  y: contry\n"), at + "6: plot.y: 'contry' is not a swept key (swept: country, seed; or scenario)");
  EXPECT_EQ(load("plot: {x: seed}\n"), at + "2: plot.x: 'seed' is not a swept key (nothing is swept: only scenario)");
  EXPECT_EQ(load(grid + "plot: {x: seed, y: seed}\n"), at + "5: plot.y: 'seed' is the x axis too: x and y must differ");
  EXPECT_EQ(load(grid + "plot: {y: country}\n"),
            at + "5: plot.y: 'country' is the x axis too (x defaults to the first swept key; give plot.x): x and y "
                 "must differ");
  EXPECT_EQ(load(grid + "plot:\n  x: seed\n  metric: turn1.missed\n"),
            at + "7: plot.metric: 'turn1.missed' holds text or true/false, not numbers: a heat map cannot show it "
                 "(numeric fields of turn<n>: lead_distance, lead_time, time_on, flickers)");
  EXPECT_EQ(load("plot: {metric: light1.zne}\n"),
            at + "2: plot.metric: 'zne' in 'light1.zne' is not a field of light<n> (numeric fields: stop_position_error, "
                 "red_light_violation, emergency_stop)");
  EXPECT_EQ(load("plot: {metric: exit1.lead_distance}\n"),
            at + "2: plot.metric: 'exit' in 'exit1.lead_distance' is not a section kind or light (turn, "
                 "roundabout_entry, roundabout_exit, lane_change, avoidance, pull_out, pull_over, light)");
  EXPECT_EQ(load("plot: {metric: lead_distance}\n").rfind(at + "2: plot.metric: 'lead_distance' is not a results.csv metric column (numeric columns: max_decel, ", 0), 0u);
}

// plot: may be a list of mappings: one picture each, every one checked at its own line.
TEST(SweepPlot, APlotListGivesOnePictureEach) {
  TempDir dir;
  const std::string grid = "grid:\n  country: [jp, de]\n  seed: [1, 2]\n";  // lines 2-4
  const std::string path = dir.write("s.yaml", "scenarios: " + data_dir() + "/turns.yaml\n" + grid +
                                                   "plot:\n"
                                                   "  - {metric: red_light_violations, x: seed, y: country}\n"
                                                   "  - {metric: light1.emergency_stop, x: country, y: seed}\n");
  const Sweep sweep = load_sweep(path);
  ASSERT_EQ(sweep.plots.size(), 2u);
  EXPECT_EQ(sweep.plot.metric, "red_light_violations");
  EXPECT_EQ(sweep.plots[1].metric, "light1.emergency_stop");
  EXPECT_EQ(sweep.plots[1].x, "country");
  const auto load = [&](const std::string& text) {
    const std::string bad = dir.write("bad.yaml", "scenarios: " + data_dir() + "/turns.yaml\n" + text);
    return error_of([&] { load_sweep(bad); });
  };
  const std::string at = dir.path() + "/bad.yaml:";
  EXPECT_EQ(load(grid + "plot:\n  - {x: seed}\n  - {x: seed, y: seed}\n"),
            at + "7: plot.y: 'seed' is the x axis too: x and y must differ");
  EXPECT_EQ(load(grid + "plot: []\n"), at + "5: key 'plot': an empty list draws nothing");
}

// Maneuver sections belong to each run's scenario, not to its route: a run with the same route but
// no lane change must not hide another run's lane change.
TEST(SweepPlot, ManeuverSectionsAreCountedPerRunNotPerRoute) {
  TempDir dir;
  const std::string bundled = std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/";
  const auto check = [&](const std::string& metric) {
    const std::string path =
        dir.write("s.yaml", "scenarios: [" + bundled + "intersection_straight.yaml, " + bundled +
                                "lane_change_right.yaml]\ngrid: {seed: [1, 2]}\nplot:\n  metric: " + metric + "\n");
    return error_of([&] {
      const Sweep sweep = load_sweep(path);
      const SweepRuns runs(sweep);
      const SweepCheck checked(runs);
      check_sweep_plot(runs);
    });
  };
  EXPECT_EQ(check("lane_change1.lead_time"), "");  // both run in_S -> out_N; only the second changes lanes
  EXPECT_NE(check("lane_change2.lead_time").find("no run's route has a lane_change2"), std::string::npos);
}

TEST(SweepPlot, AMetricNoRunsRouteHasIsRefusedBeforeAnyRun) {
  TempDir dir;
  const auto check = [&](const std::string& scenarios, const std::string& metric) {
    const std::string path = dir.write("s.yaml", "scenarios: [" + scenarios + "]\ngrid: {seed: [1, 2]}\nplot:\n  metric: " + metric + "\n");
    return error_of([&] {
      const Sweep sweep = load_sweep(path);
      const SweepRuns runs(sweep);
      const SweepCheck checked(runs);
      check_sweep_plot(runs);
    });
  };
  const std::string turns = data_dir() + "/turns.yaml", roundabout = data_dir() + "/roundabout_exit.yaml";
  const std::string at = dir.path() + "/s.yaml:4: plot.metric: ";
  // close_turns: a left turn at A and a right turn at B, no roundabout, no light.
  EXPECT_EQ(check(turns, "turn2.lead_distance"), "");
  EXPECT_EQ(check(turns, "max_decel"), "");
  EXPECT_EQ(check(turns, "turn3.lead_distance"),
            at + "no run's route has a turn3, so no run can give 'turn3.lead_distance' (the most any route has: 2 turn, "
                 "0 light)");
  EXPECT_EQ(check(turns, "roundabout_exit1.lead_distance").rfind(at + "no run's route has a roundabout_exit1", 0), 0u);
  EXPECT_EQ(check(turns, "light1.stop_position_error").rfind(at + "no run's route has a light1", 0), 0u);
  // One scenario that has it is enough (signalsim-plot draws the scenarios that have the metric).
  EXPECT_EQ(check(turns + ", " + roundabout, "roundabout_exit1.lead_distance"), "");
}

}  // namespace
}  // namespace signalsim
