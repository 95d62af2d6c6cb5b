// Autoware's parameter files as shipped (fixtures in tests/data/autoware, written with the real
// files' structure): every parameter signalsim uses is read from where the real file keeps it,
// the other keys are listed (not refused; strict: checked against Autoware's own keys), and each value
// remembers its origin.
#include <algorithm>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "autoware_fixture.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"
#include "scenario/parameters.hpp"
#include "scenario/scenario.hpp"
#include "temp_dir.hpp"
#include "test_files.hpp"

namespace signalsim {
namespace {

using test::fixture;

using test::error_of;

const UnusedParameters* unused_of(const ParameterSet& set, const std::string& file) {
  for (const UnusedParameters& u : set.unused())
    if (u.file == file) return &u;
  return nullptr;
}

bool lists(const UnusedParameters* u, const std::string& key) {
  return u && std::find(u->keys.begin(), u->keys.end(), key) != u->keys.end();
}

TEST(AutowareFiles, EveryShippedFileLoadsAndEachValueComesFromItsPlace) {
  ParameterSet set;
  for (const char* file : {"behavior_path_planner.param.yaml", "traffic_light.param.yaml",
                           "behavior_velocity_planner_common.param.yaml", "lane_change.param.yaml",
                           "start_planner.param.yaml", "goal_planner.param.yaml", "static_obstacle_avoidance.param.yaml"})
    EXPECT_NO_THROW(set.apply_file(fixture(file), /*strict=*/false)) << file;
  // Under the module namespaces and their nesting.
  EXPECT_DOUBLE_EQ(set.number("max_prepare_duration"), 3.5);  // lane_change.trajectory.
  EXPECT_DOUBLE_EQ(set.number("stop_margin"), 0.5);           // traffic_light.
  EXPECT_DOUBLE_EQ(set.number("yellow_light_stop_velocity"), 1.0);
  EXPECT_DOUBLE_EQ(set.number("max_prepare_time"), 2.0);      // avoidance.avoidance.longitudinal.
  EXPECT_DOUBLE_EQ(set.number("restart_suppression.max_behind_distance_to_stop"), 1.0);
  EXPECT_EQ(set.text("turn_signal_on_centerline_start"), "RIGHT");
  EXPECT_DOUBLE_EQ(set.number("turn_signal_search_time"), 2.5);  // top level of behavior_path_planner
  EXPECT_TRUE(set.boolean("turn_signal_roundabout_entry_indicator_persistence"));
  EXPECT_DOUBLE_EQ(set.number("max_accel"), -2.8);
  // Origins: file and line of the key.
  EXPECT_EQ(set.origin("max_prepare_duration"), fixture("lane_change.param.yaml") + ":17");
  EXPECT_EQ(set.origin("stop_margin"), fixture("traffic_light.param.yaml") + ":4");
  EXPECT_EQ(set.origin("max_prepare_time"), fixture("static_obstacle_avoidance.param.yaml") + ":18");
  // avoidance.policy. (docs/behaviour.md §T8.2 "Avoidance") and start_planner.enable_back.
  EXPECT_EQ(set.text("candidate_path_turn_signal"), "none");
  EXPECT_EQ(set.origin("candidate_path_turn_signal"), fixture("static_obstacle_avoidance.param.yaml") + ":28");
  EXPECT_DOUBLE_EQ(set.number("turn_signal_on_approval_hold_duration"), 3.0);
  EXPECT_EQ(set.origin("turn_signal_on_approval_hold_duration"), fixture("static_obstacle_avoidance.param.yaml") + ":29");
  EXPECT_TRUE(set.boolean("enable_back"));
  EXPECT_EQ(set.origin("enable_back"), fixture("start_planner.param.yaml") + ":11");
  EXPECT_EQ(set.origin("turn_signal_search_time"), fixture("behavior_path_planner.param.yaml") + ":26");
  EXPECT_EQ(set.origin("lane_change_safety_rear_gap"), "default");
  // forward_path_length comes from behavior_path_planner (line 9), not from the start planner's
  // path_safety_check.safety_check_params.forward_path_length (another parameter of another module).
  EXPECT_EQ(set.origin("forward_path_length"), fixture("behavior_path_planner.param.yaml") + ":9");
  EXPECT_DOUBLE_EQ(set.number("forward_path_length"), 300.0);
  // Keys signalsim does not use are listed per file, in file order; the traffic-light file has none.
  EXPECT_EQ(unused_of(set, fixture("traffic_light.param.yaml")), nullptr);
  const UnusedParameters* lane_change = unused_of(set, fixture("lane_change.param.yaml"));
  ASSERT_NE(lane_change, nullptr);
  EXPECT_EQ(lane_change->keys.front(), "lane_change.time_limit");
  EXPECT_TRUE(lists(lane_change, "lane_change.trajectory.min_longitudinal_acc"));  // two edits from max_: not a typo
  EXPECT_TRUE(lists(lane_change, "lane_change.safety_check.execution.rear_vehicle_reaction_time"));
  EXPECT_TRUE(lists(unused_of(set, fixture("start_planner.param.yaml")),
                    "start_planner.path_safety_check.safety_check_params.forward_path_length"));
  EXPECT_TRUE(lists(unused_of(set, fixture("start_planner.param.yaml")), "start_planner.collision_check_margins"));
  EXPECT_TRUE(lists(unused_of(set, fixture("behavior_path_planner.param.yaml")), "traffic_light_signal_timeout"));
  EXPECT_TRUE(lists(unused_of(set, fixture("static_obstacle_avoidance.param.yaml")),
                    "avoidance.avoidance.longitudinal.min_prepare_time"));
  const UnusedParameters* goal = unused_of(set, fixture("goal_planner.param.yaml"));
  ASSERT_NE(goal, nullptr);
  EXPECT_EQ(goal->keys.size(), 9u);  // signalsim uses nothing of the goal planner's file
}

TEST(AutowareFiles, StrictListsAutowaresKeysAndWarnsOfADroppedOne) {
  ParameterSet set;
  ASSERT_NO_THROW(set.apply_file(fixture("lane_change.param.yaml"), /*strict=*/true));
  EXPECT_EQ(unused_of(set, fixture("lane_change.param.yaml"))->keys.front(), "lane_change.time_limit");
  EXPECT_TRUE(set.warnings().empty());
  // The start planner's enable_shift_pull_out left autoware_launch's file in 2025.
  ASSERT_NO_THROW(set.apply_file(fixture("start_planner.param.yaml"), /*strict=*/true));
  ASSERT_EQ(set.warnings().size(), 1u);
  EXPECT_EQ(set.warnings()[0], fixture("start_planner.param.yaml") +
                                   ":10: parameter 'start_planner.enable_shift_pull_out' was dropped from Autoware's "
                                   "start_planner.param.yaml (autowarefoundation/autoware_launch 4aeeff84d0, "
                                   "2025-08-28): it has no effect");
  EXPECT_FALSE(lists(unused_of(set, fixture("start_planner.param.yaml")), "start_planner.enable_shift_pull_out"));
}

TEST(AutowareFiles, NoteNamesTheFileTheCountAndTheFirstKeys) {
  UnusedParameters u{"lc.yaml", {"a", "b", "c", "d", "e", "f", "g", "h"}};
  EXPECT_EQ(unused_parameters_note(u),
            "lc.yaml: 8 keys signalsim does not use: a, b, c, d, e, f (+2 more; all in summary.json parameter_files)");
  EXPECT_EQ(unused_parameters_note({"x.yaml", {"a"}}), "x.yaml: 1 key signalsim does not use: a");
}

TEST(AutowareFiles, NotesAndWarningsHeldBackPrintOnRelease) {
  forget_printed_notes();
  std::ostringstream captured;
  std::streambuf* const stderr_buffer = std::cerr.rdbuf(captured.rdbuf());
  hold_notes();
  note_once("held note");
  warn_once("held warning");
  warn_once("held warning");  // once
  const std::string while_held = captured.str();
  release_notes();
  note_once("after");
  std::cerr.rdbuf(stderr_buffer);
  forget_printed_notes();
  EXPECT_EQ(while_held, "");
  EXPECT_EQ(captured.str(), "signalsim: note: held note\nsignalsim: warning: held warning\nsignalsim: note: after\n");
}

// --- bad input in a namespaced file: the file, the line and the key as written -----------------

std::string apply_text(const std::string& text) {
  TempDir dir("params");
  const std::string path = dir.file("p.param.yaml", text);
  ParameterSet set;
  const std::string message = error_of([&] { set.apply_file(path, /*strict=*/false); });
  return message.empty() ? message : message.substr(path.size());  // ":<line>: reason"
}

TEST(AutowareFilesBadInput, OutOfRangeNamesTheNamespacedKey) {
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    traffic_light:\n      stop_margin: 99\n"),
            ":4: parameter 'traffic_light.stop_margin': value 99 is out of range [-10, 50]");
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    lane_change:\n      trajectory:\n        max_prepare_duration: -1\n"),
            ":5: parameter 'lane_change.trajectory.max_prepare_duration': value -1 is out of range [0, 60]");
}

