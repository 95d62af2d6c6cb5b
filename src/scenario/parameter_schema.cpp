// The parameter schema: Autoware's names, defaults and the ranges signalsim accepts, and where
// Autoware's shipped parameter files keep each one (autoware_launch: behavior_path_planner.param.yaml
// top level for the decider, `traffic_light.` in traffic_light.param.yaml, `lane_change.` and
// `lane_change.trajectory.` in lane_change.param.yaml, `avoidance.avoidance.longitudinal.` and
// `avoidance.policy.` in static_obstacle_avoidance.param.yaml, `start_planner.` in start_planner.param.yaml, the top level
// of behavior_velocity_planner_common.param.yaml for max_accel, max_jerk, delay_response_time).
#include "scenario/parameters.hpp"

#include <utility>
#include <vector>

namespace signalsim {

// An entry without its last field (autoware_key) is kept where Autoware keeps it under its own name.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace {

// The turn-signal decider, the behaviour modules (docs/behaviour.md §T10) and the run.
std::vector<ParameterSpec> decider_and_module_parameter_specs() {
  return {
    // Turn-signal decider (docs/behaviour.md §T10).
    {"turn_signal_intersection_search_distance", 30.0, 0.0, 1000.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_intersection_angle_threshold_deg", 15.0, 0.0, 180.0, {}, "deg", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_on_entry", std::string("None"), 0, 0, {"None", "Left", "Right"}, "-", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_entry_indicator_persistence", false, 0, 0, {}, "-", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_on_exit", std::string("Left"), 0, 0, {"None", "Left", "Right"}, "-", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_search_distance", 30.0, 0.0, 1000.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_angle_threshold_deg", 15.0, 0.0, 180.0, {}, "deg", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_backward_depth", 50, -1.0, 100000.0, {}, "lanelets", "docs/behaviour.md §T10"},
    {"turn_signal_roundabout_exit_signal_from_previous_exit", false, 0, 0, {}, "-",
     "signalsim: mark ring lanes from the previous exit as enable_exit_turn_signal (Japan)"},
    {"turn_signal_minimum_search_distance", 10.0, 0.0, 1000.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_path_backward_length", 100.0, 0.0, 10000.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_search_time", 3.0, 0.0, 60.0, {}, "s", "docs/behaviour.md §T10"},
    {"turn_signal_shift_length_threshold", 0.3, 0.0, 10.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_remaining_shift_length_threshold", 0.1, 0.0, 10.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_remaining_distance_to_bound_threshold", 1.3, 0.0, 10.0, {}, "m", "docs/behaviour.md §T10"},
    {"turn_signal_on_swerving", true, 0, 0, {}, "-", "docs/behaviour.md §T10"},
    {"forward_path_length", 300.0, 1.0, 10000.0, {}, "m", "docs/behaviour.md §T10"},
    {"input_path_interval", 2.0, 0.01, 100.0, {}, "m", "docs/behaviour.md §T10 (parity only: s needs no resampling)"},
    {"ego_nearest_dist_threshold", 3.0, 0.0, 100.0, {}, "m", "docs/behaviour.md §T1.4 (parity only: the ego is located on s by its lane)"},
    {"ego_nearest_yaw_threshold", 1.046, 0.0, 3.1416, {}, "rad", "docs/behaviour.md §T1.4 (parity only)"},
    {"min_length_for_turn_signal_activation", 10.0, 0.0, 1000.0, {}, "m", "docs/behaviour.md §T10 (lane change)",
     "lane_change.min_length_for_turn_signal_activation"},
    {"max_prepare_duration", 4.0, 0.0, 60.0, {}, "s", "lane_change.param.yaml trajectory.max_prepare_duration (docs/behaviour.md §T8.2)",
     "lane_change.trajectory.max_prepare_duration"},
    {"min_prepare_duration", 2.0, 0.0, 60.0, {}, "s", "lane_change.param.yaml trajectory.min_prepare_duration (docs/behaviour.md §T8.2)",
     "lane_change.trajectory.min_prepare_duration"},
    {"min_lane_changing_velocity", 2.78, 0.0, 50.0, {}, "m/s",
     "lane_change.param.yaml trajectory.min_lane_changing_velocity (docs/behaviour.md §T8.2)",
     "lane_change.trajectory.min_lane_changing_velocity"},
    {"max_longitudinal_acc", 1.0, 0.0, 10.0, {}, "m/s^2", "lane_change.param.yaml trajectory.max_longitudinal_acc (docs/behaviour.md §T8.2)",
     "lane_change.trajectory.max_longitudinal_acc"},
    {"lane_change_required_end_at_boundary", true, 0, 0, {}, "-",
     "signalsim: the lane change's required end where the path crosses the adjacent lane's boundary"},
    {"lane_change_safety_rear_gap", 10.0, 0.0, 1000.0, {}, "m",
     "signalsim: target lane kept free behind the rear bumper before approval (stand-in for the RSS check)"},
    {"lane_change_safety_front_gap", 10.0, 0.0, 1000.0, {}, "m",
     "signalsim: target lane kept free beyond the lane change's end before approval"},
    {"max_prepare_time", 3.0, 0.0, 60.0, {}, "s", "docs/behaviour.md §T10 (avoidance)",
     "avoidance.avoidance.longitudinal.max_prepare_time"},
    {"candidate_path_turn_signal", std::string("none"), 0, 0,
     {"none", "stopped_candidate", "all_candidate", "stop_on_approval"}, "-",
     "docs/behaviour.md §T10 (avoidance: the blinker while waiting for approval)",
     "avoidance.policy.candidate_path_turn_signal"},
    {"turn_signal_on_approval_hold_duration", 3.0, 0.0, 60.0, {}, "s",
     "docs/behaviour.md §T10 (avoidance: stop_on_approval's hold)",
     "avoidance.policy.turn_signal_on_approval_hold_duration"},
    {"turn_signal_on_centerline_start", std::string("RIGHT"), 0, 0, {"LEFT", "RIGHT"}, "-", "docs/behaviour.md §T10 (start planner)",
     "start_planner.turn_signal_on_centerline_start"},
    {"minimum_shift_length", 0.5, 0.0, 10.0, {}, "m", "docs/behaviour.md §T10 (start planner)",
     "start_planner.minimum_shift_length"},
    {"th_distance_to_middle_of_the_road", 0.5, 0.0, 10.0, {}, "m", "docs/behaviour.md §T10 (start planner)",
     "start_planner.th_distance_to_middle_of_the_road"},
    {"prepare_time_before_start", 0.0, 0.0, 60.0, {}, "s", "docs/behaviour.md §T10 (start planner)",
     "start_planner.prepare_time_before_start"},
    {"enable_back", true, 0, 0, {}, "-", "docs/behaviour.md §T10 (start planner)", "start_planner.enable_back"},
    // The run (signalsim).
    {"stuck_rest_time", 60.0, 0.0, 1e6, {}, "s",
     "signalsim: the ego at rest this long while signalsim commands it to drive ends the run as not arrived "
     "(0: off)"},
  };
}

// The traffic-light judge.
std::vector<ParameterSpec> judge_parameter_specs() {
  return {
    // Traffic-light judge (docs/behaviour.md §L4 and its Decisions).
    {"stop_margin", 0.0, -10.0, 50.0, {}, "m", "docs/behaviour.md §L4",
     "traffic_light.stop_margin"},
    {"tl_state_timeout", 1.0, 0.0, 60.0, {}, "s", "docs/behaviour.md §L4",
     "traffic_light.tl_state_timeout"},
    {"stop_time_hysteresis", 0.1, 0.0, 60.0, {}, "s", "docs/behaviour.md §L4",
     "traffic_light.stop_time_hysteresis"},
    {"yellow_lamp_period", 2.75, 0.0, 60.0, {}, "s", "docs/behaviour.md §L4",
     "traffic_light.yellow_lamp_period"},
    {"yellow_light_stop_velocity", 2.0, 0.0, 50.0, {}, "m/s", "docs/behaviour.md §L0 (brief: 2.0)",
     "traffic_light.yellow_light_stop_velocity"},
    {"enable_pass_judge", true, 0, 0, {}, "-", "docs/behaviour.md §L4",
     "traffic_light.enable_pass_judge"},
    {"enable_rtc", false, 0, 0, {}, "-", "docs/behaviour.md §L1.5 (only false: no operator in simulation)",
     "traffic_light.enable_rtc"},
    {"restart_suppression.min_behind_distance_to_stop", 0.5, 0.0, 10.0, {}, "m", "docs/behaviour.md §L1.6",
     "traffic_light.restart_suppression.min_behind_distance_to_stop"},
    {"restart_suppression.max_behind_distance_to_stop", 1.0, 0.0, 10.0, {}, "m", "docs/behaviour.md §L1.6",
     "traffic_light.restart_suppression.max_behind_distance_to_stop"},
    {"v2i.use_remaining_time", false, 0, 0, {}, "-", "docs/behaviour.md §L1.7",
     "traffic_light.v2i.use_remaining_time"},
    {"v2i.last_time_allowed_to_pass", 2.0, 0.0, 60.0, {}, "s", "docs/behaviour.md §L1.7",
     "traffic_light.v2i.last_time_allowed_to_pass"},
    {"v2i.velocity_threshold", 0.5, 0.0, 50.0, {}, "m/s", "docs/behaviour.md §L1.7",
     "traffic_light.v2i.velocity_threshold"},
    {"v2i.required_time_to_departure", 3.0, 0.0, 60.0, {}, "s", "docs/behaviour.md §L1.7",
     "traffic_light.v2i.required_time_to_departure"},
    {"enable_arrow_aware_yellow_passing", false, 0, 0, {}, "-", "docs/behaviour.md §L1.8 (corrected: false, as shipped)",
     "traffic_light.enable_arrow_aware_yellow_passing"},
    {"is_simulation", true, 0, 0, {}, "-", "docs/behaviour.md §L0"},
    {"max_accel", -2.8, -50.0, -0.01, {}, "m/s^2", "docs/behaviour.md §L2.1 (pass-judge deceleration, negative)"},
    {"max_jerk", -5.0, -100.0, -0.01, {}, "m/s^3", "docs/behaviour.md §L2.1 (pass-judge jerk, negative)"},
    {"delay_response_time", 0.5, 0.0, 10.0, {}, "s", "docs/behaviour.md §L2.1"},
    {"stop_release_confirmation_time", 0.0, 0.0, 10.0, {}, "s",
     "signalsim: a decided stop (the judge's latch, docs/behaviour.md §L1.2 step 3.10) is released only after no stop signal "
     "for this long without a break (0: the reference, one go cycle releases it)"},
  };
}

}  // namespace

const std::vector<ParameterSpec>& parameter_schema() {
  static const std::vector<ParameterSpec> schema = [] {
    std::vector<ParameterSpec> all = decider_and_module_parameter_specs();
    for (ParameterSpec& spec : judge_parameter_specs()) all.push_back(std::move(spec));
    return all;
  }();
  return schema;
}

}  // namespace signalsim
