// Every behaviour-module parameter of the schema reaches the modules (scenario/parameters
// behavior_parameters): a value set in a parameter file must change what the module reads, or a
// sweep over it would silently sweep nothing.
#include <gtest/gtest.h>

#include <yaml-cpp/yaml.h>

#include "scenario/input_error.hpp"
#include "scenario/parameters.hpp"

namespace signalsim {
namespace {

TEST(BehaviorParameters, EveryModuleParameterIsApplied) {
  ParameterSet set;
  set.apply(YAML::Load("min_length_for_turn_signal_activation: 12.5\n"
                       "max_prepare_duration: 5.5\n"
                       "min_prepare_duration: 1.5\n"
                       "min_lane_changing_velocity: 3.5\n"
                       "max_longitudinal_acc: 0.75\n"
                       "lane_change_required_end_at_boundary: false\n"
                       "max_prepare_time: 2.5\n"
                       "turn_signal_on_centerline_start: LEFT\n"
                       "minimum_shift_length: 0.25\n"
                       "th_distance_to_middle_of_the_road: 0.75\n"
                       "prepare_time_before_start: 1.25\n"
                       "turn_signal_search_time: 2.0\n"),
            "test");
  const BehaviorSignalParameters p =
      behavior_parameters(set, turn_signal_parameters(set, 3.5), /*vehicle_length=*/5.0, /*vehicle_width=*/1.9);
  EXPECT_DOUBLE_EQ(p.min_length_for_turn_signal_activation, 12.5);
  EXPECT_DOUBLE_EQ(p.max_prepare_duration, 5.5);
  EXPECT_DOUBLE_EQ(p.min_prepare_duration, 1.5);
  EXPECT_DOUBLE_EQ(p.min_lane_changing_velocity, 3.5);
  EXPECT_DOUBLE_EQ(p.max_longitudinal_acc, 0.75);
  EXPECT_FALSE(p.lane_change_required_end_at_boundary);
  EXPECT_DOUBLE_EQ(p.max_prepare_time, 2.5);
  EXPECT_EQ(p.turn_signal_on_centerline_start, "LEFT");
  EXPECT_DOUBLE_EQ(p.minimum_shift_length, 0.25);
  EXPECT_DOUBLE_EQ(p.th_distance_to_middle_of_the_road, 0.75);
  EXPECT_DOUBLE_EQ(p.prepare_time_before_start, 1.25);
  // Shared with the decider, and the ego's footprint.
  EXPECT_DOUBLE_EQ(p.turn_signal_search_time, 2.0);
  EXPECT_DOUBLE_EQ(p.base_link_to_front, 3.5);
  EXPECT_DOUBLE_EQ(p.rear_overhang, 1.5);
  EXPECT_DOUBLE_EQ(p.vehicle_width, 1.9);
}

TEST(BehaviorParameters, PrepareDurationsMustNotBeInverted) {
  ParameterSet set;
  try {
    set.apply(YAML::Load("min_prepare_duration: 5.0\n"), "params.yaml");
    set.check_consistency("params.yaml");  // on the final values
    FAIL() << "accepted min_prepare_duration > max_prepare_duration";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is greater than max_prepare_duration"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signalsim
