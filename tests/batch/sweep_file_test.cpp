// Sweep files: strict reading (errors with file:line), the grid x zip expansion and its order.
#include <gtest/gtest.h>

#include "batch/run_list.hpp"
#include "batch/sweep_check.hpp"
#include "batch/sweep_file.hpp"
#include "scenario/input_error.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::data_dir;
using test::error_of;
using test::TempDir;

std::string scenarios_line() {
  return "scenarios: [" + data_dir() + "/turns.yaml, " + data_dir() + "/roundabout_exit.yaml]\n";
}


TEST(SweepFile, GridIsACartesianProductFirstKeySlowestScenariosOutermost) {
  TempDir dir;
  const std::string path = dir.write("s.yaml", scenarios_line() +
                                                   "grid:\n"
                                                   "  country: [jp, de]\n"
                                                   "  ego.max_speed: [8, 10, 12]\n");
  const Sweep sweep = load_sweep(path);
  EXPECT_EQ(sweep.name, "s");
  EXPECT_EQ(swept_keys(sweep), (std::vector<std::string>{"country", "ego.max_speed"}));
  const auto runs = expand_sweep(sweep);
  ASSERT_EQ(runs.size(), 12u);
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].index, i);
  EXPECT_EQ(runs[0].values, (std::vector<std::pair<std::string, std::string>>{{"country", "jp"}, {"ego.max_speed", "8"}}));
  EXPECT_EQ(runs[1].values[1].second, "10");
  EXPECT_EQ(runs[3].values[0].second, "de");
  EXPECT_EQ(runs[3].values[1].second, "8");
  EXPECT_NE(runs[5].scenario.find("turns.yaml"), std::string::npos);
  EXPECT_NE(runs[6].scenario.find("roundabout_exit.yaml"), std::string::npos);
  EXPECT_EQ(runs[7].set, (std::vector<std::string>{"country=jp", "ego.max_speed=10"}));
}

TEST(SweepFile, ZipListsGoTogetherAfterTheGridAndFixedSetComesFirst) {
  TempDir dir;
  const std::string path = dir.write("s.yaml", "scenarios: " + data_dir() + "/turns.yaml\n" +
                                                   "grid: {seed: [1, 2]}\n"
                                                   "zip:\n"
                                                   "  ego.max_speed: [8, 10, 12]\n"
                                                   "  ego.depart_speed: [7, 9, 11]\n"
                                                   "set: {turn_signal_search_time: 2.5}\n"
                                                   "timeout: 12\n"
                                                   "out: results\n"
                                                   "plot: {metric: turn1.lead_distance, x: ego.max_speed, y: seed}\n");
  const Sweep sweep = load_sweep(path);
  ASSERT_EQ(sweep.zips.size(), 1u);
  EXPECT_EQ(sweep.timeout, 12.0);
  EXPECT_EQ(sweep.out, dir.path() + "/results");
  EXPECT_EQ(sweep.plot.metric, "turn1.lead_distance");
  const auto runs = expand_sweep(sweep);
  ASSERT_EQ(runs.size(), 6u);
  EXPECT_EQ(runs[4].set, (std::vector<std::string>{"turn_signal_search_time=2.5", "seed=2", "ego.max_speed=10",
                                                    "ego.depart_speed=9"}));
  EXPECT_EQ(swept_keys(sweep), (std::vector<std::string>{"seed", "ego.max_speed", "ego.depart_speed"}));
}

TEST(SweepFile, SeveralZipGroupsAreSeveralFactors) {
  TempDir dir;
  const std::string path = dir.write("s.yaml", "scenarios: " + data_dir() + "/turns.yaml\n" +
                                                   "zip:\n"
                                                   "  - {seed: [1, 2]}\n"
                                                   "  - {ego.max_speed: [8, 9, 10], ego.depart_speed: [8, 9, 10]}\n");
  EXPECT_EQ(expand_sweep(load_sweep(path)).size(), 6u);
}

