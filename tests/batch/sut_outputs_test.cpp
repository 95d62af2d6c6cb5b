// A system under test beside the reference, in the outputs (no SUMO): summary.json's "decider" and
// "light_judge" objects from hand-made rows, timeline.csv's ref columns read back, results.csv's
// decider / decider_agreement cells, the override that names a SUT relative to the command line's or a
// sweep file's directory, a swept decider, the golden files' side file, and compare's three drivers.
#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

#include "route_lanelets.hpp"
#include "batch/comparison.hpp"
#include "batch/golden_suts.hpp"
#include "batch/run_list.hpp"
#include "batch/run_outputs.hpp"
#include "batch/run_rows.hpp"
#include "batch/results_table.hpp"
#include "report/metrics.hpp"
#include "report/outputs.hpp"
#include "report/sut_agreement.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

using test::lanelet;

// a_0 | a left turn in J from s 100 to 115 | b_0 to s 260.
RouteMap sut_route() {
  return RouteMap({lanelet("a_0", 0, 100), lanelet(":J_0_0", 100, 15, TurnDirection::Left, "J"), lanelet("b_0", 115, 145)});
}

// 1 m per 0.1 s step from s = 0 to 249: the SUT's blinker and the reference's, by s.
RunRecord record(const std::function<Blinker(double)>& sut, const std::function<Blinker(double)>& ref) {
  RunRecord r;
  r.base_link_to_front = 3.7;
  r.decider_sut = "lib:my_decider.so";
  for (int i = 0; i < 250; ++i) {
    TimelineRow row;
    row.time = 0.1 * (i + 1);
    row.s_front = i;
    row.speed = 10.0;
    row.blinker = sut(i);
    row.blinker_source = RequestSource::Sut;
    row.ref_blinker = ref(i);
    row.ref_blinker_source = *row.ref_blinker == Blinker::None ? RequestSource::None : RequestSource::Intersection;
    r.rows.push_back(row);
  }
  return r;
}

Scenario scenario() {
  Scenario s;
  s.step_length = 0.1;
  return s;
}

TEST(SutAgreement, DeciderAgreementAndEachSidesOnAndOffPerSection) {
  // The SUT blinks left from s 40, the reference from 70; both until the front is at 118.
  const RunRecord r = record([](double s) { return s >= 40 && s <= 118 ? Blinker::Left : Blinker::None; },
                             [](double s) { return s >= 70 && s <= 118 ? Blinker::Left : Blinker::None; });
  const auto j = decider_agreement_json(scenario(), sut_route(), r);
  EXPECT_EQ(j["name"], "lib:my_decider.so");
  EXPECT_EQ(j["steps"], 250);
  EXPECT_EQ(j["agreeing_steps"], 220);  // s 40..69 differ
  EXPECT_DOUBLE_EQ(j["agreement"].get<double>(), 0.88);
  ASSERT_EQ(j["sections"].size(), 1u);
  const auto& turn = j["sections"][0];
  EXPECT_EQ(turn["kind"], "turn");
  EXPECT_EQ(turn["id"], "J");
  EXPECT_EQ(turn["blinker"], "left");
  EXPECT_DOUBLE_EQ(turn["sut"]["on_s"].get<double>(), 40.0);
  EXPECT_DOUBLE_EQ(turn["sut"]["off_s"].get<double>(), 119.0);  // the first row without it
  EXPECT_DOUBLE_EQ(turn["sut"]["lead_distance"].get<double>(), 60.0);
  EXPECT_DOUBLE_EQ(turn["reference"]["on_s"].get<double>(), 70.0);
  EXPECT_DOUBLE_EQ(turn["reference"]["off_s"].get<double>(), 119.0);
  EXPECT_DOUBLE_EQ(turn["reference"]["lead_distance"].get<double>(), 30.0);
  EXPECT_EQ(turn["sut"]["missed"], false);
  // The summary's metrics are the SUT's own (the rows' blinker).
  EXPECT_DOUBLE_EQ(compute_metrics(scenario(), sut_route(), r).sections[0].lead_distance.value(), 60.0);
}

