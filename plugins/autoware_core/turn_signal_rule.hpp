// autoware_core path_generator's turn-signal rule (planning/autoware_path_generator/src/utils.cpp,
// get_turn_signal, commit 2d693b82) on a route placed on s: which command the node publishes for
// one ego position and speed. The route is the plugin's copy; nothing is remembered between steps.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "required_end_point.hpp"

namespace signalsim::autoware_core {

/// TurnIndicatorsCommand values (autoware_vehicle_msgs).
enum class Command { NoCommand, Disable, Left, Right };

/// A lanelet's turn_direction attribute; None: absent.
enum class TurnDirection { None, Straight, Left, Right };

/// One route lanelet as the rule needs it.
struct Lane {
  double s_start = 0.0, s_end = 0.0;     ///< [m] route s
  double geometric_length = 0.0;         ///< [m] the centerline's length (lanelet::geometry::length2d)
  TurnDirection turn_direction = TurnDirection::None;
  std::optional<double> turn_signal_distance;  ///< [m] the lanelet's attribute, when it has one
  std::optional<double> required_end_arc;      ///< [m] on the centerline (required_end_point.hpp)
};

/// path_generator's parameters (planning/autoware_path_generator/config/path_generator.param.yaml
/// and vehicle_info's max_longitudinal_offset_m, commit 2d693b82).
struct Settings {
  double search_distance = 30.0;     ///< [m] turn_signal.search_distance
  double search_time = 3.0;          ///< [s] turn_signal.search_time
  double angle_threshold_deg = 15.0; ///< [deg] turn_signal.angle_threshold_deg
  double path_backward = 5.0;        ///< [m] path_length.backward
  double path_forward = 300.0;       ///< [m] path_length.forward
  double base_link_to_front = 0.0;   ///< [m] max_longitudinal_offset_m
};

/// The ego as get_turn_signal reads it: base_link's route position and the odometry's speed.
struct EgoState {
  double s_base = 0.0;  ///< [m]
  double speed = 0.0;   ///< [m/s] signed (twist.linear.x)
};

/// The command get_turn_signal returns for `ego` on `route` (lanes in driving order, contiguous).
Command get_turn_signal(const std::vector<Lane>& route, const EgoState& ego, const Settings& settings);

}  // namespace signalsim::autoware_core