TEST(SweepFile, NoGridIsOneRunPerScenario) {
  TempDir dir;
  const std::string path = dir.write("s.yaml", "scenarios: [" + data_dir() + "]\n");
  const Sweep sweep = load_sweep(path);
  // The directory's *.yaml in name order (sweep files there are not scenarios, but the sweep does
  // not care until the runs are checked).
  ASSERT_GE(sweep.scenarios.size(), 2u);
  EXPECT_TRUE(std::is_sorted(sweep.scenarios.begin(), sweep.scenarios.end()));
  EXPECT_EQ(expand_sweep(sweep).size(), sweep.scenarios.size());
}

TEST(SweepFile, ErrorsNameTheFileAndLine) {
  TempDir dir;
  const auto load = [&](const std::string& text) {
    const std::string path = dir.write("bad.yaml", text);
    return error_of([&] { load_sweep(path); });
  };
  const std::string s = scenarios_line();  // line 1
  const std::string at = dir.path() + "/bad.yaml:";
  EXPECT_EQ(load(s + "gird: {seed: [1]}\n"), at + "2: unknown key 'gird'");
  EXPECT_EQ(load(s + "grid:\n  seed: 3\n"), at + "3: grid.seed: expected a list of values");
  EXPECT_EQ(load(s + "grid:\n  seed: []\n"), at + "3: grid.seed: the list is empty");
  EXPECT_EQ(load(s + "zip:\n  seed: [1, 2]\n  ego.max_speed: [8]\n"),
            at + "4: zip.ego.max_speed: 1 values, but zip.seed has 2 (zipped lists go together and need the same length)");
  EXPECT_EQ(load(s + "grid:\n  seed: [1]\nset:\n  seed: 2\n"), at + "5: set.seed: the key is swept or set twice");
  EXPECT_EQ(load(s + "grid:\n  status: [a]\n"),
            at + "3: grid.status: 'status' is a results.csv column, not a key to sweep");
  EXPECT_EQ(load(s + "timeout: -1\n"), at + "2: key 'timeout': value -1 is out of range [0.1, 86400]");
  EXPECT_EQ(load("scenarios: [nowhere.yaml]\n"),
            at + "1: scenario path '" + dir.path() + "/nowhere.yaml' not found");
  EXPECT_EQ(load(s + "plot: {metrc: x}\n"), at + "2: unknown key 'plot.metrc'");
  EXPECT_NE(load(s + "grid: [\n").find(at + "3: malformed YAML"), std::string::npos);
}

TEST(SweepFile, AnEmptyGridOrZipSweepsNothingAndIsRefused) {
  TempDir dir;
  const auto load = [&](const std::string& text) {
    const std::string path = dir.write("bad.yaml", text);
    return error_of([&] { load_sweep(path); });
  };
  const std::string s = scenarios_line();  // line 1
  const std::string at = dir.path() + "/bad.yaml:";
  EXPECT_EQ(load(s + "zip: []\n"),
            at + "2: key 'zip': the list is empty: it sweeps nothing (give mappings of key: [values], or leave zip out)");
  EXPECT_EQ(load(s + "zip:\n  - {}\n"),
            at + "3: zip: the mapping is empty: it sweeps nothing (give key: [values], or leave it out)");
  EXPECT_EQ(load(s + "zip: {}\n"),
            at + "2: zip: the mapping is empty: it sweeps nothing (give key: [values], or leave it out)");
  EXPECT_EQ(load(s + "zip:\n  - {seed: [1]}\n  - {ego.max_speed: []}\n"), at + "4: zip.ego.max_speed: the list is empty");
  EXPECT_EQ(load(s + "grid: {}\n"),
            at + "2: key 'grid': the mapping is empty: it sweeps nothing (give key: [values], or leave grid out)");
  EXPECT_EQ(load(s + "grid:\n  country: [jp]\n  seed: []\n"), at + "4: grid.seed: the list is empty");
}

