// Speed along the route under the lane speed limits ahead (internal lanes included) and the
// vehicle's maximum, jerk-limited (planning/stop/jerk_limited_speed.hpp, docs/behaviour.md §P1): the ego
// accelerates toward the limit of the lane its front is on and arrives at every lower limit ahead at
// or below it, where its front enters that lane (SUMO's own clamp point), within its accel, decel
// and the ride's jerk.
#pragma once

#include <cstdint>
#include <limits>
#include <string_view>

#include "core/vehicle_defaults.hpp"
#include "map/route_map.hpp"
#include "planning/stop/jerk_limited_speed.hpp"

namespace signalsim {

struct SpeedLimits {
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< vehicle maximum [m/s]
  double accel = 1.0;        ///< [m/s^2], > 0
  double decel = 1.0;        ///< [m/s^2], > 0
  double jerk = kRideJerk;   ///< [m/s^3], > 0
  RideLimits ride() const { return {accel, decel, jerk}; }
};

/// What set the speed the lane limits plan (the timeline's `speed_limited_by`).
enum class SpeedLimitKind : std::uint8_t {
  MaxSpeed,      ///< the vehicle's maximum, below the lane's limit
  LaneLimit,     ///< the limit of the lane the front is on
  LimitAhead,    ///< a lower limit ahead (a turn's internal lane, a slower edge)
  HeldOnYellow,  ///< the speed is held to the stop line of a light passed on a stop signal
};
std::string_view to_string(SpeedLimitKind kind);

/// Where the plan stops looking, for a light the judge lets the ego pass on a stop signal (yellow,
/// or red within reach): its decision assumed the ego keeps its speed to the line (docs/behaviour.md
/// §L2.3: d < v * yellow_lamp_period), so the speed is held (no acceleration) and lanelets starting
/// at or beyond `stop_line` are not looked at; a lower limit beyond it (a turn) applies once the
/// front has crossed the line.
struct HeldToLine {
  double stop_line = std::numeric_limits<double>::infinity();  ///< route s; infinity: none
};

struct LimitsPlan {
  SpeedStep step;                                   ///< the speed to command and its end acceleration
  SpeedLimitKind by = SpeedLimitKind::LaneLimit;
  bool feasible = true;  ///< false: a lower limit ahead (or the lane's own) is beyond reach at -decel
  /// Still slowing down toward a higher target: a deceleration being released at the jerk (`by`
  /// names the target, not what the slowing is for).
  bool releasing = false;
};

/// The speed to command for the next step of length dt, from the front at `s_front` with `speed`
/// and the profile's acceleration `accel`. Looks only as far ahead as a jerk-limited slow-down from
/// the faster of max_speed and the speed needs: cost independent of the net.
LimitsPlan plan_speed_under_limits(const RouteMap& route, double s_front, double speed, double accel, double dt,
                                   const SpeedLimits& limits, const HeldToLine& held = {});

}  // namespace signalsim
