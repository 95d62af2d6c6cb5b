// The law's verdicts on the real libsumo (report/law_verdicts.hpp): a run's core with a system under
// test in the loop (in-process BlinkerSut / LightJudgeSut), its record written as summary.json by the
// same code as `signalsim run`, and the summary's "law" read back. The reference passes every verdict;
// a blinker that is always left, or the reference's own blinker 2 s late, and a light judge that always
// says go are caught, by section id and rule.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "net/net_index.hpp"
#include "report/expectations.hpp"
#include "report/outputs.hpp"
#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"
#include "sim/step_loop.hpp"
#include "step/step_core.hpp"
#include "sut/system_under_test.hpp"
#include "source_files.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;

// Always the left blinker.
class AlwaysLeft : public BlinkerSut {
 public:
  void start(const SutRun&) override {}
  Blinker decide(const SutStep&) override { return Blinker::Left; }
};

// The blinker the reference showed 2 s earlier in a run of the same scenario (the blinker does not
// move the ego here, so both runs drive the same way until the late blinker changes a lane change's
// prepare time).
class LateBy2s : public BlinkerSut {
 public:
  explicit LateBy2s(std::map<double, Blinker> reference) : reference_(std::move(reference)) {}
  void start(const SutRun&) override {}
  Blinker decide(const SutStep& step) override {
    auto it = reference_.upper_bound(step.time - 2.0 + 1e-6);
    if (it == reference_.begin()) return Blinker::None;
    return std::prev(it)->second;
  }

 private:
  std::map<double, Blinker> reference_;
};

// Go for every light.
class AlwaysGo : public LightJudgeSut {
 public:
  void start(const SutRun&) override {}
  std::vector<SutLightAnswer> judge(const SutStep& step) override {
    return std::vector<SutLightAnswer>(step.lights.size(), SutLightAnswer{false, "always go"});
  }
};

struct Verdicts {
  RunRecord record;
  nlohmann::json law;  // summary.json's "law"
  std::string status;  // summary.json's "status"
  // (section id, rule) of every failed verdict.
  std::set<std::pair<std::string, std::string>> failed() const {
    std::set<std::pair<std::string, std::string>> out;
    for (const auto& v : law["verdicts"])
      if (!v["passed"].get<bool>()) out.insert({v["id"].get<std::string>(), v["rule"].get<std::string>()});
    return out;
  }
};

// Runs `relative` on SUMO with the SUTs given (none: the reference) and writes its outputs as a run does.
Verdicts run_with(const std::string& relative, std::shared_ptr<BlinkerSut> decider,
                  std::shared_ptr<LightJudgeSut> judge) {
  const Scenario scenario = load_scenario(source_path(relative));
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const StartedRun run = start_run(plan_run(scenario, net), net, RunContext{});
  CoreSetup setup = core_setup(run, net);
  if (decider) {
    setup.suts.decider = std::move(decider);
    setup.suts.decider_name = "test:decider";
  }
  if (judge) {
    setup.suts.light_judge = std::move(judge);
    setup.suts.light_judge_name = "test:judge";
  }
  StepCore core(setup);
  Verdicts out;
  out.record = run_steps(*run.session, core);
  const auto results = evaluate_expectations(run.scenario, run.plan.map, out.record);
  const std::vector<LawVerdict> law = law_verdicts(run.scenario, run.plan.map, out.record);
  const fs::path dir = fs::temp_directory_path() / ("signalsim_law_" + std::to_string(::getpid()));
  write_run_outputs(dir.string(), run.scenario, run.plan, out.record, results, run_status(results, law), &law);
  const nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir / "summary.json"));
  out.law = summary["law"];
  out.status = summary["status"];
  fs::remove_all(dir);
  return out;
}

std::map<double, Blinker> blinkers_of(const RunRecord& record) {
  std::map<double, Blinker> out;
  for (const TimelineRow& r : record.rows) out[r.time] = r.blinker;
  return out;
}

using Failed = std::set<std::pair<std::string, std::string>>;

struct Case {
  std::string scenario;
  Failed always_left;  // the verdicts an always-left blinker fails
  Failed late;         // the verdicts the reference's blinker 2 s late fails
};

class LawVerdicts : public testing::TestWithParam<Case> {};

TEST_P(LawVerdicts, TheReferencePassesAndWrongBlinkersAreCaught) {
  const Case& c = GetParam();
  const Verdicts reference = run_with(c.scenario, nullptr, nullptr);
  ASSERT_TRUE(reference.law.is_object());
  EXPECT_GT(reference.law["verdicts"].size(), 3u);
  EXPECT_EQ(reference.law["failed"], 0) << reference.law.dump(1);
  EXPECT_EQ(reference.status, "passed");

  const Verdicts left = run_with(c.scenario, std::make_shared<AlwaysLeft>(), nullptr);
  EXPECT_EQ(left.failed(), c.always_left) << left.law.dump(1);
  EXPECT_EQ(left.status, "failed");

  const Verdicts late = run_with(c.scenario, std::make_shared<LateBy2s>(blinkers_of(reference.record)), nullptr);
  EXPECT_EQ(late.failed(), c.late) << late.law.dump(1);
  EXPECT_EQ(late.status, "failed");
}

INSTANTIATE_TEST_SUITE_P(
    Scenarios, LawVerdicts,
    testing::Values(
        // A left turn: always left is the turn's side, but not off before nor after it; 2 s late misses
        // the lead and stays on after the turn.
        Case{"scenarios/intersection_left.yaml", {{"start", "off"}, {"C", "off"}}, {{"C", "lead"}, {"C", "off"}}},
        // The first exit of a roundabout (jp: left from the entry on, the exit-signal marking).
        Case{"scenarios/roundabout_jp_exit1.yaml", {{"start", "off"}, {"RE", "off"}}, {{"RE", "lead"}, {"RE", "off"}}},
        // A lane change to the right: always left is the wrong side, on the whole route; 2 s late is not
        // on from the approval on.
        Case{"scenarios/lane_change_right.yaml",
             {{"in_S", "on"}, {"in_S", "wrong_side"}, {"in_S", "off"}, {"", "never_left"}},
             {{"in_S", "on"}}}),
    [](const testing::TestParamInfo<Case>& info) { return fs::path(info.param.scenario).stem().string(); });

TEST(LawVerdicts, AJudgeThatAlwaysGoesCrossesTheRedLight) {
  const std::string scenario = "scenarios/tl_red_stop_then_go.yaml";
  const Verdicts reference = run_with(scenario, nullptr, nullptr);
  EXPECT_EQ(reference.law["failed"], 0) << reference.law.dump(1);
  const Verdicts go = run_with(scenario, nullptr, std::make_shared<AlwaysGo>());
  EXPECT_EQ(go.failed(), (Failed{{"C", "stop"}})) << go.law.dump(1);
  EXPECT_EQ(go.status, "failed");
  EXPECT_FALSE(go.record.red_violations.empty());
}

}  // namespace
}  // namespace signalsim