TEST(SutAgreement, ASectionTheSutMissesHasNoOnOrOff) {
  const RunRecord r = record([](double) { return Blinker::None; },
                             [](double s) { return s >= 70 && s <= 118 ? Blinker::Left : Blinker::None; });
  const auto turn = decider_agreement_json(scenario(), sut_route(), r)["sections"][0];
  EXPECT_TRUE(turn["sut"]["on_s"].is_null());
  EXPECT_TRUE(turn["sut"]["off_s"].is_null());
  EXPECT_EQ(turn["sut"]["missed"], true);
  EXPECT_DOUBLE_EQ(turn["reference"]["on_s"].get<double>(), 70.0);
}

TEST(SutAgreement, AgreementRoundedToFourDecimalsAndAbsentWithoutASut) {
  RunRecord r = record([](double) { return Blinker::None; }, [](double s) { return s < 1 ? Blinker::None : Blinker::Left; });
  r.rows.resize(3);  // 1 of 3 agree
  EXPECT_DOUBLE_EQ(decider_agreement_json(scenario(), sut_route(), r)["agreement"].get<double>(), 0.3333);
  r.rows.resize(0);
  EXPECT_TRUE(decider_agreement_json(scenario(), sut_route(), r)["agreement"].is_null());
  r.decider_sut.clear();
  EXPECT_TRUE(decider_agreement_json(scenario(), sut_route(), r).is_null());
  EXPECT_TRUE(light_judge_agreement_json(r).is_null());
}

TEST(SutAgreement, LightJudgeAgreementOverJudgedRowsAndEachLightsDecisions) {
  RunRecord r;
  r.light_judge_sut = "exec:python3 judge.py";
  const auto add = [&](int n, const std::string& light, JudgeDecision sut, std::optional<JudgeDecision> ref) {
    for (int i = 0; i < n; ++i) {
      TimelineRow row;
      row.tl_id = light;
      row.tl_decision = sut;
      row.ref_tl_decision = ref;
      r.rows.push_back(row);
    }
  };
  add(10, "T", JudgeDecision::Stop, JudgeDecision::Stop);
  add(10, "T", JudgeDecision::Pass, JudgeDecision::Stop);
  add(10, "T", JudgeDecision::Pass, JudgeDecision::Pass);
  add(10, "U", JudgeDecision::Pass, std::nullopt);  // not judged by the reference: not compared
  add(5, "U", JudgeDecision::Stop, JudgeDecision::Stop);
  const auto j = light_judge_agreement_json(r);
  EXPECT_EQ(j["name"], "exec:python3 judge.py");
  EXPECT_EQ(j["steps"], 35);
  EXPECT_EQ(j["agreeing_steps"], 25);
  EXPECT_DOUBLE_EQ(j["agreement"].get<double>(), 0.7143);
  ASSERT_EQ(j["lights"].size(), 2u);
  EXPECT_EQ(j["lights"][0]["id"], "T");
  EXPECT_EQ(j["lights"][0]["sut"], nlohmann::ordered_json({"stop", "pass"}));
  EXPECT_EQ(j["lights"][0]["reference"], nlohmann::ordered_json({"stop", "pass"}));
  EXPECT_DOUBLE_EQ(j["lights"][0]["agreement"].get<double>(), 0.6667);
  EXPECT_EQ(j["lights"][1]["steps"], 5);
}

TEST(SutOutputs, TimelineRefColumnsReadBack) {
  TempDir dir;
  TimelineRow a;
  a.blinker = Blinker::Right;
  a.blinker_source = RequestSource::Sut;
  a.ref_blinker = Blinker::Left;
  a.ref_blinker_source = RequestSource::Intersection;
  a.tl_id = "C";
  a.tl_decision = JudgeDecision::Pass;
  a.ref_tl_decision = JudgeDecision::Stop;
  a.tl_reason = "amber and close";
  TimelineRow b;  // no reference decision this step
  const std::string path = (fs::path(dir.path()) / "timeline.csv").string();
  write_timeline_csv(path, {a, b}, {.decider = true, .light_judge = true});
  const std::vector<TimelineRow> rows = read_timeline_csv(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].blinker, Blinker::Right);
  EXPECT_EQ(rows[0].blinker_source, RequestSource::Sut);
  EXPECT_EQ(rows[0].ref_blinker, Blinker::Left);
  EXPECT_EQ(rows[0].ref_blinker_source, RequestSource::Intersection);
  EXPECT_EQ(rows[0].ref_tl_decision, JudgeDecision::Stop);
  EXPECT_EQ(rows[0].tl_reason, "amber and close");
  EXPECT_FALSE(rows[1].ref_blinker.has_value());
  EXPECT_FALSE(rows[1].ref_tl_decision.has_value());
}

