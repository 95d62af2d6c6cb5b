// Lateral maneuvers as shift lines on the route coordinate s (lane change, avoidance, pull out,
// pull over). The turn-signal side (turn_signal/behavior_signal.hpp) only needs the four numbers of a
// line; this file adds the lateral profile the ego actually drives.
//
// Conventions
// - s is base_link's route position [m]. A shift line says where base_link moves sideways.
// - Offsets are lateral, left positive, metres from the centre line of the *reference lane* (the
//   lane the maneuver is planned on: the original lane for a lane change or an avoidance, the
//   driving lane for a pull out or pull over). This is the arc-coordinate convention of docs/behaviour.md §T8.1.
//
// Profile: quintic minimum-jerk blend
//   offset(s) = a + (b - a) * B(u),  u = (s - s_start) / (s_end - s_start),  B(u) = 10u^3 - 15u^4 + 6u^5
// B is monotone on [0, 1], B(0) = 0, B(1) = 1, and its first and second derivatives vanish at both
// ends, so a plan of several lines is C2 (position, heading and curvature continuous) at every joint.
// Peak slope dB/du = 15/8 at u = 1/2. At a constant speed v over a line of length L (time T = L/v),
// the peak lateral acceleration is (10/sqrt(3)) |b-a| / T^2 and the peak lateral jerk 60 |b-a| / T^3.
// Autoware's PathShifter uses a piecewise-cubic jerk-limited profile instead; the quintic is smooth,
// closed-form and monotone, and ShiftLengthPolicy sizes it so that the stated jerk and acceleration
// limits are the true peaks of the quintic (which makes it about 23 % longer than Autoware's
// T = 4 (|b-a| / 2j)^(1/3) for the same jerk).
#pragma once

#include <optional>
#include <vector>

#include "core/vehicle_defaults.hpp"

namespace signalsim {

/// The minimum-jerk blend B(u) on [0, 1] (clamped outside).
double shift_blend(double u);
/// dB/du (0 outside [0, 1]).
double shift_blend_derivative(double u);

/// One lateral shift from `shift_start` at `s_start` to `shift_end` at `s_end`.
struct ShiftLine {
  double s_start = 0.0;      ///< route s where the lateral motion begins [m]
  double s_end = 0.0;        ///< route s where it ends [m], >= s_start
  double shift_start = 0.0;  ///< lateral offset at s_start [m], left positive
  double shift_end = 0.0;    ///< lateral offset at s_end [m], left positive

  double length() const { return s_end - s_start; }
  /// shift_end - shift_start: > 0 moves left.
  double relative_shift() const { return shift_end - shift_start; }

  /// Lateral offset at s: shift_start before the line, shift_end after it. A zero-length line
  /// jumps at s_start (shift_end from s_start on).
  double offset_at(double s) const;
  /// Lateral slope d(offset)/ds at s (0 outside the line). atan of it is the yaw relative to the lane.
  double heading_at(double s) const;
  /// The first s in [s_start, s_end] where the offset reaches `offset` (the profile is monotone),
  /// or nullopt when `offset` lies outside [min(shift_start, shift_end), max(...)].
  /// Used for the lane change's required end: where the path crosses the adjacent lane's boundary.
  std::optional<double> s_at_offset(double offset) const;
};

/// An ordered list of non-overlapping shift lines: the lateral plan of one maneuver.
class ShiftPlan {
 public:
  ShiftPlan() = default;
  /// Throws std::invalid_argument when a line has s_end < s_start or the lines are not ordered and
  /// non-overlapping (lines[i].s_end <= lines[i+1].s_start).
  explicit ShiftPlan(std::vector<ShiftLine> lines);

  const std::vector<ShiftLine>& lines() const { return lines_; }
  bool empty() const { return lines_.empty(); }

  /// Piecewise: before the first line its shift_start; inside a line its profile; between two lines
  /// the previous line's shift_end; after the last line its shift_end. 0 for an empty plan.
  double offset_at(double s) const;
  /// Lateral slope at s (0 outside every line).
  double heading_at(double s) const;

 private:
  std::vector<ShiftLine> lines_;
};

/// How long (in s) a shift of a given lateral size is. Either a fixed longitudinal length, or the
/// shortest length at which the quintic's peak lateral jerk and acceleration at `speed` stay within
/// the limits, never shorter than `min_length`.
struct ShiftLengthPolicy {
  double fixed_length = 0.0;   ///< > 0: every shift has this length [m] (jerk/accel ignored)
  double lateral_jerk = 0.5;   ///< peak lateral jerk [m/s^3] (Autoware lane_change lateral_jerk)
  double lateral_accel = 0.5;  ///< peak lateral acceleration [m/s^2]; <= 0 disables the limit
  double min_length = 10.0;    ///< lower bound [m] (also the length at standstill)

  /// Length [m] for a lateral shift of |lateral| metres driven at `speed` [m/s].
  double length_for(double lateral, double speed) const;
};

/// The shortest time [s] in which the quintic shifts |lateral| metres with peak jerk <= `jerk` and
/// (if accel > 0) peak acceleration <= `accel`. 0 for a zero shift.
double shift_time_from_limits(double lateral, double jerk, double accel);

/// A lane change of signed width `width` (left positive: the target lane's centre seen from the
/// reference lane's centre) over `length` metres starting at s0: one line 0 -> width.
ShiftPlan plan_lane_change(double s0, double width, double length);

/// Which side the ego passes an obstacle on.
enum class AvoidSide { Auto, Left, Right };

/// An avoidance around an obstacle on the reference lane.
struct AvoidanceRequest {
  double s_object_start = 0.0;  ///< route s of the obstacle's rear end [m]
  double s_object_end = 0.0;    ///< route s of the obstacle's front end [m]
  double object_left = 0.0;     ///< lateral position of the obstacle's left edge [m]
  double object_right = 0.0;    ///< lateral position of the obstacle's right edge [m]
  double clearance = 1.0;       ///< lateral gap kept between the ego's side and the obstacle [m]
  double vehicle_width = vehicle_defaults::kWidth;  ///< [m]
  AvoidSide side = AvoidSide::Auto;  ///< Auto: pass on the side away from the obstacle's centre (left if centred)
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< the shift out ends when the front reaches the margin [m]
  double rear_overhang = 0.8;        ///< the return starts when the rear has passed the margin [m]
  double longitudinal_margin = 1.0;  ///< kept ahead of / behind the obstacle [m]
  double speed = 0.0;                ///< planning speed for the length policy [m/s]
  ShiftLengthPolicy lengths;
};

/// Lateral target while passing: left of the obstacle at object_left + clearance + width/2, or right
/// of it at object_right - clearance - width/2.
double avoidance_offset(const AvoidanceRequest& request);

/// Shift out, hold, shift back (two lines): the shift out ends at
/// s_object_start - longitudinal_margin - base_link_to_front; the return starts at
/// s_object_end + longitudinal_margin + rear_overhang. When the two would overlap (a short gap), the
/// hold shrinks to nothing and both lines meet at the midpoint.
ShiftPlan plan_avoidance(const AvoidanceRequest& request);

/// A pull out from the road-side offset `start_offset` back to the lane centre (0) over `length`
/// metres starting at s0.
ShiftPlan plan_pull_out(double s0, double start_offset, double length);

/// A pull over from the lane centre (0) to the road-side offset `goal_offset`, ending at the goal s.
ShiftPlan plan_pull_over(double s_goal, double goal_offset, double length);

}  // namespace signalsim