TEST(SweepFile, RunsAreCheckedAgainstTheScenarioAndPointAtTheValue) {
  TempDir dir;
  const auto check = [&](const std::string& text) {
    const std::string path = dir.write("bad.yaml", text);
    return error_of([&] {
      const Sweep sweep = load_sweep(path);
      auto runs = expand_sweep(sweep);
      check_sweep_runs(sweep, runs);
    });
  };
  const std::string s = "scenarios: " + data_dir() + "/turns.yaml\n";
  const std::string at = dir.path() + "/bad.yaml:";
  // An unknown parameter, an unknown country, a value out of range: the line of the value.
  EXPECT_EQ(check(s + "grid:\n  turn_signal_serch_time: [1, 2]\n").rfind(at + "3: grid.turn_signal_serch_time: value 1: ", 0), 0u);
  EXPECT_EQ(check(s + "grid:\n  country:\n    - jp\n    - xx\n").rfind(at + "5: grid.country: value xx: ", 0), 0u);
  EXPECT_EQ(check(s + "zip:\n  ego.max_speed: [9, 1000]\n").rfind(at + "3: zip.ego.max_speed: value 1000: ", 0), 0u);
  // Only the combination is wrong (depart faster than the top speed): the grid's line.
  EXPECT_EQ(check(s + "grid:\n  ego.max_speed: [9, 10]\n  ego.depart_speed: [9.5]\n").rfind(at + "2: run 0 (turns.yaml ego.max_speed=9 ego.depart_speed=9.5): ", 0), 0u);
  // A good sweep: every run gets its scenario's name.
  const std::string path = dir.write("good.yaml", s + "grid: {country: [jp, de]}\n");
  const Sweep sweep = load_sweep(path);
  auto runs = expand_sweep(sweep);
  check_sweep_runs(sweep, runs);
  EXPECT_EQ(runs[1].name, "turns");
}

// Above kCombinationsChecked runs each value is checked in a run of its own (the other factors at
// their first values), not every run: a bad value is still named at its line, zipped values are
// checked together, and a swept name names its runs.
TEST(SweepFile, ALargeGridIsCheckedValueByValue) {
  TempDir dir;
  std::string seeds, times;
  for (int i = 1; i <= 200; ++i) seeds += (i > 1 ? ", " : "") + std::to_string(i);
  for (int i = 1; i <= 60; ++i) times += (i > 1 ? ", " : "") + std::to_string(i * 0.5);
  const std::string head = "scenarios: " + data_dir() + "/turns.yaml\ngrid:\n  seed: [" + seeds + "]\n";
  const auto check = [&](const std::string& rest) {
    const std::string path = dir.write("large.yaml", head + rest);
    return error_of([&] {
      const Sweep sweep = load_sweep(path);
      const SweepRuns runs(sweep);
      ASSERT_GT(runs.size(), kCombinationsChecked);
      (void)SweepCheck(runs);
    });
  };
  EXPECT_EQ(check("  turn_signal_search_time: [" + times + ", 99]\n").rfind(dir.path() + "/large.yaml:4: grid.turn_signal_search_time: value 99: ", 0), 0u);
  EXPECT_EQ(check("  turn_signal_search_time: [" + times + "]\nzip:\n  ego.max_speed: [13.89, 0.15]\n  ego.depart_speed: [8.33, 0.15]\n"), "");
  const std::string path = dir.write("named.yaml", head + "  turn_signal_search_time: [" + times + "]\n  name: [a, b]\n");
  const Sweep sweep = load_sweep(path);
  const SweepRuns runs(sweep);
  const SweepCheck check_names(runs);
  EXPECT_EQ(check_names.name_of(runs.at(0)), "a");
  EXPECT_EQ(check_names.name_of(runs.at(runs.size() - 1)), "b");
  EXPECT_EQ(runs.at(runs.size() - 1).values, (std::vector<std::pair<std::string, std::string>>{
                                                 {"seed", "200"}, {"turn_signal_search_time", "30.000000"}, {"name", "b"}}));
}

TEST(SweepFile, ListValuesAreGivenToSetInFlowStyle) {
  TempDir dir;
  const std::string path = dir.write("s.yaml", "scenarios: " + data_dir() + "/turns.yaml\n" +
                                                   "grid:\n  ego.route: [[in_S, mid_W, out_N]]\n  name: ['a: b']\n");
  const auto runs = expand_sweep(load_sweep(path));
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].set[0], "ego.route=[in_S, mid_W, out_N]");
  EXPECT_EQ(runs[0].set[1], "name=\"a: b\"");
  EXPECT_EQ(runs[0].values[1].second, "a: b");
}

}  // namespace
}  // namespace signalsim