TEST(AutowareFilesBadInput, AvoidancePolicyNamesTheFileLineAndChoices) {
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    avoidance:\n      policy:\n"
                       "        candidate_path_turn_signal: \"when_stopped\"\n"),
            ":5: parameter 'avoidance.policy.candidate_path_turn_signal': 'when_stopped' is not one of none, "
            "stopped_candidate, all_candidate, stop_on_approval");
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    avoidance:\n      policy:\n"
                       "        turn_signal_on_approval_hold_duration: -1.0\n"),
            ":5: parameter 'avoidance.policy.turn_signal_on_approval_hold_duration': value -1.0 is out of range [0, 60]");
}

TEST(AutowareFilesBadInput, WrongTypeNamesTheNamespacedKey) {
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    traffic_light:\n      enable_pass_judge: maybe\n"),
            ":4: parameter 'traffic_light.enable_pass_judge': expected true or false, got 'maybe'");
}

TEST(AutowareFilesBadInput, AListWhereAMapBelongs) {
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    - stop_margin\n    - 1.0\n"),
            ":3: '/**.ros__parameters' must be a mapping of name: value, got a list");
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    traffic_light:\n      - stop_margin: 1.0\n"),
            ":3: 'traffic_light' must be a mapping of parameters, got a list");
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    traffic_light:\n      stop_margin: [1.0]\n"),
            ":4: parameter 'traffic_light.stop_margin': expected a single value, got a list");
  EXPECT_EQ(apply_text("- a\n- b\n"), ":1: parameters must be a mapping of name: value");
}

