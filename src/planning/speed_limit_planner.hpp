// Speed along the route under the lane speed limits ahead (internal lanes included), within
// comfortable acceleration and deceleration limits.
#pragma once

#include <limits>

#include "core/vehicle_defaults.hpp"
#include "map/route_map.hpp"

namespace signalsim {

struct SpeedLimits {
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< vehicle maximum [m/s]
  double accel = 1.0;        ///< [m/s^2], > 0
  double decel = 1.0;        ///< [m/s^2], > 0
};

/// The speed to command for the next step of length dt: the highest speed from which every
/// lanelet ahead can still be entered (front bumper) at no more than its limit with `decel`,
/// reached from `speed` with at most `accel` and at most `decel` per second.
/// Looks only as far ahead as the braking distance from max_speed: cost independent of the net.
/// Lanelets starting at or beyond `limits_end` (route s) are not looked at: the step loop passes the
/// stop line of a light the judge lets the ego pass on a stop signal (yellow, or red within reach),
/// whose decision assumed the ego keeps its speed to the line (docs/behaviour.md §L2.3: d < v * yellow_lamp_period);
/// a lower limit beyond it (a turn) applies once the front has crossed the line.
double plan_speed_under_limits(const RouteMap& route, double s_front, double speed, double dt,
                               const SpeedLimits& limits,
                               double limits_end = std::numeric_limits<double>::infinity());

}  // namespace signalsim
