// A signalsim-driven run's core replayed without SUMO on the recorded steps of a real run
// (data/intersection_left.steps.jsonl: bundled scenario intersection_left on the real libsumo, every
// observation, the commands the core gave and SUMO's feedback; rewritten by the step_ports
// integration test with SIGNALSIM_WRITE_STEP_FIXTURES=DIR). The core is built from the scenario,
// net and route alone: the same commands at every step, and the events the golden file holds; an
// observation changed in the recording changes what the core decides; a recording that lacks what
// the core asks for stops the replay with the step.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <optional>
#include <string>

#include "net/net_index.hpp"
#include "report/outputs.hpp"
#include "route/approach_lights.hpp"
#include "scenario/input_error.hpp"
#include "scenario/scenario.hpp"
#include "step/route_planning.hpp"
#include "step/step_core.hpp"
#include "step/step_recording.hpp"
#include "source_files.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;

StepRecording recording(const std::string& relative) {
  std::ifstream in(source_path(relative), std::ios::binary);
  return read_step_recording(in, relative);
}

// intersection_left's core, built without SUMO.
struct IntersectionLeft {
  Scenario scenario = load_scenario(source_path("scenarios/intersection_left.yaml"));
  sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  sumo::RoutePlan plan = plan_route(scenario, net);
  LateralPlan lateral = plan_lateral(scenario, plan, net);
  StepRecording steps = recording("tests/unit/step/data/intersection_left.steps.jsonl");

  StepCore core() const {
    return StepCore(CoreSetup{scenario, plan.map, lateral,
                              with_recorded_arrows(sumo::approach_lights(net, plan.map), steps), {}, steps.start_time, {}});
  }
};

TEST(StepReplay, IntersectionLeftGivesTheRecordedCommandsAndTheGoldenEvents) {
  const IntersectionLeft run;
  StepCore core = run.core();
  const Replay replayed = replay(core, run.steps);
  EXPECT_EQ(replayed.unrecorded, "");
  EXPECT_FALSE(replayed.first_different_commands.has_value())
      << "the commands differ from step " << *replayed.first_different_commands;
  EXPECT_EQ(replayed.steps, run.steps.steps.size());
  EXPECT_TRUE(replayed.record.arrived);
  const fs::path events = fs::temp_directory_path() / ("signalsim_replay_events_" + std::to_string(::getpid()) + ".csv");
  write_events_csv(events.string(), replayed.record.events);
  EXPECT_EQ(file_text(events.string()), file_text(source_path("tests/golden/intersection_left.events.csv")));
  fs::remove(events);
}

// The recorded light C shows red from 5 s on (green in the run): the core's judge asks for a stop,
// so its commands leave the recording's from the step the red reaches the judge and it brakes.
TEST(StepReplay, ALightRedInTheRecordingMakesTheCoreBrakeForIt) {
  IntersectionLeft run;
  std::optional<std::size_t> first_red;
  for (std::size_t k = 0; k < run.steps.steps.size(); ++k) {
    StepObservation& seen = run.steps.steps[k].observation;
    if (seen.ego.time < 5.0) continue;
    for (LightReading& light : seen.lights)
      if (light.tls_id == "C") {
        light.state.assign(light.state.size(), 'r');
        if (!first_red) first_red = k;
      }
  }
  ASSERT_TRUE(first_red.has_value());
  StepCore core = run.core();
  const Replay replayed = replay(core, run.steps);
  ASSERT_TRUE(replayed.first_different_commands.has_value());
  EXPECT_GE(*replayed.first_different_commands, *first_red);
  const auto stop = std::find_if(replayed.record.rows.begin(), replayed.record.rows.end(),
                                 [](const TimelineRow& r) { return r.tl_decision == JudgeDecision::Stop; });
  ASSERT_NE(stop, replayed.record.rows.end());
  EXPECT_EQ(stop->tl_id, "C");
  EXPECT_GE(stop->time, 5.0);
}

// Light C's readings removed from 10 s on: the core still asks for them, and the replay stops there
// with the step instead of deciding on nothing.
TEST(StepReplay, ARecordingWithoutWhatTheCoreAsksForStopsWithTheStep) {
  IntersectionLeft run;
  std::size_t first_missing = 0;
  for (std::size_t k = run.steps.steps.size(); k-- > 0;) {
    StepObservation& seen = run.steps.steps[k].observation;
    if (seen.ego.time < 10.0 - 1e-9) break;
    if (seen.light("C")) first_missing = k;
    std::erase_if(seen.lights, [](const LightReading& l) { return l.tls_id == "C"; });
  }
  ASSERT_GT(first_missing, 0u);
  StepCore core = run.core();
  const Replay replayed = replay(core, run.steps);
  EXPECT_EQ(replayed.steps, first_missing);
  EXPECT_NE(replayed.unrecorded.find("step " + std::to_string(first_missing) + " at 10."), std::string::npos)
      << replayed.unrecorded;
  EXPECT_NE(replayed.unrecorded.find("the core asks for light C"), std::string::npos) << replayed.unrecorded;
}

TEST(StepReplay, ARecordingOfAnotherFormatIsRefusedWithItsLine) {
  std::istringstream other("\n{\"format\": \"something-else\", \"version\": 1, \"start_time\": 0}\n");
  EXPECT_THROW(
      {
        try {
          read_step_recording(other, "x.jsonl");
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(), "x.jsonl:2: not a signalsim-steps recording of version 1");
          throw;
        }
      },
      InputError);
  std::istringstream broken(
      "{\"format\": \"signalsim-steps\", \"version\": 1, \"start_time\": 0, \"arrows\": []}\n{\"observation\": 3}\n");
  try {
    read_step_recording(broken, "y.jsonl");
    FAIL() << "a malformed step was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("y.jsonl:2: not a recorded step: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace signalsim