TEST(AutowareFilesBadInput, ATypoNearAKnownNameIsAnError) {
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    traffic_light:\n      stop_margn: 1.0\n"),
            ":4: unknown parameter 'traffic_light.stop_margn' (did you mean 'traffic_light.stop_margin'?)");
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    turn_signal_serch_time: 1.0\n"),
            ":3: unknown parameter 'turn_signal_serch_time' (did you mean 'turn_signal_search_time'?)");
  // The right name at the wrong depth of its module.
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    lane_change:\n      max_prepare_duration: 3.0\n"),
            ":4: unknown parameter 'lane_change.max_prepare_duration' (did you mean "
            "'lane_change.trajectory.max_prepare_duration'?)");
}

TEST(AutowareFilesBadInput, NestedAndDottedSpellingsAreOneKey) {
  EXPECT_EQ(apply_text("traffic_light:\n  stop_margin: 1.0\ntraffic_light.stop_margin: 2.0\n"),
            ":3: parameter 'traffic_light.stop_margin' is given twice (lines 2 and 3)");
  EXPECT_EQ(apply_text("stop_margin: 1.0\ntraffic_light:\n  stop_margin: 2.0\n"),
            ":3: parameter 'traffic_light.stop_margin' is given twice (also as 'stop_margin' at line 1)");
  EXPECT_EQ(apply_text("v2i:\n  velocity_threshold: 1.0\nv2i.velocity_threshold: 2.0\n"),
            ":3: parameter 'v2i.velocity_threshold' is given twice (lines 2 and 3)");
  EXPECT_EQ(apply_text("stop_margin: 1.0\nstop_margin: 2.0\n"), ":2: duplicate key 'stop_margin'");
}

