#include "planning/stop/jerk_limited_stop.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "planning/stop/jerk_limited_speed.hpp"

namespace signalsim {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kStoppedVelocity = 1e-3;    // [m/s] at or below: standing
constexpr double kBrakingAcceleration = -1e-3;  // [m/s^2] below: already braking
constexpr double kDistanceTolerance = 0.01;  // [m] feasibility slack against step discretisation
// [m] From rest, a stop nearer than this holds the ego (the judge's restart suppression keeps it
// where it stands up to max_behind_distance_to_stop, 1.0 m short, docs/behaviour.md §L1.6).
constexpr double kPullAwayDistance = 1.0;

// Smallest t in (0, t_max] with v + a t + s t^2 / 2 = 0 (v > 0), if any.
std::optional<double> first_stop_time(double v, double a, double s, double t_max) {
  if (t_max <= 0.0) return std::nullopt;
  double best = kInf;
  if (s == 0.0) {
    if (a < 0.0) best = -v / a;
  } else {
    const double A = 0.5 * s;
    const double disc = a * a - 4.0 * A * v;
    if (disc >= 0.0) {
      const double sq = std::sqrt(disc);
      for (const double t : {(-a - sq) / (2.0 * A), (-a + sq) / (2.0 * A)}) {
        if (t > 0.0 && t < best) best = t;
      }
    }
  }
  if (best <= t_max) return best;
  return std::nullopt;
}

struct Ramp {
  double s;  // signed jerk of the ramp
  double t;  // ramp duration
};

Ramp ramp(double a, double target_acc, double jerk) {
  if (std::isinf(jerk) || target_acc == a) return {0.0, 0.0};
  const double s = target_acc < a ? -jerk : jerk;
  return {s, std::abs(target_acc - a) / jerk};
}

struct Motion {
  double v;
  double a;
};

// The profile's state after dt.
Motion advance(double v, double a, double target_acc, double jerk, double dt) {
  if (v <= 0.0) return {0.0, 0.0};
  const Ramp r = ramp(a, target_acc, jerk);
  const double a0 = std::isinf(jerk) ? target_acc : a;
  const double tau = std::min(dt, r.t);
  if (first_stop_time(v, a0, r.s, tau)) return {0.0, 0.0};
  const double v1 = v + a0 * tau + 0.5 * r.s * tau * tau;
  const double a1 = a0 + r.s * tau;
  const double rest = dt - tau;
  if (rest <= 0.0) return {v1, a1};
  const double v2 = v1 + target_acc * rest;
  if (v2 <= 0.0) return {0.0, 0.0};
  return {v2, target_acc};
}

// The distance of the profile a step follows: with a finite jerk the deceleration is released as
// the ego comes to rest (planning/stop/jerk_limited_speed: ramp, hold, ramp out), so the stop ends
// without a jolt; with unbounded jerk it is held to rest.
double ride_stop_distance(double v, double a, double target_acc, double jerk) {
  return std::isinf(jerk) ? stopping_distance(v, a, target_acc, jerk) : slow_down_distance(v, a, 0.0, target_acc, jerk);
}

void require_finite(double value, const char* name) {
  if (!std::isfinite(value)) throw std::invalid_argument(std::string("plan_stop: ") + name + " is not finite");
}

void validate_set(const StopConstraintSet& c, const char* name) {
  if (!std::isfinite(c.min_acc) || !(c.min_acc < 0.0)) {
    throw std::invalid_argument(std::string("stop planner parameter ") + name + ".min_acc must be finite and < 0");
  }
  if (std::isnan(c.min_jerk) || !(c.min_jerk < 0.0)) {
    throw std::invalid_argument(std::string("stop planner parameter ") + name + ".min_jerk must be < 0");
  }
}

// Exact stop: the gentlest target within [min_acc, 0) whose profile ends at D; released at rest
// when the distance allows it (ride_stop_distance), else held to rest.
void exact_stop(StopCommand& cmd, double v, double a, double D, double min_acc, double jerk, double s_min, double dt) {
  const bool releases = !std::isinf(jerk) && slow_down_distance(v, a, 0.0, min_acc, jerk) <= D;
  const auto distance_at = [&](double target) {
    return releases ? slow_down_distance(v, a, 0.0, target, jerk) : stopping_distance(v, a, target, jerk);
  };
  double lo = min_acc;  // S(lo) <= D (+ tolerance)
  double hi = -1e-9;    // S(hi) is (practically) >= D
  if (distance_at(hi) <= D) {
    lo = hi;
  } else if (releases || s_min < D) {
    for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
      const double mid = 0.5 * (lo + hi);
      (distance_at(mid) <= D ? lo : hi) = mid;
    }
  }
  cmd.braking = true;
  cmd.releases = releases;
  cmd.target_acceleration = lo;
  if (releases) {
    const SpeedStep next = slow_down_step(v, a, 0.0, lo, jerk, dt);
    cmd.commanded_velocity = next.speed;
    cmd.commanded_acceleration = next.accel;
  } else {
    const Motion next = advance(v, a, lo, jerk, dt);
    cmd.commanded_velocity = next.v;
    cmd.commanded_acceleration = next.a;
  }
}

}  // namespace

std::string_view to_string(StopLevel level) {
  switch (level) {
    case StopLevel::Normal: return "normal";
    case StopLevel::Limit: return "limit";
    case StopLevel::Emergency: return "emergency";
  }
  return "invalid";
}

