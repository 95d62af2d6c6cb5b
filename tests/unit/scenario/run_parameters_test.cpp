// The typed parameters (RunParameters): their defaults are the schema's, a scenario fills them once
// from its parameter files, country, params.set and --set, the decider's and the modules' structs
// get the ego's footprint, and a bad value is refused with the same message as before.
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "autoware_fixture.hpp"
#include "scenario/input_error.hpp"
#include "scenario/parameters.hpp"
#include "scenario/scenario.hpp"
#include "temp_dir.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::error_of;

using test::fixture;

const std::string kBase = "name: s\nnet: x.net.xml\nego: {route: [a], length: 5.0, base_link_to_front: 4.0}\n";

TEST(RunParameters, TheStructDefaultsAreTheSchemaDefaults) {
  const RunParameters from_schema = run_parameters(ParameterSet());
  const RunParameters typed;
  EXPECT_TRUE(from_schema.decider == typed.decider);
  EXPECT_TRUE(from_schema.behavior == typed.behavior);
  EXPECT_TRUE(from_schema.judge == typed.judge);
  EXPECT_TRUE(from_schema == typed);  // and the run's own values
  EXPECT_TRUE(Scenario().run_params == run_parameters(ParameterSet()));  // a scenario built in code
}

TEST(RunParameters, AScenarioFillsThemFromEverySourceAndKeepsTheRestAtTheirDefaults) {
  TempDir dir("run-params");
  dir.file("x.net.xml", "<net/>\n");  // only its existence is checked at load
  const std::string file = dir.file(
      "s.yaml", kBase + "country: jp\nparams:\n  files: [" + fixture("lane_change.param.yaml") +
                    "]\n  set: {stop_margin: 0.25, stuck_rest_time: 30, lane_change_safety_front_gap: 12}\n");
  const Scenario s = load_scenario(file, ScenarioOverrides{{"turn_signal_roundabout_on_exit=Right",
                                                            "v2i.use_remaining_time=true"}});
  const RunParameters& p = s.run_params;
  EXPECT_TRUE(p.decider.turn_signal_roundabout_exit_signal_from_previous_exit);  // country jp
  EXPECT_EQ(p.decider.turn_signal_roundabout_on_exit, "Right");                  // --set
  EXPECT_DOUBLE_EQ(p.behavior.max_prepare_duration, 3.5);                        // the parameter file
  EXPECT_DOUBLE_EQ(p.judge.stop_margin, 0.25);                                   // params.set
  EXPECT_TRUE(p.judge.v2i.use_remaining_time);                                   // --set
  EXPECT_DOUBLE_EQ(p.stuck_rest_time, 30.0);
  EXPECT_DOUBLE_EQ(p.lane_change_safety_front_gap, 12.0);
  EXPECT_DOUBLE_EQ(p.lane_change_safety_rear_gap, 10.0);  // defaults where nothing sets a value
  EXPECT_DOUBLE_EQ(p.judge.tl_state_timeout, 1.0);
  EXPECT_EQ(p.decider.turn_signal_roundabout_backward_depth, 50);
  // Every typed value is the resolved set's: the typed form of s.params.
  EXPECT_TRUE(p == run_parameters(s.params));
}

TEST(RunParameters, TheDeciderAndTheModulesGetTheEgosFootprint) {
  TempDir dir("run-params-ego");
  dir.file("x.net.xml", "<net/>\n");
  const Scenario s = load_scenario(dir.file("s.yaml", kBase), ScenarioOverrides{{"max_prepare_time=2.5"}});
  const TurnSignalParameters decider = turn_signal_parameters(s);
  EXPECT_DOUBLE_EQ(decider.base_link_to_front, 4.0);
  const BehaviorSignalParameters modules = behavior_parameters(s);
  EXPECT_DOUBLE_EQ(modules.base_link_to_front, 4.0);
  EXPECT_DOUBLE_EQ(modules.rear_overhang, 1.0);
  EXPECT_DOUBLE_EQ(modules.vehicle_width, kObstacleWidth);
  EXPECT_DOUBLE_EQ(modules.max_prepare_time, 2.5);
  // The same structs as made from the set by name with the ego's values.
  EXPECT_TRUE(decider == turn_signal_parameters(s.params, 4.0));
  EXPECT_TRUE(modules == behavior_parameters(s.params, decider, 5.0, kObstacleWidth));
}

TEST(RunParameters, ABadValueIsRefusedWithItsSourceAndReason) {
  TempDir dir("run-params-bad");
  dir.file("x.net.xml", "<net/>\n");
  const std::string file = dir.file("s.yaml", kBase);
  EXPECT_EQ(error_of([&] { load_scenario(file, ScenarioOverrides{{"stuck_rest_tme=3"}}); }),
            "--set: unknown parameter 'stuck_rest_tme' (did you mean 'stuck_rest_time'?)");
  EXPECT_EQ(error_of([&] { load_scenario(file, ScenarioOverrides{{"lane_change_safety_rear_gap=-1"}}); }),
            "--set: parameter 'lane_change_safety_rear_gap': value -1 is out of range [0, 1000]");
  EXPECT_EQ(error_of([&] { load_scenario(file, ScenarioOverrides{{"turn_signal_roundabout_on_exit=Up"}}); }),
            "--set: parameter 'turn_signal_roundabout_on_exit': 'Up' is not one of None, Left, Right");
}

}  // namespace
}  // namespace signalsim