TEST(SutOutputs, ResultsRowHasTheSutAndItsAgreementBeforeTheMetrics) {
  TempDir out;
  out.write("runs/0000-x/summary.json",
            R"({"status": "passed", "expectations": [], "metrics": {"max_decel": 1.5},
                "decider": {"name": "lib:my.so", "agreement": 0.925, "steps": 400},
                "light_judge": {"name": "exec:./judge", "agreement": null, "steps": 0}})");
  RunSpec run;
  run.scenario = "x.yaml";
  run.name = "x";
  ProcessResult result;
  result.exited = true;
  result.exit_code = 0;
  const ResultRow row = make_row(run, out.path(), "runs/0000-x", 10.0, result);
  EXPECT_EQ(row.cells.at("decider"), "lib:my.so");
  EXPECT_EQ(row.cells.at("decider_agreement"), "0.925");
  EXPECT_EQ(row.cells.at("light_judge"), "exec:./judge");
  EXPECT_FALSE(row.cells.count("light_judge_agreement"));
  const auto columns = result_columns({}, {{0, row}});
  const auto at = [&](const std::string& c) { return std::find(columns.begin(), columns.end(), c) - columns.begin(); };
  EXPECT_LT(at("decider"), at("decider_agreement"));
  EXPECT_LT(at("decider_agreement"), at("light_judge"));
  EXPECT_LT(at("light_judge"), at("max_decel"));
}

const std::string kScenario = std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/intersection_left.yaml";

TEST(SutOutputs, AnOverrideNamesTheSutRelativeToItsOwnDirectory) {
  const Scenario s = load_scenario(
      kScenario, ScenarioOverrides{{sut_override("decider", "lib:plugins/my.so", "/opt/here"),
                                    sut_override("light_judge", "exec:python3 judge.py --fast", "/opt/there")}});
  EXPECT_EQ(s.decider.kind, SutSpec::Kind::Library);
  EXPECT_EQ(s.decider.text, "lib:plugins/my.so");  // as given: summaries and results.csv
  EXPECT_EQ(s.decider.target, "/opt/here/plugins/my.so");
  EXPECT_EQ(s.light_judge.kind, SutSpec::Kind::Exec);
  EXPECT_EQ(s.light_judge.target, "python3 judge.py --fast");
  EXPECT_EQ(s.light_judge.base_dir, "/opt/there");
  // A plain override stays relative to the scenario file, as the key in the file.
  const Scenario plain = load_scenario(kScenario, ScenarioOverrides{{"decider=lib:my.so"}});
  EXPECT_EQ(plain.decider.target, (fs::path(kScenario).parent_path() / "my.so").lexically_normal().string());
  EXPECT_NE(test::error_of([] { (void)load_scenario(kScenario, ScenarioOverrides{{"decider={sut: reference}"}}); })
                .find("decider"),
            std::string::npos);
}

TEST(SutOutputs, ASweptDeciderIsRelativeToTheSweepFileAndShownAsWritten) {
  TempDir dir;
  const std::string file = dir.write("sweeps/s.yaml", "scenarios: " + kScenario +
                                                          "\ngrid:\n  decider: [reference, \"lib:../plug/my.so\"]\n"
                                                          "  country: [jp, de]\n");
  const Sweep sweep = load_sweep(file);
  const std::vector<RunSpec> runs = expand_sweep(sweep);
  ASSERT_EQ(runs.size(), 4u);
  EXPECT_EQ(runs[2].values[0], (std::pair<std::string, std::string>{"decider", "lib:../plug/my.so"}));
  const Scenario s = load_scenario(runs[2].scenario, ScenarioOverrides{runs[2].set});
  EXPECT_EQ(s.decider.target, (fs::path(dir.path()) / "plug/my.so").string());
  EXPECT_EQ(s.decider.text, "lib:../plug/my.so");
  EXPECT_EQ(s.country, "jp");
}