TEST(AutowareFilesBadInput, AWrapperWithMoreThanRosParameters) {
  EXPECT_EQ(apply_text("/**:\n  ros__parameters:\n    stop_margin: 1.0\n  stray: 1\n"),
            ":4: unknown key '/**.stray' beside ros__parameters");
}

TEST(AutowareFilesBadInput, TheWrapperMustBeRosParameters) {
  // A misspelt wrapper would drop every value: an error, not a list of unused keys.
  EXPECT_EQ(apply_text("/**:\n  ros_parameters:\n    traffic_light:\n      stop_margin: 3.0\n"),
            ":2: unknown key '/**.ros_parameters' (did you mean 'ros__parameters'?)");
  EXPECT_EQ(apply_text("/**:\n"), "");  // empty: nothing to apply
}

TEST(AutowareFiles, SeveralNodeSectionsAreAllApplied) {
  TempDir dir("params");
  const std::string path =
      dir.file("p.yaml", "/**:\n  ros__parameters:\n    max_accel: -3.0\nbehavior_velocity_planner:\n  ros__parameters:\n"
                         "    traffic_light:\n      stop_margin: 1.5\n");
  ParameterSet set;
  set.apply_file(path, false);
  EXPECT_DOUBLE_EQ(set.number("max_accel"), -3.0);
  EXPECT_DOUBLE_EQ(set.number("stop_margin"), 1.5);
  EXPECT_EQ(set.origin("stop_margin"), path + ":7");
  EXPECT_TRUE(set.unused().empty());
}

TEST(AutowareFilesBadInput, AKnownNameDirectlyUnderAnotherModule) {
  EXPECT_EQ(apply_text("lane_change:\n  stop_margin: 1.0\n"),
            ":2: unknown parameter 'lane_change.stop_margin' (did you mean 'traffic_light.stop_margin'?)");
  EXPECT_EQ(apply_text("traffic_light:\n  max_accel: -1.0\n"),
            ":2: unknown parameter 'traffic_light.max_accel' (did you mean 'max_accel'?)");
}

TEST(AutowareFiles, AnotherNestingIsAnotherParameterNotATypo) {
  // path_generator.param.yaml keeps its own turn_signal.search_time (not the decider's).
  TempDir dir("params");
  const std::string path = dir.file("path_generator.param.yaml",
                                    "/**:\n  ros__parameters:\n    turn_signal:\n      search_time: 3.0\n      search_distance: 30.0\n");
  ParameterSet set;
  set.apply_file(path, false);
  ASSERT_EQ(set.unused().size(), 1u);
  EXPECT_EQ(set.unused()[0].keys, (std::vector<std::string>{"turn_signal.search_time", "turn_signal.search_distance"}));
  EXPECT_EQ(set.origin("turn_signal_search_time"), "default");
}

TEST(ParameterOrigins, ConsistencyIsCheckedOnTheFinalValues) {
  ParameterSet set;
  set.apply(YAML::Load("min_prepare_duration: 5.0"), ParameterOrigin{"a.yaml", "set"});  // max still 4
  set.apply(YAML::Load("max_prepare_duration: 6.0"), ParameterOrigin{"--set", "--set"});
  EXPECT_NO_THROW(set.check_consistency("s.yaml"));
  set.apply(YAML::Load("max_prepare_duration: 4.5"), ParameterOrigin{"--set", "--set"});
  EXPECT_EQ(error_of([&] { set.check_consistency("s.yaml"); }),
            "s.yaml: min_prepare_duration 5 (set) is greater than max_prepare_duration 4.5 (--set) (docs/behaviour.md §T8.2: "
            "the prepare duration lies in [min, max])");
}

