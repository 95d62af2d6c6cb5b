// Jerk-limited stop planner with relaxation levels (docs/behaviour.md §L2.7, §L0 "dilemma zone"):
// bring the ego to rest at a stop point, with the first constraint set that can still do it:
// normal (-1.0 m/s^2, -1.0 m/s^3), then limit (-2.5, -1.5) (Autoware common.param.yaml), then the
// vehicle's emergency deceleration with unbounded jerk. Pure functions and value types only.
//
// Profile model ("ramp then hold"): from the current (v, a) the acceleration moves at the level's
// jerk magnitude J toward a target a_t in [min_acc, 0), then holds a_t until standstill; with
// unbounded jerk it jumps to a_t at once. Its stopping distance S(v, a, a_t, J) grows as a_t -> 0,
// so the exact-stop target is found by bisection. The level's minimum stopping distance is
// S(v, a, min_acc, J): the level is feasible iff that is <= distance (+ 1 cm tolerance). With a > 0
// the ramp starts from the positive acceleration (the ego still speeds up while the ramp crosses 0).
//
// plan_stop(in) each step (r = brake_start_ratio, margin: a normal stop that needs only r * min_acc;
// from rest the cruise rule applies only to a stop more than 1 m ahead, as restart suppression):
//   if a cruise speed v_c is given (what the lane limits command without the stop), the normal
//   level is feasible from (v, a), and after one step at v_c -- state (v_c, a_c = (v_c - v) / dt),
//   max(v, v_c) dt further on -- S(v_c, a_c, r * normal.min_acc, J) <= distance - max(v, v_c) dt:
//                            cruise: commanded v_c (braking = false); a far stop does not hold the
//                            ego down (docs/behaviour.md §L3, inserted profile 4: before the stop point the
//                            path keeps its speed limits, the smoother brakes when it must)
//   if v <= 1e-3:            hold 0 (braking iff distance <= 0); level Normal, feasible
//   level := first of (normal, limit, emergency) with S_min(level) <= distance + 1 cm
//   if none:                 level Emergency, infeasible: brake at emergency min_acc
//   if level == normal and a >= -1e-3 (not braking yet), and from the holding step (v_h, a_h) --
//      the acceleration released toward 0 at J -- S(v_h, a_h, r * normal.min_acc, J) <= distance - v dt:
//                            hold: commanded v_h (braking = false; braking can still start next step)
//   else:                    a_t := solve S(v, a, a_t, J) = distance on [min_acc, 0)
//                            commanded := the profile's speed and acceleration after dt
// With a finite jerk the profile a step follows releases the deceleration at J as the ego comes to
// rest ("ramp, hold, ramp out", planning/stop/jerk_limited_speed.hpp, docs/behaviour.md §P1.2): the
// cruise, hold and exact-stop rules use its distance S'(v, a, a_t, J) >= S, and the exact stop falls
// back to S (held to rest, a jolt at standstill) only when S'(min_acc) no longer fits. The level's
// feasibility stays S_min, the judge's distance.
// So braking starts as late as the normal level allows, less a tracking margin (like a velocity
// smoother tracking the speed limit), also when the ego was accelerating (the cruise test uses the
// acceleration the cruise command leads to), and at once, as gently as possible, when only a
// relaxed level can still stop. Without a cruise speed the first rule is skipped (the speed is held).
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>

namespace signalsim {

/// Which constraint set a stop uses (the timeline records it; docs/behaviour.md §L0).
enum class StopLevel : std::uint8_t { Normal, Limit, Emergency };

std::string_view to_string(StopLevel level);

/// One constraint set (Autoware's common.param.yaml names; both negative).
struct StopConstraintSet {
  double min_acc = -1.0;   ///< [m/s^2] strongest deceleration allowed, < 0
  double min_jerk = -1.0;  ///< [m/s^3] strongest jerk allowed, < 0; -infinity = unbounded
};

struct StopPlannerParameters {
  StopConstraintSet normal{-1.0, -1.0};  ///< [LAUNCH] common.param.yaml `normal`
  StopConstraintSet limit{-2.5, -1.5};   ///< [LAUNCH] common.param.yaml `limit`
  /// Vehicle emergency deceleration, jerk unbounded. Default: SUMO's passenger emergencyDecel 9.0;
  /// the SUMO adapter should pass the ego vType's emergencyDecel.
  StopConstraintSet emergency{-9.0, -std::numeric_limits<double>::infinity()};
  /// (0, 1]: a normal stop starts braking once its exact-stop target deceleration reaches
  /// brake_start_ratio * normal.min_acc. The remaining share is tracking margin, so the normal level
  /// stays feasible while a point mass with measured (step-averaged) acceleration follows the plan.
  double brake_start_ratio = 0.9;
};

/// Throws std::invalid_argument unless every min_acc is finite and < 0, every min_jerk is < 0
/// (finite or -infinity) and brake_start_ratio is in (0, 1].
void validate(const StopPlannerParameters& params);

struct StopPlannerInput {
  double velocity = 0.0;          ///< [m/s] current speed v (>= 0 expected; negative counts as 0)
  double acceleration = 0.0;      ///< [m/s^2] current acceleration a
  double distance_to_stop = 0.0;  ///< [m] from the reference point to where it must come to rest
  double dt = 0.1;                ///< [s] step length, > 0
  /// [m/s] the speed the ego would be commanded without this stop (the lane limits' plan for this
  /// step, its acceleration included); empty: the stop holds the current speed until it must brake.
  std::optional<double> cruise_velocity;
};

struct StopCommand {
  StopLevel level = StopLevel::Normal;  ///< first feasible level (Emergency if none)
  bool feasible = true;   ///< false: even the emergency level overshoots the stop point
  bool braking = false;   ///< false: the stop does not constrain the speed yet (cruise or hold)
  bool releases = false;  ///< braking on a profile that releases the deceleration as it comes to rest
  double commanded_velocity = 0.0;      ///< [m/s] speed to reach at the end of this step, >= 0
  double commanded_acceleration = 0.0;  ///< [m/s^2] plan's acceleration at the end of the step
  double target_acceleration = 0.0;     ///< [m/s^2] a_t of the plan (0 when not braking)
  double stopping_distance = 0.0;       ///< [m] the chosen level's minimum stopping distance
};

/// Stopping distance of the ramp-then-hold profile (see top). `jerk` is a magnitude (> 0,
/// +infinity = jump). Returns 0 for v <= 0 and +infinity if a_t >= 0 and the ramp does not stop
/// the vehicle. Never throws.
double stopping_distance(double v, double a, double target_acc, double jerk);

/// Minimum stopping distance within a constraint set: stopping_distance(v, a, c.min_acc, |c.min_jerk|).
double min_stopping_distance(double v, double a, const StopConstraintSet& c);

/// Whether the set can bring (v, a) to rest within `distance`: min_stopping_distance <= distance
/// + 1 cm (tolerance against step discretisation). Never throws.
bool is_stop_feasible(double v, double a, double distance, const StopConstraintSet& c);

/// One step of the planner (algorithm at the top). Throws std::invalid_argument if dt <= 0, an
/// input (the cruise speed included) is not finite, or validate(params) throws.
StopCommand plan_stop(const StopPlannerInput& in, const StopPlannerParameters& params = {});

}  // namespace signalsim