TEST(SutOutputs, ABadSweptDeciderNamesTheSweepFileAndLine) {
  TempDir dir;
  const std::string file =
      dir.write("s.yaml", "scenarios: " + kScenario + "\ngrid:\n  decider:\n    - reference\n    - magic\n");
  EXPECT_NE(test::error_of([&] { (void)load_sweep(file); }).find("s.yaml:5: grid.decider: 'magic' is not a decider"),
            std::string::npos)
      << test::error_of([&] { (void)load_sweep(file); });
  const std::string judge = dir.write("j.yaml", "scenarios: " + kScenario + "\nset:\n  light_judge: autoware_core\n");
  EXPECT_NE(test::error_of([&] { (void)load_sweep(judge); }).find("j.yaml:3: set.light_judge: autoware_core is a decider"),
            std::string::npos)
      << test::error_of([&] { (void)load_sweep(judge); });
}

TEST(SutOutputs, GoldenSideFileNamesTheSutsThatMadeIt) {
  TempDir dir;
  const std::string golden = (fs::path(dir.path()) / "left.events.csv").string();
  EXPECT_EQ(golden_suts_path(golden), (fs::path(dir.path()) / "left.suts.json").string());
  EXPECT_EQ(read_golden_suts(golden), GoldenSuts{});  // none: the reference
  const GoldenSuts mine{"lib:my.so", "reference"};
  write_golden_suts(golden, mine);
  EXPECT_EQ(read_golden_suts(golden), mine);
  EXPECT_NE(read_golden_suts(golden), GoldenSuts{});
  write_golden_suts(golden, GoldenSuts{});  // updated with the reference: the side file goes
  EXPECT_FALSE(fs::exists(golden_suts_path(golden)));
  EXPECT_EQ(run_suts(nlohmann::ordered_json::parse(R"({"decider": {"name": "autoware_core"}})")),
            (GoldenSuts{"autoware_core", "reference"}));
  EXPECT_EQ(describe(mine), "decider lib:my.so, light_judge reference");
}

TEST(SutOutputs, CompareScreenHasOneColumnPerDriverInRunOrder) {
  ScenarioComparison sc;
  sc.scenario = "synthetic";
  sc.base_link_to_front = 3.7;
  sc.items = compared_items(sut_route(), TurnSignalParameters());
  for (const char* driver : {"sut", "signalsim", "sumo"}) {
    const double from = std::string(driver) == "sut" ? 40 : std::string(driver) == "signalsim" ? 70 : 90;
    RunRecord r = record([from](double s) { return s >= from && s <= 118 ? Blinker::Left : Blinker::None; },
                         [](double) { return Blinker::None; });
    DriverRun run;
    run.driver = driver;
    run.status = "passed";
    run.run_dir = std::string("runs/0000-x-") + driver;
    run.summary["status"] = "passed";
    run.summary["metrics"] = metrics_json(scenario(), sut_route(), r);
    run.summary["expectations"] = nlohmann::ordered_json::array();
    sc.runs.push_back(std::move(run));
  }
  const std::string screen = comparison_screen({sc});
  const std::string header = screen.substr(0, screen.find('\n'));
  EXPECT_LT(header.find("sut"), header.find("signalsim"));
  EXPECT_LT(header.find("signalsim"), header.find("sumo"));
  EXPECT_NE(screen.find("lead 60.0 m"), std::string::npos) << screen;
  EXPECT_LT(screen.find("lead 60.0 m"), screen.find("lead 30.0 m")) << screen;
  EXPECT_LT(screen.find("lead 30.0 m"), screen.find("lead 10.0 m")) << screen;
  EXPECT_EQ(comparison_rows({sc}).size(), 3u);  // one item, three drivers
}

}  // namespace
}  // namespace signalsim
