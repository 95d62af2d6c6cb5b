// Jerk-limited speed changes; the profile and the step rules are in jerk_limited_speed.hpp.
#include "planning/stop/jerk_limited_speed.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace signalsim {
namespace {

constexpr double kSpeedTolerance = 1e-6;     // [m/s] at the limit
constexpr double kLimitDistanceTolerance = 0.01;  // [m] feasibility slack against step discretisation
constexpr double kReleasing = -1e-3;         // [m/s^2] at or above: not braking

struct Phase {
  double jerk = 0.0;  // [m/s^3] signed
  double t = 0.0;     // [s]
};

// At most three phases of constant jerk: ramp, hold, ramp out.
struct Profile {
  std::array<Phase, 3> phases{};
  int count = 0;
  void add(double jerk, double t) {
    if (t > 0.0) phases[static_cast<std::size_t>(count++)] = {jerk, t};
  }
};

// The slow-down from (v, a) to v_f with target a_t (see the header).
Profile slow_down_profile(double v, double a, double v_f, double a_t, double J) {
  Profile p;
  const double dv = v_f - v;  // < 0: the speed to shed
  if (dv >= 0.0) return p;
  const double release = -(a < 0.0 ? a * a : 0.0) / (2.0 * J);  // speed change of ramping a (< 0) to 0
  if (a < 0.0 && release <= dv) {  // releasing the brake alone sheds enough
    p.add(J, -a / J);
    return p;
  }
  const double s1 = a_t < a ? -J : J;
  const double dv1 = (a_t * a_t - a * a) / (2.0 * s1);
  const double dv3 = -a_t * a_t / (2.0 * J);
  const double hold = (dv - dv1 - dv3) / a_t;
  if (hold >= 0.0) {
    p.add(s1, std::abs(a_t - a) / J);
    p.add(0.0, hold);
    p.add(J, -a_t / J);
    return p;
  }
  // a_t is deeper than needed: a triangle down to the peak a_p (from (a^2 - 2 a_p^2) / 2J = dv).
  const double a_p = -std::sqrt(std::max(0.0, (a * a - 2.0 * J * dv) / 2.0));
  p.add(-J, std::max(0.0, a - a_p) / J);
  p.add(J, -a_p / J);
  return p;
}

struct PhaseState {
  double x = 0.0, v = 0.0, a = 0.0;
};

// The first time in (0, t] at which v + a tau + jerk tau^2 / 2 reaches 0 (v > 0), or t when it does
// not. The speed's lowest point is at an end or, for jerk > 0, at tau* = -a / jerk; before the first
// root the speed only falls, so bisection on [0, end] finds it.
double until_rest(double v, double a, double jerk, double t) {
  const auto speed = [&](double tau) { return v + a * tau + jerk * tau * tau / 2.0; };
  double end = t;
  if (jerk > 0.0 && -a / jerk > 0.0 && -a / jerk < t && speed(-a / jerk) <= 0.0) end = -a / jerk;
  else if (speed(t) > 0.0) return t;
  double lo = 0.0, hi = end;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (speed(mid) > 0.0 ? lo : hi) = mid;
  }
  return hi;
}

// Moves along one phase for t seconds; a speed reaching 0 stays at rest (no acceleration left).
PhaseState along(PhaseState m, double jerk, double t) {
  const double tau = m.v > 0.0 ? until_rest(m.v, m.a, jerk, t) : 0.0;
  m.x += m.v * tau + m.a * tau * tau / 2.0 + jerk * tau * tau * tau / 6.0;
  if (tau < t) return {m.x, 0.0, 0.0};
  m.v = std::max(0.0, m.v + m.a * tau + jerk * tau * tau / 2.0);
  m.a += jerk * tau;
  return m;
}

double profile_distance(double v, double a, const Profile& p) {
  PhaseState m{0.0, v, a};
  for (int i = 0; i < p.count; ++i) m = along(m, p.phases[static_cast<std::size_t>(i)].jerk, p.phases[static_cast<std::size_t>(i)].t);
  return m.x;
}

// The profile's state after dt (past its end the speed is held, acceleration 0).
SpeedStep profile_step(double v, double a, const Profile& p, double dt) {
  PhaseState m{0.0, v, a};
  double left = dt;
  for (int i = 0; i < p.count && left > 0.0; ++i) {
    const Phase& ph = p.phases[static_cast<std::size_t>(i)];
    const double t = std::min(left, ph.t);
    m = along(m, ph.jerk, t);
    left -= t;
  }
  if (left > 0.0) m.a = 0.0;
  return {m.v, m.a};
}

}  // namespace

