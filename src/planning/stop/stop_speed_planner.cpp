#include "planning/stop/stop_speed_planner.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace signalsim {

namespace {

constexpr double kTrackingTolerance = 0.01;  // [m/s] SUMO followed the last command this closely
constexpr double kSettleDistance = 0.02;     // [m] this close to the stop point the ego is brought to rest

}  // namespace

StopSpeedPlanner::StopSpeedPlanner(const StopPlannerParameters& params, double emergency_decel)
    : params_(params), emergency_decel_(emergency_decel) {
  validate(params_);
  if (!(emergency_decel_ > 0.0)) throw std::invalid_argument("StopSpeedPlanner: emergency_decel must be > 0");
}

double StopSpeedPlanner::begin_step(double measured_speed, double measured_accel, double dt) {
  v_ = measured_speed;
  dt_ = dt;
  const bool tracked = last_command_ && std::abs(measured_speed - *last_command_) <= kTrackingTolerance;
  start_accel_ = tracked ? last_end_accel_ : std::clamp(measured_accel, start_low_, start_high_);
  speed_ = cruise_ = measured_speed;
  end_accel_ = 0.0;
  return start_accel_;
}

void StopSpeedPlanner::set_cruise(double limits_speed, double limits_end_accel) {
  speed_ = limits_speed;
  cruise_ = limits_speed;
  end_accel_ = limits_end_accel;
}

std::optional<StopLevel> StopSpeedPlanner::add_stop(double to_go) {
  const StopCommand stop = plan_stop({v_, start_accel_, to_go, dt_, speed_}, params_);
  // Planned from the cruise speed itself (no earlier stop lowered it), this is also its speed alone.
  last_alone_ = speed_ == cruise_ ? std::min(cruise_, stop.commanded_velocity) : speed_alone(to_go);
  std::optional<StopLevel> level;
  if (stop.braking || stop.commanded_velocity < speed_) {
    if (stop.commanded_velocity < speed_) {
      speed_ = stop.commanded_velocity;
      end_accel_ = stop.commanded_acceleration;
    }
    level = stop.level;
  }
  // Within 2 cm: come to rest (coarse steps never settle), if the emergency deceleration can shed
  // the speed in this step; past the point faster than that, the planner's braking stands. Up to
  // twice what the normal deceleration sheds in a step, it brakes at that deceleration (two steps,
  // under 2 cm further) rather than with a last-step jolt beyond the normal set. A profile that
  // releases its deceleration at rest settles by itself.
  const double normal_step = -params_.normal.min_acc * dt_;
  if (to_go < kSettleDistance && v_ <= emergency_decel_ * dt_ && !stop.releases) {
    const double settle = v_ <= 2.0 * normal_step ? std::max(0.0, v_ - normal_step) : 0.0;
    if (settle < speed_) {
      speed_ = settle;
      end_accel_ = (settle - v_) / dt_;
    }
  }
  return level;
}

double StopSpeedPlanner::speed_alone(double to_go) const {
  return std::min(cruise_, plan_stop({v_, start_accel_, to_go, dt_, cruise_}, params_).commanded_velocity);
}

void StopSpeedPlanner::end_step(double commanded_speed) {
  last_end_accel_ = commanded_speed == speed_ ? end_accel_ : (commanded_speed - v_) / dt_;
  if (commanded_speed <= 0.0) last_end_accel_ = 0.0;  // at rest the profile has no acceleration left
  last_command_ = commanded_speed;
}

}  // namespace signalsim
