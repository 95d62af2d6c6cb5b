#include "planning/speed_limit_planner.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {

std::string_view to_string(SpeedLimitKind kind) {
  switch (kind) {
    case SpeedLimitKind::MaxSpeed: return "max_speed";
    case SpeedLimitKind::LaneLimit: return "lane_limit";
    case SpeedLimitKind::LimitAhead: return "limit_ahead";
    case SpeedLimitKind::HeldOnYellow: return "held_on_yellow";
  }
  return "invalid";
}

LimitsPlan plan_speed_under_limits(const RouteMap& route, double s_front, double speed, double accel, double dt,
                                   const SpeedLimits& limits, const HeldToLine& held) {
  LimitsPlan plan;
  if (route.empty()) return plan;
  const RideLimits ride = limits.ride();
  const std::size_t here = route.index_at(s_front);
  const double lane_limit = route.at(here).speed_limit;
  double target = std::min(limits.max_speed, lane_limit);
  plan.by = limits.max_speed < lane_limit ? SpeedLimitKind::MaxSpeed : SpeedLimitKind::LaneLimit;
  const bool holding = std::isfinite(held.stop_line) && s_front < held.stop_line;
  if (holding && speed < target) {
    target = speed;
    plan.by = SpeedLimitKind::HeldOnYellow;
  }
  plan.step = track_speed(speed, accel, target, ride, dt);
  plan.releasing = plan.step.speed < speed && target >= speed;
  plan.feasible = speed <= lane_limit + 1e-6;
  // A jerk-limited slow-down from the fastest speed there can be: v^2 / 2 decel plus the ramps.
  const double fastest = std::max(limits.max_speed, speed);
  const double horizon = fastest * fastest / (2.0 * limits.decel) + fastest * limits.decel / limits.jerk + 1.0;
  const RouteMap::Window window = route.window(s_front, s_front + horizon);
  for (std::size_t i = std::max(window.first, here + 1); i < window.last; ++i) {
    const Lanelet& lanelet = route.at(i);
    if (lanelet.s_start >= held.stop_line - 1e-6) break;  // route order: the rest are beyond too
    // A limit above the speed and above what the acceleration still adds while released does not bind.
    const double b = std::max(0.0, plan.step.accel);
    const double release = b * b / (2.0 * limits.jerk) + b * dt;
    if (lanelet.speed_limit >= std::max(speed, plan.step.speed + release)) continue;
    const SlowDownStep slow =
        plan_slow_down(speed, accel, lanelet.speed_limit, lanelet.s_start - s_front, plan.step, ride, dt);
    plan.feasible = plan.feasible && slow.feasible;
    if (slow.binds && slow.step.speed < plan.step.speed) {
      plan.step = slow.step;
      plan.by = SpeedLimitKind::LimitAhead;
      plan.releasing = false;
    }
  }
  return plan;
}

}  // namespace signalsim
