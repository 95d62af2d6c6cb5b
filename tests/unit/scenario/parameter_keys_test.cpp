// Flattening, lookup by either name, and the "did you mean" rule (scenario/parameter_keys).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "scenario/input_error.hpp"
#include "scenario/parameter_keys.hpp"

namespace signalsim {
namespace {

TEST(ParameterKeys, NestedAndDottedKeysFlattenToOneName) {
  const auto flat = flatten_parameters(YAML::Load("a:\n  b:\n    c: 1\n  d: [1, 2]\ne.f: x\ng: ~\n"), "f.yaml");
  ASSERT_EQ(flat.size(), 4u);
  EXPECT_EQ(flat[0].name, "a.b.c");
  EXPECT_EQ(flat[0].line, 3);
  EXPECT_EQ(flat[1].name, "a.d");
  EXPECT_TRUE(flat[1].value.IsSequence());
  EXPECT_EQ(flat[2].name, "e.f");
  EXPECT_EQ(flat[3].name, "g");
}

TEST(ParameterKeys, ANonTextKeyIsRefused) {
  EXPECT_THROW(flatten_parameters(YAML::Load("? [a, b]\n: 1\n"), "f.yaml"), InputError);
}

TEST(ParameterKeys, FoundBySignalsimNameOrAutowarePlace) {
  ASSERT_NE(find_parameter("max_prepare_duration"), nullptr);
  EXPECT_EQ(find_parameter("lane_change.trajectory.max_prepare_duration"), find_parameter("max_prepare_duration"));
  EXPECT_EQ(find_parameter("traffic_light.v2i.velocity_threshold"), find_parameter("v2i.velocity_threshold"));
  EXPECT_EQ(find_parameter("avoidance.avoidance.longitudinal.max_prepare_time"), find_parameter("max_prepare_time"));
  EXPECT_EQ(find_parameter("lane_change.max_prepare_duration"), nullptr);
  EXPECT_EQ(find_parameter("goal_planner.path_safety_check.safety_check_params.forward_path_length"), nullptr);
}

TEST(ParameterKeys, SuggestionsAreOneEditOrTheWrongDepth) {
  EXPECT_EQ(suggest_parameter("stop_margn"), "stop_margin");
  EXPECT_EQ(suggest_parameter("traffic_light.stop_mragin"), "traffic_light.stop_margin");  // a transposition
  EXPECT_EQ(suggest_parameter("lane_change.max_prepare_duration"), "lane_change.trajectory.max_prepare_duration");
  // Real keys of Autoware's files that signalsim does not use are no typos.
  EXPECT_EQ(suggest_parameter("lane_change.trajectory.min_longitudinal_acc"), std::nullopt);
  EXPECT_EQ(suggest_parameter("avoidance.avoidance.longitudinal.min_prepare_time"), std::nullopt);
  EXPECT_EQ(suggest_parameter("start_planner.path_safety_check.safety_check_params.forward_path_length"), std::nullopt);
  EXPECT_EQ(suggest_parameter("avoidance.constraints.longitudinal.max_jerk"), std::nullopt);
  EXPECT_EQ(suggest_parameter("output_path_interval"), std::nullopt);
}

TEST(ParameterKeys, ModuleNamespacesAreGroups) {
  EXPECT_TRUE(is_parameter_group("traffic_light"));
  EXPECT_TRUE(is_parameter_group("lane_change.trajectory"));
  EXPECT_TRUE(is_parameter_group("v2i"));
  EXPECT_FALSE(is_parameter_group("goal_planner"));
  EXPECT_FALSE(is_parameter_group("traffic_light.stop_margin"));
}

TEST(ParameterKeys, EditDistanceCountsATranspositionOnce) {
  EXPECT_EQ(edit_distance("abc", "abc"), 0u);
  EXPECT_EQ(edit_distance("abc", "acb"), 1u);
  EXPECT_EQ(edit_distance("min_x", "max_x"), 2u);
  EXPECT_EQ(edit_distance("", "ab"), 2u);
}

}  // namespace
}  // namespace signalsim
