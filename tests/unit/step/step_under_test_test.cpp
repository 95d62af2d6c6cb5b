// The step core with systems under test, replayed without SUMO on the recorded steps of a real run
// (data/intersection_left.steps.jsonl): a decider under test commands the blinker while signalsim's
// decider runs in shadow (its blinker in the row beside the SUT's); a light judge under test decides
// stop or go for the judged lights and the planner executes it, the reference's decision kept beside.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "net/net_index.hpp"
#include "route/approach_lights.hpp"
#include "scenario/scenario.hpp"
#include "step/route_planning.hpp"
#include "step/step_core.hpp"
#include "step/step_recording.hpp"
#include "source_files.hpp"
#include "sut/system_under_test.hpp"

namespace signalsim {
namespace {

struct AlwaysLeft : BlinkerSut {
  int starts = 0, steps = 0, finishes = 0;
  std::vector<SutStep> seen;
  void start(const SutRun& run) override {
    ++starts;
    EXPECT_EQ(run.scenario, "intersection_left");
    EXPECT_NE(run.route, nullptr);
    EXPECT_FALSE(run.parameters.empty());
  }
  Blinker decide(const SutStep& step) override {
    ++steps;
    seen.push_back(step);
    return Blinker::Left;
  }
  void finish() override { ++finishes; }
};

struct StopAtEveryLight : LightJudgeSut {
  void start(const SutRun&) override {}
  std::vector<SutLightAnswer> judge(const SutStep& step) override {
    return std::vector<SutLightAnswer>(step.lights.size(), SutLightAnswer{true, "test, \"stops\"\nhere"});
  }
};

struct IntersectionLeftWithSuts {
  Scenario scenario = load_scenario(source_path("scenarios/intersection_left.yaml"));
  sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  sumo::RoutePlan plan = plan_route(scenario, net);
  LateralPlan lateral = plan_lateral(scenario, plan, net);
  StepRecording steps = [] {
    std::ifstream in(source_path("tests/unit/step/data/intersection_left.steps.jsonl"), std::ios::binary);
    return read_step_recording(in, "intersection_left.steps.jsonl");
  }();

  CoreSetup setup(SystemsUnderTest suts = {}) const {
    return CoreSetup{scenario, plan.map, lateral, with_recorded_arrows(sumo::approach_lights(net, plan.map), steps),
                     {},       steps.start_time, std::move(suts)};
  }
};

TEST(StepUnderTest, ADecidersBlinkerIsCommandedAndTheReferencesRecordedBesideIt) {
  const IntersectionLeftWithSuts run;
  StepCore alone(run.setup());
  const Replay reference = replay(alone, run.steps);
  auto sut = std::make_shared<AlwaysLeft>();
  SystemsUnderTest suts;
  suts.decider = sut;
  suts.decider_name = "always-left";
  StepCore core(run.setup(suts));
  const Replay replayed = replay(core, run.steps);
  ASSERT_EQ(replayed.record.rows.size(), reference.record.rows.size());
  EXPECT_EQ(sut->starts, 1);
  EXPECT_EQ(sut->finishes, 1);
  EXPECT_EQ(static_cast<std::size_t>(sut->steps), replayed.record.rows.size());
  EXPECT_EQ(replayed.record.decider_sut, "always-left");
  for (std::size_t i = 0; i < replayed.record.rows.size(); ++i) {
    const TimelineRow& row = replayed.record.rows[i];
    EXPECT_EQ(row.blinker, Blinker::Left) << i;
    EXPECT_EQ(row.blinker_source, RequestSource::Sut) << i;
    ASSERT_TRUE(row.ref_blinker.has_value()) << i;
    EXPECT_EQ(*row.ref_blinker, reference.record.rows[i].blinker) << i;
    EXPECT_EQ(row.ref_blinker_source, reference.record.rows[i].blinker_source) << i;
  }
  // The commands differ from the recording from the first step the reference does not blink left.
  const auto first_not_left = std::find_if(reference.record.rows.begin(), reference.record.rows.end(),
                                           [](const TimelineRow& r) { return r.blinker != Blinker::Left; });
  ASSERT_TRUE(replayed.first_different_commands.has_value());
  EXPECT_EQ(*replayed.first_different_commands,
            static_cast<std::size_t>(first_not_left - reference.record.rows.begin()));
  // What the SUT saw: the ego on the route, a window around it, time moving on.
  const SutStep& first = sut->seen.front();
  EXPECT_DOUBLE_EQ(first.ego.s_front - first.ego.s_base, run.scenario.ego.base_link_to_front);
  EXPECT_LT(first.window.first, first.window.last);
  const SutStep& middle = sut->seen[sut->seen.size() / 2];
  EXPECT_LE(run.plan.map.at(middle.window.first).s_start, middle.ego.s_base);
  EXPECT_GE(run.plan.map.at(middle.window.last - 1).s_end(), middle.ego.s_front);
  EXPECT_GT(sut->seen.back().time, first.time);
  EXPECT_FALSE(first.sumo_signals.has_value());  // not a traci decider: SUMO's mask is not read
}

TEST(StepUnderTest, ALightJudgesStopIsExecutedAndTheReferencesDecisionKept) {
  const IntersectionLeftWithSuts run;
  SystemsUnderTest suts;
  suts.light_judge = std::make_shared<StopAtEveryLight>();
  suts.light_judge_name = "always-stop";
  StepCore core(run.setup(suts));
  const Replay replayed = replay(core, run.steps);
  // The reference passes light C on green; the SUT's stop makes the core brake for it.
  ASSERT_TRUE(replayed.first_different_commands.has_value());
  const auto judged = std::find_if(replayed.record.rows.begin(), replayed.record.rows.end(),
                                   [](const TimelineRow& r) { return r.ref_tl_decision.has_value(); });
  ASSERT_NE(judged, replayed.record.rows.end());
  EXPECT_EQ(judged->tl_id, "C");
  EXPECT_EQ(judged->tl_decision, JudgeDecision::Stop);
  EXPECT_EQ(*judged->ref_tl_decision, JudgeDecision::Pass);
  EXPECT_EQ(judged->tl_reason, "test;  stops  here");  // a comma as ';', a quote or line break as a space
  // Never a stop point behind the front: a light whose line is passed is not asked about.
  for (const TimelineRow& row : replayed.record.rows) {
    if (row.stop_s && row.ref_tl_decision) {
      EXPECT_GE(*row.stop_s, row.s_front - 1e-9) << row.time;
    }
  }
  // The stop point is the reference's: the stop line less stop_margin.
  const std::vector<sumo::ApproachLight> lights = sumo::approach_lights(run.net, run.plan.map);
  ASSERT_EQ(lights.size(), 1u);
  ASSERT_TRUE(judged->stop_s.has_value());
  EXPECT_NEAR(*judged->stop_s, lights.front().s_stop_line - run.scenario.run_params.judge.stop_margin, 1e-6);

}

}  // namespace
}  // namespace signalsim
