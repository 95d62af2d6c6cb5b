// Parameters of the turn-signal decider, with Autoware's names (docs/behaviour.md §T1.4, §T10).
#pragma once

#include <string>

#include "core/vehicle_defaults.hpp"

namespace signalsim {

struct TurnSignalParameters {
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< rear-axle centre to front bumper [m]
  double turn_signal_intersection_search_distance = 30.0;   ///< constant part of the search [m]
  double turn_signal_intersection_angle_threshold_deg = 15.0;  ///< required-end threshold [deg] (§T7)
  double turn_signal_search_time = 3.0;                     ///< speed part of the search [s]
  double turn_signal_minimum_search_distance = 10.0;        ///< "near next turn lane" threshold [m] (§T4.1)
  double turn_signal_path_backward_length = 100.0;          ///< path P behind the ego [m] (§T3)
  double forward_path_length = 300.0;                       ///< path P ahead of the ego [m] (§T3)
  std::string turn_signal_roundabout_on_entry = "None";     ///< "None" / "Left" / "Right" (§T5.2)
  std::string turn_signal_roundabout_on_exit = "Left";      ///< "None" / "Left" / "Right" (§T5.3)
  bool turn_signal_roundabout_entry_indicator_persistence = false;  ///< (§T5.2)
  double turn_signal_roundabout_search_distance = 30.0;     ///< [m] (§T5.2)
  double turn_signal_roundabout_angle_threshold_deg = 15.0; ///< [deg] (§T7)
  int turn_signal_roundabout_backward_depth = 50;           ///< lanelets, -1 unlimited (§T5.4)
  double turn_signal_shift_length_threshold = 0.3;          ///< [m] (§T8)
  double turn_signal_remaining_shift_length_threshold = 0.1;  ///< [m] (§T8)
  double turn_signal_remaining_distance_to_bound_threshold = 1.3;  ///< [m] (§T8, pull out)
  bool turn_signal_on_swerving = true;                      ///< (§T8, §T12.1.1)
  /// signalsim: ring lanes from the previous exit on are marked enable_exit_turn_signal before the
  /// decider sees the route (turn_signal/exit_signal_marking.hpp; Japan's rule).
  bool turn_signal_roundabout_exit_signal_from_previous_exit = false;

  bool operator==(const TurnSignalParameters&) const = default;
};

}  // namespace signalsim
