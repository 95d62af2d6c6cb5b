// Jerk-limited speed changes of the ride (docs/behaviour.md §P1): how the ego reaches a cruise speed,
// and how it slows down to a lower speed limit that begins at a point ahead, with its acceleration
// within [-decel, accel] and the acceleration's rate within the jerk. Pure functions, value types.
//
// Profile of a slow-down ("ramp, hold, ramp out"): from (v, a) the acceleration moves at jerk J to a
// target a_t < 0, holds a_t, and moves back to 0 at J, so the speed ends at the limit v_f with no
// acceleration left (no jolt where the lower limit begins). When the speed to shed is too small to
// reach a_t, the profile is a triangle whose peak is shallower than a_t; when the ego already
// brakes so hard that releasing the brake at J sheds more than needed, it only releases (it ends
// a little below v_f). Its distance D(v, a, v_f, a_t, J) grows as a_t -> 0.
//
// plan_slow_down, each step (the same rules as the stop planner's plan_stop, planning/stop, with
// the ego's decel and the ride's jerk in place of a constraint set, and r = kBrakeStartRatio):
//   v <= v_f:                 cruise while v_c + a_c^2 / 2J <= v_f (its acceleration can still be
//                             released below the limit), else approach v_f from below (track_speed)
//   the cruise step (v_c, a_c) keeps D(v_c, a_c, v_f, r * -decel, J) <= d - max(v, v_c) dt
//                             and the slow-down is feasible from (v, a): cruise
//   not feasible from (v, a) even at -decel: brake at -decel (jerk-limited); the ego arrives late
//   the holding step (release_acceleration) keeps the same test: hold
//   else:                     the gentlest a_t in [-decel, 0) with D <= d; one step along it
// track_speed approaches a speed from either side: the acceleration moves at most J dt per step
// toward +-sqrt(2 J |gap|) (clamped to accel / -decel), so it is back at 0 as the speed arrives.
//
// Speeds follow a linear acceleration ramp over the step: v1 = v + (a + a1) dt / 2, which is what
// SUMO reports as the step's acceleration ((v1 - v) / dt, the mean): its jerk between rows is J.
#pragma once

namespace signalsim {

/// [m/s^3] The ride's jerk: Autoware's `normal` constraint set (common.param.yaml max_jerk 1.0,
/// min_jerk -1.0), the one the stop planner's normal level uses.
inline constexpr double kRideJerk = 1.0;
/// Share of the ego's decel a slow-down plans with before it must brake (the rest is tracking
/// margin), as the stop planner's brake_start_ratio.
inline constexpr double kBrakeStartRatio = 0.9;

/// The ego's acceleration limits (all > 0).
struct RideLimits {
  double accel = 1.0;       ///< [m/s^2]
  double decel = 1.0;       ///< [m/s^2]
  double jerk = kRideJerk;  ///< [m/s^3]
};

/// The state a step's command leads to: the speed at its end and the acceleration the profile has there.
struct SpeedStep {
  double speed = 0.0;  ///< [m/s]
  double accel = 0.0;  ///< [m/s^2]
};

/// Distance [m] of the slow-down from (v, a) to v_f with target a_t (< 0) and jerk (> 0); 0 when
/// v <= v_f. Never throws.
double slow_down_distance(double v, double a, double v_f, double a_t, double jerk);

/// The state after dt along the slow-down from (v, a) to v_f with target a_t (< 0); past the
/// profile's end v_f is held with no acceleration. With v_f = 0 it is a stop whose deceleration is
/// released as the ego comes to rest (the stop planner's profile where the distance allows).
SpeedStep slow_down_step(double v, double a, double v_f, double a_t, double jerk, double dt);

/// One step of length dt that releases the acceleration a toward 0 at `jerk` (a hold of the speed
/// that is still speeding up or slowing down: it changes a^2 / 2 jerk more).
SpeedStep release_acceleration(double v, double a, double jerk, double dt);

/// One step of length dt from (v, a) toward `target` speed (see the top).
SpeedStep track_speed(double v, double a, double target, const RideLimits& limits, double dt);

struct SlowDownStep {
  SpeedStep step;
  bool binds = false;     ///< the limit lowers the speed below the cruise step
  bool feasible = true;   ///< false: even -decel arrives above v_f
};

/// One step under a speed limit v_f beginning `distance` [m] ahead, from (v, a), when the ego
/// would otherwise take `cruise` (see the top).
SlowDownStep plan_slow_down(double v, double a, double v_f, double distance, const SpeedStep& cruise,
                            const RideLimits& limits, double dt);

}  // namespace signalsim