double slow_down_distance(double v, double a, double v_f, double a_t, double jerk) {
  return profile_distance(v, a, slow_down_profile(v, a, v_f, a_t, jerk));
}

SpeedStep slow_down_step(double v, double a, double v_f, double a_t, double jerk, double dt) {
  return profile_step(v, a, slow_down_profile(v, a, v_f, a_t, jerk), dt);
}

SpeedStep release_acceleration(double v, double a, double jerk, double dt) {
  const double a1 = a > 0.0 ? std::max(0.0, a - jerk * dt) : std::min(0.0, a + jerk * dt);
  return {std::max(0.0, v + (a + a1) * dt / 2.0), a1};
}

// In the direction of the target (sign s): the remaining gap u = s (target - v) and the acceleration
// toward it b = s a. The step ends at b1, and ramping b1 out at J afterwards sheds b1^2 / 2J more, so
// u - (b + b1) dt / 2 - b1^2 / 2J >= 0: b1 is at most the positive root of that quadratic.
SpeedStep track_speed(double v, double a, double target, const RideLimits& limits, double dt) {
  const double J = limits.jerk;
  const double s = target >= v ? 1.0 : -1.0;
  const double u = s * (target - v);
  const double b = s * a;
  const double toward = s > 0.0 ? limits.accel : limits.decel;
  const double c = u - b * dt / 2.0;  // the gap left if b1 were 0
  const double disc = dt * dt / 4.0 + 2.0 * c / J;
  const double room = disc >= 0.0 ? J * (-dt / 2.0 + std::sqrt(disc)) : -std::numeric_limits<double>::infinity();
  const double b1 = std::clamp(std::min(room, toward), b - J * dt, std::max(b - J * dt, std::min(toward, b + J * dt)));
  const double v1 = std::max(0.0, v + s * (b + b1) * dt / 2.0);
  // Arriving within the step: land on the target (the acceleration left is below J dt).
  if (s * (target - v1) <= 1e-9 && b1 <= J * dt) return {target, 0.0};
  return {v1, s * b1};
}

SlowDownStep plan_slow_down(double v, double a, double v_f, double distance, const SpeedStep& cruise,
                            const RideLimits& limits, double dt) {
  const double J = limits.jerk;
  const double hardest = -limits.decel;
  const double planned = kBrakeStartRatio * hardest;
  if (v <= v_f + kSpeedTolerance) {
    // Below the limit: the cruise stands while its acceleration can still be released before it
    // reaches the limit (a^2 / 2J more speed); else the ego approaches the limit itself.
    // (and one more step at that acceleration: the ramp-out starts a step after the test)
    const double b = std::max(0.0, cruise.accel);
    if (cruise.speed + b * b / (2.0 * J) + b * dt <= v_f + kSpeedTolerance) return {cruise, false, true};
    return {track_speed(v, a, v_f, limits, dt), true, true};
  }
  const bool feasible = slow_down_distance(v, a, v_f, hardest, J) <= distance + kLimitDistanceTolerance;
  // Whether a step to `next` still leaves room for the planned slow-down from where it leads.
  const auto leaves_room = [&](const SpeedStep& next) {
    return slow_down_distance(next.speed, next.accel, v_f, planned, J) <= distance - std::max(v, next.speed) * dt;
  };
  if (feasible && leaves_room(cruise)) return {cruise, false, true};
  if (!feasible) return {profile_step(v, a, slow_down_profile(v, a, v_f, hardest, J), dt), true, false};
  const SpeedStep held = release_acceleration(v, a, J, dt);
  if (a >= kReleasing && leaves_room(held)) return {held, held.speed < cruise.speed, true};
  // The gentlest target that still ends at the limit within the distance.
  double lo = hardest, hi = -1e-9;
  if (slow_down_distance(v, a, v_f, hi, J) <= distance) lo = hi;
  for (int i = 0; i < 100 && hi - lo > 1e-9 && lo != hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (slow_down_distance(v, a, v_f, mid, J) <= distance ? lo : hi) = mid;
  }
  const SpeedStep next = profile_step(v, a, slow_down_profile(v, a, v_f, lo, J), dt);
  return {next, next.speed < cruise.speed, true};
}

}  // namespace signalsim
