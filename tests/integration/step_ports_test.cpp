// The step as a system, on the real libsumo: a run's core sees SUMO only through its observation
// and commands. A real run is recorded step by step (step/step_recording) and its core replayed on
// the recording without SUMO: the same commands every step and the same record. The timeline's
// light columns are those of the row's own moment: the next light's state is SUMO's at the row's
// time, checked against SUMO's own light-state output.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <pugixml.hpp>

#include "net/net_index.hpp"
#include "report/outputs.hpp"
#include "route/approach_lights.hpp"
#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"
#include "sim/step_loop.hpp"
#include "step/step_core.hpp"
#include "step/sumo_driven_core.hpp"
#include "step/step_recording.hpp"
#include "source_files.hpp"

namespace signalsim {
namespace {

namespace fs = std::filesystem;

// The run's files as written (timeline.csv, events.csv, summary.json: its stops, red crossings, light
// log counts, lane changes, maneuver lines, off-plan stretches and end), as one text.
std::string outputs_of(const Scenario& scenario, const sumo::RoutePlan& plan, const RunRecord& record,
                       const fs::path& dir) {
  write_run_outputs(dir.string(), scenario, plan, record, {}, RunStatus::NoExpectations);
  return file_text(dir / "timeline.csv") + file_text(dir / "events.csv") + file_text(dir / "summary.json");
}

struct Recorded {
  RunRecord record;
  StepRecording recording;
  std::string text;  // the recording as written
};

// Runs `relative` on SUMO with `core` (built from `setup`) recorded.
Recorded record_run(const std::string& relative, const StartedRun& run, const CoreSetup& setup, RunCore& core) {
  std::ostringstream out;
  write_recording_header(out, setup);
  RecordingCore recording(core, out);
  Recorded r;
  r.record = run_steps(*run.session, recording);
  r.text = out.str();
  std::istringstream in(r.text);
  r.recording = read_step_recording(in, relative);
  return r;
}

class StepReplay : public testing::TestWithParam<std::string> {};

TEST_P(StepReplay, GivesTheSameCommandsAndRecordWithoutSumo) {
  const std::string relative = GetParam();
  const Scenario scenario = load_scenario(source_path(relative));
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const StartedRun run = start_run(plan_run(scenario, net), net, RunContext{});
  const CoreSetup setup = core_setup(run, net);
  StepCore live_core(setup);
  const Recorded live = record_run(relative, run, setup, live_core);
  ASSERT_FALSE(live.recording.steps.empty());
  EXPECT_EQ(live.recording.steps.size(), live.record.rows.size());

  StepCore again(setup);
  const Replay replayed = replay(again, live.recording);
  EXPECT_EQ(replayed.unrecorded, "");
  EXPECT_FALSE(replayed.first_different_commands.has_value())
      << relative << ": commands differ from step " << *replayed.first_different_commands;
  EXPECT_EQ(replayed.steps, live.recording.steps.size());
  const fs::path work = fs::temp_directory_path() / ("signalsim_replay_" + std::to_string(::getpid()));
  EXPECT_EQ(outputs_of(run.scenario, run.plan, replayed.record, work / "replayed"),
            outputs_of(run.scenario, run.plan, live.record, work / "live"))
      << relative;
  fs::remove_all(work);

  // The fixture of the SUMO-free replay test (tests/unit/step), written on request.
  if (const char* dir = std::getenv("SIGNALSIM_WRITE_STEP_FIXTURES")) {
    const std::string name = fs::path(relative).stem().string();
    std::ofstream(fs::path(dir) / (name + ".steps.jsonl"), std::ios::binary) << live.text;
  }
}

// A left turn at a light, a lane change waiting for a gap (target-lane traffic), V2I (programs and
// timing), backing up (commands move_back), a run that ends stuck behind an obstacle (the leader), and an
// arrow program loaded from an additional file (the recording's arrows).
INSTANTIATE_TEST_SUITE_P(Scenarios, StepReplay,
                         testing::Values("scenarios/intersection_left.yaml", "scenarios/lane_change_waits_for_gap.yaml",
                                         "scenarios/tl_v2i_red_predicted_stop.yaml",
                                         "scenarios/pull_out_backward_hazard.yaml",
                                         "tests/data/scenarios/stuck_behind_obstacle.yaml",
                                         "tests/data/scenarios/arrow_program_left_yellow.yaml"),
                         [](const testing::TestParamInfo<std::string>& info) {
                           return fs::path(info.param).stem().string();
                         });

// The SUMO-driven core replays the same way: it commands nothing, and its record (SUMO's blinker, the
// stops SUMO made at a red light) comes from the observations alone.
TEST(StepReplay, TheSumoDrivenCoreGivesTheSameRecordWithoutSumo) {
  const std::string relative = "scenarios/tl_red_stop_then_go.yaml";
  const Scenario scenario = load_scenario(source_path(relative));
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  RunContext context;
  context.sumo_drives = true;
  const StartedRun run = start_run(plan_run(scenario, net), net, context);
  const CoreSetup setup = core_setup(run, net);
  SumoDrivenCore live_core(setup);
  const Recorded live = record_run(relative, run, setup, live_core);
  ASSERT_FALSE(live.record.stops.empty());  // SUMO stopped at the red light on its own
  SumoDrivenCore again(setup);
  const Replay replayed = replay(again, live.recording);
  EXPECT_EQ(replayed.unrecorded, "");
  EXPECT_FALSE(replayed.first_different_commands.has_value());
  const fs::path work = fs::temp_directory_path() / ("signalsim_replay_sumo_" + std::to_string(::getpid()));
  EXPECT_EQ(outputs_of(run.scenario, run.plan, replayed.record, work / "replayed"),
            outputs_of(run.scenario, run.plan, live.record, work / "live"));
  fs::remove_all(work);
}

// SUMO's own record of a light's states (additional SaveTLSStates): each state from its time on.
std::map<double, std::string> sumo_light_states(const fs::path& file, const std::string& tls) {
  pugi::xml_document doc;
  EXPECT_TRUE(doc.load_file(file.c_str())) << file;
  std::map<double, std::string> states;
  for (pugi::xml_node s : doc.child("tlsStates").children("tlsState"))
    if (tls == s.attribute("id").value()) states[s.attribute("time").as_double()] = s.attribute("state").value();
  return states;
}

// With a short horizon (50 m) the light lies beyond the judges' window most of the approach: the row
// then shows the next light, whose state must be SUMO's at the row's time, also on the step where it
// switches from yellow to red, 100 m before the light.
TEST(StepRows, TheNextLightsStateIsSumosAtTheRowsTime) {
  const fs::path work = fs::temp_directory_path() / ("signalsim_tl_state_" + std::to_string(::getpid()));
  fs::create_directories(work);
  std::ofstream(work / "tls.add.xml") << "<additional><timedEvent type=\"SaveTLSStates\" source=\"C\" dest=\""
                                      << (work / "tls.xml").string() << "\"/></additional>\n";
  ScenarioOverrides overrides;
  overrides.set = {"forward_path_length=50", "duration=40"};
  Scenario scenario = load_scenario(source_path("scenarios/intersection_straight.yaml"), overrides);
  scenario.additional.push_back((work / "tls.add.xml").string());
  scenario.light_offsets["C"] = 20.0;  // green ends at 10 s, while the light is beyond the horizon
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  RunRecord record;
  std::vector<sumo::ApproachLight> lights;
  {
    const StartedRun run = start_run(plan_run(scenario, net), net, RunContext{});
    lights = sumo::approach_lights(net, run.plan.map);
    record = drive(run, net);
  }  // SUMO closes: its output is complete
  ASSERT_FALSE(lights.empty());
  const sumo::ApproachLight& light = lights.front();
  const std::map<double, std::string> states = sumo_light_states(work / "tls.xml", light.tls_id);
  ASSERT_GT(states.size(), 2u);
  const auto state_at = [&states, &light](double t) {
    auto it = states.upper_bound(t + 1e-6);
    return it == states.begin() ? '?' : std::prev(it)->second.at(static_cast<std::size_t>(light.link_index));
  };
  // SUMO switches a light at the start of a step and its output names the state from that step's
  // time; the state read after the step that ends at t (the row's moment) is the one named from t - dt.
  const double dt = scenario.step_length;
  std::size_t switches = 0, compared = 0;
  for (const TimelineRow& row : record.rows) {
    if (row.tl_id != light.tls_id) continue;
    ++compared;
    EXPECT_EQ(row.tl_state, state_at(row.time - dt)) << "t=" << row.time << " s=" << row.s_front;
    if (state_at(row.time - dt) != state_at(row.time)) ++switches;
  }
  EXPECT_GT(compared, 100u);
  EXPECT_GT(switches, 0u) << "no switch seen: the test would not tell the row's moment from the next step's";
  fs::remove_all(work);
}

}  // namespace
}  // namespace signalsim
