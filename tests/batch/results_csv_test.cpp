// results.csv: fixed columns around the metrics, a canonical metric order, quoting, reading back.
#include <gtest/gtest.h>

#include "batch/results_table.hpp"
#include "report/atomic_file.hpp"
#include "report/metric_columns.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

ResultRow row(std::size_t run, std::map<std::string, std::string> cells) { return {run, std::move(cells)}; }

TEST(ResultsCsv, ColumnsAreFixedAroundCanonicallyOrderedMetrics) {
  ResultRows rows;
  rows[1] = row(1, {{"scenario", "b"}, {"light1.id", "C"}, {"turn1.lead_distance", "70"}, {"max_jerk", "10"},
                    {"status", "passed"}, {"wall_time", "0.10"}});
  rows[0] = row(0, {{"scenario", "a"}, {"roundabout_exit1.missed", "true"}, {"turn2.id", "B"}, {"turn10.id", "Z"},
                    {"max_decel", "1"}, {"turn1.id", "A"}, {"status", "error"}, {"error", "boom"}});
  const auto columns = result_columns({"country"}, rows);
  const std::vector<std::string> expected = {
      "run", "scenario", "file", "country", "status", "expectations_passed", "expectations_total",
      "failed_expectations", "law_failed", "run_dir", "max_decel", "max_jerk", "turn1.id", "turn1.lead_distance", "turn2.id",
      "turn10.id", "roundabout_exit1.missed", "light1.id", "wall_time", "error"};
  EXPECT_EQ(columns, expected);
}

TEST(ResultsCsv, ASweptKeyNamedLikeAMetricNeverHidesTheMetric) {
  // The judge's max_jerk parameter swept: its column is swept.max_jerk, the ride's max_jerk its own.
  EXPECT_EQ(swept_column("max_jerk"), "swept.max_jerk");
  EXPECT_EQ(swept_column("p95_decel"), "swept.p95_decel");
  EXPECT_EQ(swept_column("yellow_lamp_period"), "yellow_lamp_period");
  EXPECT_EQ(swept_column("decider"), "decider") << "a swept decider shares the SUT's name column";
  ResultRows rows;
  rows[0] = row(0, {{"scenario", "a"}, {swept_column("max_jerk"), "-5"}, {"max_jerk", "1"}, {"status", "passed"}});
  const std::string text = results_csv({"max_jerk"}, rows);
  EXPECT_EQ(text, "run,scenario,file,swept.max_jerk,status,expectations_passed,expectations_total,"
                  "failed_expectations,law_failed,run_dir,max_jerk,wall_time,error\n"
                  "0,a,,-5,passed,,,,,,1,,\n");
}

TEST(ResultsCsv, QuotesWhatNeedsQuotingAndReadsItBack) {
  test::TempDir dir;
  ResultRows rows;
  rows[2] = row(2, {{"scenario", "x"}, {"file", "a,b.yaml"}, {"status", "error"},
                    {"error", "said \"no\", twice\nsecond line"}});
  rows[0] = row(0, {{"scenario", "y"}, {"file", "y.yaml"}, {"status", "passed"}, {"turn1.lead_distance", "71.5"}});
  const std::string text = results_csv({}, rows);
  EXPECT_EQ(text.substr(0, text.find('\n')),
            "run,scenario,file,status,expectations_passed,expectations_total,failed_expectations,law_failed,run_dir,"
            "turn1.lead_distance,wall_time,error");
  EXPECT_NE(text.find("\"a,b.yaml\""), std::string::npos);
  EXPECT_NE(text.find("\"said \"\"no\"\", twice\nsecond line\""), std::string::npos);
  const std::string path = dir.path() + "/results.csv";
  write_file_atomically(path, text);
  const ResultRows back = read_results_csv(path);
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back.at(2).cells, rows[2].cells);
  EXPECT_EQ(back.at(0).cells, rows[0].cells);
  EXPECT_EQ(results_csv({}, back), text);  // rows are ordered by run, whatever order they came in
}

TEST(ResultsCsv, RowMatchesItsRunOnly) {
  RunSpec run;
  run.index = 3;
  run.scenario = "s.yaml";
  run.values = {{"country", "de"}};
  EXPECT_TRUE(row_matches(row(3, {{"file", "s.yaml"}, {"country", "de"}}), run));
  EXPECT_FALSE(row_matches(row(3, {{"file", "s.yaml"}, {"country", "jp"}}), run));
  EXPECT_FALSE(row_matches(row(3, {{"file", "t.yaml"}, {"country", "de"}}), run));
  EXPECT_FALSE(row_matches(row(4, {{"file", "s.yaml"}, {"country", "de"}}), run));
}

TEST(ResultsCsv, NotAResultsFileIsAnError) {
  test::TempDir dir;
  EXPECT_THROW(read_results_csv(dir.write("x.csv", "a,b\n1,2\n")), std::runtime_error);
  EXPECT_THROW(read_results_csv(dir.write("y.csv", "run,a\n1,2,3\n")), std::runtime_error);
  EXPECT_THROW(read_results_csv(dir.path() + "/missing.csv"), std::runtime_error);
}

TEST(ResultsCsv, MetricsFlattenWithKindOrdinals) {
  const auto metrics = nlohmann::ordered_json::parse(R"({
    "max_decel": 1.5, "collisions": 0,
    "sections": [
      {"kind": "turn", "id": "A", "blinker": "left", "s_start": 1, "lanelets": ["x"], "lead_distance": 70.5, "missed": false},
      {"kind": "roundabout_exit", "id": "R", "blinker": "right", "lead_distance": null, "missed": true},
      {"kind": "turn", "id": "B", "blinker": "right", "lead_distance": 41.9, "missed": false}],
    "lights": [{"id": "C", "stop_line_s": 3, "state_at_line": "r", "red_light_violation": true, "decision": null}]})");
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"max_decel", "1.5"},           {"collisions", "0"},
      {"turn1.id", "A"},              {"turn1.blinker", "left"},
      {"turn1.lead_distance", "70.5"}, {"turn1.missed", "false"},
      {"roundabout_exit1.id", "R"},   {"roundabout_exit1.blinker", "right"},
      {"roundabout_exit1.missed", "true"}, {"turn2.id", "B"},
      {"turn2.blinker", "right"},     {"turn2.lead_distance", "41.9"},
      {"turn2.missed", "false"},      {"light1.id", "C"},
      {"light1.state_at_line", "r"},  {"light1.red_light_violation", "true"}};
  EXPECT_EQ(flatten_metrics(metrics), expected);
}

}  // namespace
}  // namespace signalsim