void validate(const StopPlannerParameters& p) {
  validate_set(p.normal, "normal");
  validate_set(p.limit, "limit");
  validate_set(p.emergency, "emergency");
  if (!(p.brake_start_ratio > 0.0 && p.brake_start_ratio <= 1.0)) {
    throw std::invalid_argument("stop planner parameter brake_start_ratio must be in (0, 1]");
  }
}

double stopping_distance(double v, double a, double target_acc, double jerk) {
  if (v <= 0.0) return 0.0;
  const Ramp r = ramp(a, target_acc, jerk);
  const double a0 = std::isinf(jerk) ? target_acc : a;
  // Stops during the ramp?
  if (const auto t = first_stop_time(v, a0, r.s, r.t)) {
    return v * *t + 0.5 * a0 * *t * *t + r.s * *t * *t * *t / 6.0;
  }
  const double x1 = v * r.t + 0.5 * a0 * r.t * r.t + r.s * r.t * r.t * r.t / 6.0;
  const double v1 = v + a0 * r.t + 0.5 * r.s * r.t * r.t;
  if (v1 <= 0.0) return x1;
  if (target_acc >= 0.0) return kInf;
  return x1 + v1 * v1 / (-2.0 * target_acc);
}

double min_stopping_distance(double v, double a, const StopConstraintSet& c) {
  return stopping_distance(v, a, c.min_acc, std::abs(c.min_jerk));
}

bool is_stop_feasible(double v, double a, double distance, const StopConstraintSet& c) {
  return min_stopping_distance(std::max(0.0, v), a, c) <= distance + kDistanceTolerance;
}

StopCommand plan_stop(const StopPlannerInput& in, const StopPlannerParameters& params) {
  validate(params);
  require_finite(in.velocity, "velocity");
  require_finite(in.acceleration, "acceleration");
  require_finite(in.distance_to_stop, "distance_to_stop");
  require_finite(in.dt, "dt");
  if (!(in.dt > 0.0)) throw std::invalid_argument("plan_stop: dt must be > 0");

  const double v = std::max(0.0, in.velocity);
  const double a = in.acceleration;
  const double D = in.distance_to_stop;
  StopCommand cmd;

  // Cruise at the lane limits' speed while a normal stop from where that step leads stays possible
  // with the tracking margin: a stop far ahead never holds the speed down (docs/behaviour.md §L3, inserted
  // profile 4).
  if (in.cruise_velocity) {
    require_finite(*in.cruise_velocity, "cruise_velocity");
    const double vc = std::max(0.0, *in.cruise_velocity);
    const double ac = (vc - v) / in.dt;
    const double jerk = std::abs(params.normal.min_jerk);
    // From rest the ego pulls away only for a stop more than kPullAwayDistance ahead: a gentle start
    // would otherwise creep the last centimetres to a stop point it rests just short of.
    const bool pulls_away = v > kStoppedVelocity || D > kPullAwayDistance;
    if (vc > kStoppedVelocity && pulls_away && is_stop_feasible(v, a, D, params.normal) &&
        ride_stop_distance(vc, ac, params.brake_start_ratio * params.normal.min_acc, jerk) <=
            D - std::max(v, vc) * in.dt) {
      cmd.level = StopLevel::Normal;
      cmd.feasible = true;
      cmd.braking = false;
      cmd.commanded_velocity = vc;
      cmd.commanded_acceleration = ac;
      cmd.stopping_distance = min_stopping_distance(v, a, params.normal);
      return cmd;
    }
  }

  // Standing: hold (the stop constrains the ego only at or past the stop point).
  if (v <= kStoppedVelocity) {
    cmd.level = StopLevel::Normal;
    cmd.feasible = true;
    cmd.braking = D <= 0.0;
    cmd.commanded_velocity = cmd.braking ? 0.0 : v;
    return cmd;
  }

  const std::array<std::pair<StopLevel, StopConstraintSet>, 3> levels = {
      {{StopLevel::Normal, params.normal}, {StopLevel::Limit, params.limit}, {StopLevel::Emergency, params.emergency}}};

  for (const auto& [level, set] : levels) {
    if (!is_stop_feasible(v, a, D, set)) continue;
    const double s_min = min_stopping_distance(v, a, set);

    cmd.level = level;
    cmd.feasible = true;
    cmd.stopping_distance = s_min;
    const double jerk = std::abs(set.min_jerk);

    // Hold the speed while the normal level, less its tracking margin, can still stop after one more
    // step; an acceleration still on is released at the level's jerk.
    if (level == StopLevel::Normal && a >= kBrakingAcceleration) {
      const SpeedStep held = release_acceleration(v, a, jerk, in.dt);
      if (ride_stop_distance(held.speed, held.accel, params.brake_start_ratio * set.min_acc, jerk) <=
          D - std::max(v, held.speed) * in.dt) {
        cmd.braking = false;
        cmd.commanded_velocity = held.speed;
        cmd.commanded_acceleration = held.accel;
        cmd.target_acceleration = 0.0;
        return cmd;
      }
    }

    exact_stop(cmd, v, a, D, set.min_acc, jerk, s_min, in.dt);
    return cmd;
  }

  // Not even the emergency level stops in time: brake as hard as the vehicle can.
  cmd.level = StopLevel::Emergency;
  cmd.feasible = false;
  cmd.braking = true;
  cmd.stopping_distance = min_stopping_distance(v, a, params.emergency);
  const Motion next = advance(v, a, params.emergency.min_acc, std::abs(params.emergency.min_jerk), in.dt);
  cmd.target_acceleration = params.emergency.min_acc;
  cmd.commanded_velocity = next.v;
  cmd.commanded_acceleration = next.a;
  return cmd;
}

}  // namespace signalsim