// --- the other sources of values: always strict, each with its label -------------------------

TEST(ParameterOrigins, PresetSetAndCommandLineAreLabelledAndStrict) {
  ParameterSet set;
  set.apply(YAML::Load("turn_signal_search_time: 2.0"), ParameterOrigin{"jp.yaml", "country jp"});
  set.apply(YAML::Load("traffic_light.stop_margin: 1.5"), ParameterOrigin{"s.yaml", "set"});
  set.apply(YAML::Load("lane_change.trajectory.max_prepare_duration: 5"), ParameterOrigin{"--set", "--set"});
  EXPECT_EQ(set.origin("turn_signal_search_time"), "country jp");
  EXPECT_EQ(set.origin("stop_margin"), "set");
  EXPECT_DOUBLE_EQ(set.number("stop_margin"), 1.5);
  EXPECT_EQ(set.origin("max_prepare_duration"), "--set");
  EXPECT_DOUBLE_EQ(set.number("max_prepare_duration"), 5.0);
  EXPECT_EQ(error_of([&] { set.apply(YAML::Load("no_such_thing: 1"), ParameterOrigin{"--set", "--set"}); }),
            "--set:1: unknown parameter 'no_such_thing'");
}

// --- the scenario: params.strict, the note once, the summary's origins ------------------------

TEST(ScenarioParameterFiles, StrictKeyAndOrigins) {
  TempDir dir("scenario");
  dir.file("x.net.xml", "<net/>\n");  // only its existence is checked at load
  const std::string base = "name: s\nnet: x.net.xml\nego: {route: [a]}\ncountry: jp\n";
  const std::string files = "params:\n  files: [" + fixture("lane_change.param.yaml") + "]\n  set: {stop_margin: 0.25}\n";
  const Scenario loose = load_scenario(dir.file("loose.yaml", base + files), ScenarioOverrides{{"max_accel=-3"}});
  EXPECT_EQ(loose.params.origin("max_prepare_duration"), fixture("lane_change.param.yaml") + ":17");
  EXPECT_EQ(loose.params.origin("stop_margin"), "set");
  EXPECT_EQ(loose.params.origin("max_accel"), "--set");
  EXPECT_EQ(loose.params.origin("turn_signal_search_time"), "country jp");
  ASSERT_EQ(loose.params.unused().size(), 1u);
  const std::string typo = dir.file("lane_change.param.yaml",
                                    "/**:\n  ros__parameters:\n    lane_change:\n      time_limt: 50.0\n");
  const std::string typo_files = "params:\n  files: [" + typo + "]\n";
  const std::string strict_file = dir.file("strict.yaml", base + typo_files + "  strict: true\n");
  const std::string refused = typo + ":4: unknown parameter 'lane_change.time_limt': not a key of Autoware's "
                                     "lane_change.param.yaml (did you mean 'lane_change.time_limit'?)";
  EXPECT_EQ(error_of([&] { load_scenario(strict_file); }), refused);
  EXPECT_NO_THROW(load_scenario(dir.file("strict_shipped.yaml", base + files + "  strict: true\n")));
  // --strict-params is the override params.strict=true.
  EXPECT_EQ(error_of([&] { load_scenario(dir.file("s2.yaml", base + typo_files), ScenarioOverrides{{"params.strict=true"}}); }),
            refused);
  EXPECT_NE(error_of([&] { load_scenario(dir.file("s3.yaml", base + files + "  strict: perhaps\n")); })
                .find("key 'params.strict': expected true or false"),
            std::string::npos);
}

}  // namespace
}  // namespace signalsim
