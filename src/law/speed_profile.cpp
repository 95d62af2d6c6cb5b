// The speed planner rolled out along a route, and the bounds the rules use.
#include "law/speed_profile.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/number_text.hpp"

namespace signalsim::law {

double light_braking_distance(double v) { return v * v / 1.6 + 2.0 * v + 10.0; }
double yield_braking_distance(double v) { return v * v / 6.0 + 15.0; }

SpeedProfile::SpeedProfile(const RouteMap& route, double depart_front, double depart_speed, const SpeedLimits& limits,
                           double dt, std::vector<StopPoint> stops)
    : stops_(std::move(stops)), accel_(limits.accel), ramp_(limits.accel * limits.accel * limits.accel / (3.0 * limits.jerk * limits.jerk)) {
  std::sort(stops_.begin(), stops_.end(), [](const StopPoint& a, const StopPoint& b) { return a.s < b.s; });
  for (std::size_t i = 0; i < route.size(); ++i) limits_.emplace_back(route.at(i).s_start, route.at(i).speed_limit);
  double s = depart_front, v = depart_speed, a = 0.0;
  const double end = route.length();
  s_.push_back(s);
  v_.push_back(v);
  // The rollout ends at the route's end; a planner that would stand still forever (a zero limit)
  // is cut off after a bounded number of steps.
  const std::size_t max_steps = static_cast<std::size_t>(1e7);
  for (std::size_t k = 0; s < end && k < max_steps; ++k) {
    const LimitsPlan plan = plan_speed_under_limits(route, s, v, a, dt, limits);
    v = plan.step.speed;
    a = plan.step.accel;
    s += v * dt;  // SUMO's Euler update: the new speed over the step
    travel_time_ += dt;
    if (v <= 0.0) break;
    s_.push_back(s);
    v_.push_back(v);
  }
}

double SpeedProfile::planned(double s) const {
  if (s <= s_.front()) return v_.front();
  if (s >= s_.back()) return v_.back();
  const auto it = std::upper_bound(s_.begin(), s_.end(), s);
  const std::size_t k = static_cast<std::size_t>(it - s_.begin());
  const double t = (s - s_[k - 1]) / (s_[k] - s_[k - 1]);
  return v_[k - 1] + t * (v_[k] - v_[k - 1]);
}

// The jerk-limited start reaches accel after accel / jerk seconds, accel^3 / (6 jerk^2) metres on:
// the bound counts twice that distance as ramp.
double SpeedProfile::restart_speed(double from_rest) const {
  return std::sqrt(2.0 * kRestartShare * accel_ * std::max(0.0, from_rest - ramp_));
}

double SpeedProfile::restart_cap(double s) const {
  double cap = std::numeric_limits<double>::infinity();
  const double reach = s + light_braking_distance(planned(s));
  auto it = std::upper_bound(limits_.begin(), limits_.end(), std::make_pair(s, std::numeric_limits<double>::infinity()));
  if (it != limits_.begin()) --it;  // the lanelet s is on
  for (; it != limits_.end() && it->first <= reach; ++it) cap = std::min(cap, it->second);
  return cap;
}

double SpeedProfile::upper(double s) const { return planned(s) + kSpeedSlack; }

const StopPoint* SpeedProfile::stop_zone_at(double s) const {
  for (const StopPoint& p : stops_)
    if (s >= p.s - p.braking && s <= p.s) return &p;
  return nullptr;
}

double SpeedProfile::lower(double s) const {
  if (stop_zone_at(s)) return 0.0;
  double v = planned(s) - kSpeedSlack;
  // The latest stop point behind s: the ego may have restarted there from rest.
  for (const StopPoint& p : stops_)
    if (p.s < s) v = std::min(v, std::min(restart_speed(s - p.s), restart_cap(s)));
  return std::max(0.0, v);
}

std::string SpeedProfile::lower_reason(double s) const {
  if (const StopPoint* p = stop_zone_at(s)) return "it may be braking for " + p->what;
  const StopPoint* restart = nullptr;
  double v = planned(s) - kSpeedSlack;
  for (const StopPoint& p : stops_)
    if (p.s < s) {
      const double r = std::min(restart_speed(s - p.s), restart_cap(s));
      if (r < v) {
        v = r;
        restart = &p;
      }
    }
  if (restart) return "it may be restarting from rest at " + restart->what;
  return "the planned speed less " + rounded_fixed(kSpeedSlack, 1) + " m/s";
}

double SpeedProfile::max_planned(double from, double to) const {
  double best = std::max(planned(from), planned(to));
  for (double s = std::ceil(from); s < to; s += 1.0) best = std::max(best, planned(s));
  return best;
}

}  // namespace signalsim::law
