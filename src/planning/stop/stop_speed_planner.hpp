// One step's speed command under the stops ahead (the step loop's plan stage, docs/run.md): the lane
// limits' speed, lowered by a jerk-limited stop (plan_stop) for every stop point this step (a red
// light, a pull-over goal, a lane change's hold point), each planned with that speed as its cruise
// speed, so a far stop never holds the ego down. It owns the one piece of state the stops share:
// the acceleration their profiles start from.
//
//   begin_step(v, a_measured, dt) -> a_0
//     a_0 := the end-of-step acceleration of the previous step's command, while SUMO followed that
//            command (|v - command| <= 1 cm/s); else a_measured within the start bounds (SUMO braked
//            harder for a leader: the plan does not carry that on; the lane limits plan from a_0 too)
//   set_cruise(v_limits, a_limits): speed := v_limits, ending the step at a_limits
//   add_stop(d), for each stop:
//     c := plan_stop({v, a_0, d, dt, cruise = speed})
//     if c.braking or c.commanded_velocity < speed: speed := min(speed, c.commanded_velocity);
//                                                    returns c.level (the stop constrains the speed)
//     if d < 2 cm and v <= emergency_decel * dt:    settle: speed := 0, or v - 1 step of the normal
//                                                    deceleration when v is at most 2 such steps
//   end_step(command): remembers the command and the acceleration it ends the step with
//
// Why a_0 is not simply the measured acceleration: SUMO reports the step's mean, (v1 - v0) / dt,
// which on a jerk ramp lags the profile's end-of-step value by J dt / 2. Planning every step from
// the mean halves the ramp's jerk in effect, the profile falls behind and a stop that began at the
// normal level needs the limit level near its end (seen from rest 40 m before a red light). Like
// a velocity smoother, the plan continues from its own previous output while the ego tracks it.
#pragma once

#include <optional>

#include "planning/stop/jerk_limited_stop.hpp"

namespace signalsim {

class StopSpeedPlanner {
 public:
  /// `emergency_decel` [m/s^2, > 0] bounds the settle rule (the ego is brought to rest within 2 cm
  /// of a stop point only if it can shed its speed in one step). Throws std::invalid_argument if
  /// validate(params) throws or emergency_decel is not > 0.
  StopSpeedPlanner(const StopPlannerParameters& params, double emergency_decel);

  /// Starts a step from SUMO's measured speed and acceleration; returns the acceleration the
  /// step's profiles start from (see the top).
  double begin_step(double measured_speed, double measured_accel, double dt);

  /// The speed the lane limits allow this step and the acceleration it ends the step with.
  void set_cruise(double limits_speed, double limits_end_accel);

  /// A stop point `to_go` [m] ahead of the reference point (negative: behind it). Returns the
  /// constraint set used when this stop lowers the speed this step, else nothing.
  std::optional<StopLevel> add_stop(double to_go);

  /// Bounds of a_0 when SUMO did not follow the last command [m/s^2] (default: none).
  void set_start_bounds(double lowest, double highest) {
    start_low_ = lowest;
    start_high_ = highest;
  }

  /// The speed this stop alone would command [m/s] (planned from the lane limits' speed, not from
  /// the other stops): which of several stops sets the speed.
  double speed_alone(double to_go) const;

  /// speed_alone of the stop add_stop planned last (computed there once).
  double last_speed_alone() const { return last_alone_; }

  /// The speed to command for this step [m/s]: the lane limits' speed under every stop added.
  double speed() const { return speed_; }

  /// The acceleration this step's profiles started from [m/s^2] (see the top).
  double start_acceleration() const { return start_accel_; }

  /// Ends the step with the speed really commanded (speed(), or an override such as 0 while backing).
  void end_step(double commanded_speed);

 private:
  StopPlannerParameters params_;
  double emergency_decel_;
  // this step
  double v_ = 0.0;
  double dt_ = 0.1;
  double start_accel_ = 0.0;
  double speed_ = 0.0;
  double cruise_ = 0.0;     // the lane limits' speed of this step
  double last_alone_ = 0.0; // speed_alone of the last stop added
  double end_accel_ = 0.0;  // the acceleration speed_ ends the step with
  // the previous step's command
  std::optional<double> last_command_;
  double start_low_ = -1e9, start_high_ = 1e9;
  double last_end_accel_ = 0.0;
};

}  // namespace signalsim
