#include "planning/speed_limit_planner.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {

double plan_speed_under_limits(const RouteMap& route, double s_front, double speed, double dt,
                               const SpeedLimits& limits, double limits_end) {
  if (route.empty()) return 0.0;
  const double horizon = limits.max_speed * limits.max_speed / (2.0 * limits.decel) + 1.0;
  const RouteMap::Window window = route.window(s_front, s_front + horizon);
  double allowed = limits.max_speed;
  for (std::size_t i = window.first; i < window.last; ++i) {
    const Lanelet& lanelet = route.at(i);
    if (lanelet.s_start >= limits_end - 1e-6 && lanelet.s_start > s_front) break;  // route order: the rest are beyond too
    const double ahead = std::max(0.0, lanelet.s_start - s_front);
    // v^2 = v_limit^2 + 2 a d: the fastest speed now that still brakes down to the limit.
    allowed = std::min(allowed, std::sqrt(lanelet.speed_limit * lanelet.speed_limit + 2.0 * limits.decel * ahead));
  }
  const double lowest = std::max(0.0, speed - limits.decel * dt);
  const double highest = speed + limits.accel * dt;
  return std::clamp(allowed, lowest, std::max(lowest, highest));
}

}  // namespace signalsim
