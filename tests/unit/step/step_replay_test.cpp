// A signalsim-driven run's core replayed without SUMO on the recorded steps of a real run
// (data/intersection_left.steps.jsonl: bundled scenario intersection_left on the real libsumo, every
// observation, the commands the core gave and SUMO's feedback; rewritten by the step_ports
// integration test with SIGNALSIM_WRITE_STEP_FIXTURES=DIR). The core is built from the scenario,
// net and route alone: the same commands at every step, and the events the golden file holds.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "net/net_index.hpp"
#include "report/outputs.hpp"
#include "route/approach_lights.hpp"
#include "scenario/input_error.hpp"
#include "scenario/scenario.hpp"
#include "step/route_planning.hpp"
#include "step/step_core.hpp"
#include "step/step_recording.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;

std::string source(const std::string& relative) { return std::string(SIGNALSIM_SOURCE_DIR) + "/" + relative; }

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

StepRecording recording(const std::string& relative) {
  std::ifstream in(source(relative), std::ios::binary);
  return read_step_recording(in, relative);
}

TEST(StepReplay, IntersectionLeftGivesTheRecordedCommandsAndTheGoldenEvents) {
  const Scenario scenario = load_scenario(source("scenarios/intersection_left.yaml"));
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  const LateralPlan lateral = plan_lateral(scenario, plan, net);
  const StepRecording steps = recording("tests/unit/step/data/intersection_left.steps.jsonl");
  StepCore core(CoreSetup{scenario, plan.map, lateral, sumo::approach_lights(net, plan.map), {}, steps.start_time});
  const Replay replayed = replay(core, steps);
  EXPECT_FALSE(replayed.first_different_commands.has_value())
      << "the commands differ from step " << *replayed.first_different_commands;
  EXPECT_EQ(replayed.steps, steps.steps.size());
  EXPECT_TRUE(replayed.record.arrived);
  const fs::path events = fs::temp_directory_path() / ("signalsim_replay_events_" + std::to_string(::getpid()) + ".csv");
  write_events_csv(events.string(), replayed.record.events);
  EXPECT_EQ(file_text(events.string()), file_text(source("tests/golden/intersection_left.events.csv")));
  fs::remove(events);
}

// A left blinker the decider gives on the recorded approach is the recording's command too: the
// commands carry SUMO's blinker bits (left = 2) from the step the golden event names (9.7 s).
TEST(StepReplay, TheRecordedCommandsCarryTheLeftBlinkerFromItsEvent) {
  const StepRecording steps = recording("tests/unit/step/data/intersection_left.steps.jsonl");
  double first_left = -1.0;
  for (const RecordedStep& s : steps.steps)
    if (s.commands.signal_mask == 2) {
      first_left = s.observation.ego.time;
      break;
    }
  EXPECT_NEAR(first_left, 9.7, 1e-9);
}

TEST(StepReplay, ARecordingOfAnotherFormatIsRefusedWithItsLine) {
  std::istringstream other("{\"format\": \"something-else\", \"version\": 1, \"start_time\": 0}\n");
  EXPECT_THROW(
      {
        try {
          read_step_recording(other, "x.jsonl");
        } catch (const InputError& e) {
          EXPECT_STREQ(e.what(), "x.jsonl:1: not a signalsim-steps recording of version 1");
          throw;
        }
      },
      InputError);
  std::istringstream broken("{\"format\": \"signalsim-steps\", \"version\": 1, \"start_time\": 0}\n{\"observation\": 3}\n");
  try {
    read_step_recording(broken, "y.jsonl");
    FAIL() << "a malformed step was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("y.jsonl:2: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace signalsim
