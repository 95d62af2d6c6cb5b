// The V2I "remaining time to red" rule of the traffic-light judge (docs/behaviour.md §L1.7,
// `willTrafficLightTurnRedBeforeReachingStopLine`), as a pure function of the step's values:
//
//   t_pass  := d / v                          if v > velocity_threshold
//              required_time_to_departure     otherwise
//   horizon := t_pass + last_time_allowed_to_pass
//   turns_red := some prediction p with is_traffic_signal_red_stop(turn_direction, p.elements)
//                and (p.stamp - now) < horizon                                  (strict)
//
// The judge OR-s `turns_red` into to_be_stopped, without hysteresis (docs/behaviour.md §L1.2 step 3.6); the
// pass judge of §L2 still applies afterwards. No SUMO types: predictions are signal elements with an
// absolute stamp (SignalPrediction), made by the caller (scenario/light_stage from SUMO's program).
#pragma once

#include <optional>
#include <vector>

#include "traffic_light/signal_elements.hpp"

namespace signalsim {

/// Autoware's `v2i.*` parameters (docs/behaviour.md §L1.7, §L4).
struct V2iParameters {
  bool use_remaining_time = false;         ///< the rule is applied only when true
  double last_time_allowed_to_pass = 2.0;  ///< [s] margin added to t_pass
  double velocity_threshold = 0.5;         ///< [m/s] above: t_pass = d / v
  double required_time_to_departure = 3.0; ///< [s] t_pass at or below the threshold

  bool operator==(const V2iParameters&) const = default;
};

/// What the rule found this step.
struct V2iVerdict {
  bool turns_red = false;  ///< a red stop for this lane is predicted within the horizon
  double t_pass = 0.0;     ///< [s]
  double horizon = 0.0;    ///< [s] t_pass + last_time_allowed_to_pass
  /// [s] the earliest red-stop prediction's stamp minus now (negative: already due); empty when no
  /// prediction is a red stop for this lane.
  std::optional<double> time_to_red;
};

/// Throws std::invalid_argument naming the first non-finite or negative member.
void validate(const V2iParameters& params);

/// The rule above for one step. `d`: base_link to the stop point [m]; `v`: ego speed [m/s];
/// `now`: simulation time [s]. Evaluated whatever use_remaining_time says (the caller decides
/// whether to apply it). Never throws.
V2iVerdict will_turn_red_before_reaching_stop_line(double d, double v, double now, LaneTurnDirection turn_direction,
                                                   const std::vector<SignalPrediction>& predictions,
                                                   const V2iParameters& params);

}  // namespace signalsim
