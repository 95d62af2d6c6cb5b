// The room a lane change has on a route edge, and whether a lane change fits in it: one definition,
// used by the lane plan (sumo/lane_plan, to choose where the changes go) and by the lateral planner
// (scenario/route_planning, to time them). SUMO-free and pure.
//
// Room: the base_link travel over which the lateral motion may run with the front bumper still on
// the edge (no lateral command on internal lanes, docs/maneuvers.md): from where base_link
// may start (the edge's start; on the first edge its depart position) to the edge's end minus
// base_link_to_front. A lane change the route needs is timed by default_lane_change within it.
//
// Fit: the default lane change's length must be at least min_lane_change_length for its shift: a
// car can follow the quintic shift (planning/shift_line.hpp, peak curvature (10/sqrt 3) d / L^2)
// only while that curvature stays below the sharpest it can drive at its speed, the lesser of its
// steering limit 1 / kMinTurningRadius and the grip limit a_lat / v^2. The speed is the one the ego
// has over the lane change (lane_change_speed): under the edge's limit and its maximum, what it can
// have gained since the turn onto the edge and what still lets it brake for the turn off it.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "core/vehicle_defaults.hpp"

namespace signalsim::sumo {

inline constexpr double kLaneChangeLead = 20.0;       ///< [m] default start after base_link may start
inline constexpr double kLaneChangeLength = 50.0;     ///< [m] default length of the lateral motion
inline constexpr double kLaneChangeEndMargin = 1.0;   ///< [m] it ends this far before the front leaves
inline constexpr double kMinLaneChangeLength = 5.0;   ///< [m] never shorter, whatever the shift
/// [m] The tightest radius a passenger car steers: Autoware's sample vehicle, wheel_base 2.79 m and
/// max_steer_angle 0.70 rad (2.79 / tan 0.70).
inline constexpr double kMinTurningRadius = 3.31;

/// What limits a lane change of the ego (the defaults are scenario's EgoSpec defaults).
struct LaneChangeEgo {
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< [m]
  double depart_pos = 0.0;          ///< [m] front bumper on the first edge
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< [m/s] the ego drives no faster, nor faster than the lane
  double accel = 1.0;               ///< [m/s^2] its planned acceleration (ego.accel)
  double decel = 1.0;               ///< [m/s^2] its planned deceleration (ego.decel)
  double depart_speed = -1.0;       ///< [m/s] on the first edge; < 0: unknown (max_speed)
  double max_lateral_accel = 9.0;   ///< [m/s^2] its grip (ego.emergency_decel: the same tyres)
  /// The lane the ego is on when it enters the first edge, when that is not signalsim's choice (a
  /// taken-over vehicle departs where SUMO put it); -1: the plan chooses.
  int first_lane = -1;
  /// Its SUMO vehicle class: the lanes it may use (signalsim's own ego is a passenger car; a
  /// taken-over vehicle has its vType's).
  std::string vclass = "passenger";
  /// SUMO's look-ahead for its lane choice at junctions (sumo_lane_choice.hpp): the vType's decel
  /// [m/s^2] (signalsim's own ego: 4.5) and the step length [s].
  double sumo_decel = vehicle_defaults::kSumoDecel;
  double step_length = 0.1;
};

/// What a lane change on one route edge has.
struct EdgeRoom {
  double room = std::numeric_limits<double>::infinity();  ///< lane_change_room [m]
  std::vector<double> widths;                              ///< lane widths by index [m]
  double speed = 0.0;  ///< the ego's speed over its default lane change there (lane_change_speed) [m/s]
};

/// The limits around a route edge a lane change's speed depends on [m/s].
struct EdgeSpeeds {
  double limit = std::numeric_limits<double>::infinity();  ///< the edge's fastest lane
  /// The turn onto the edge (its internal lane's limit) and the turn off it; infinity: none (the
  /// route's first or last edge, a net without internal lanes).
  double entry = std::numeric_limits<double>::infinity();
  double exit = std::numeric_limits<double>::infinity();
};

/// The highest speed the ego has over the default lane change on an edge of `edge_length`
/// (`first`: the route's first edge): min(max_speed, limit, sqrt(entry^2 + 2 accel x),
/// sqrt(exit^2 + 2 decel (length - x))) over the front's positions x of the lateral motion; on the
/// first edge the entry is the departure (depart_speed at depart_pos).
double lane_change_speed(double edge_length, bool first, const EdgeSpeeds& speeds, const LaneChangeEgo& ego);

/// One lateral motion of a lane plan: on route edge `edge`, from lane `from_lane` to `to_lane`.
struct PlannedLaneChange {
  std::size_t edge_index = 0;
  std::string edge;
  int from_lane = 0;
  int to_lane = 0;
  double room = 0.0;        ///< lane_change_room [m]
  double shift = 0.0;       ///< lane_shift [m], >= 0
  double min_length = 0.0;  ///< min_lane_change_length [m]
  double length = 0.0;      ///< the default lane change's length in this room [m]
  bool fits = false;        ///< length >= min_length
};

/// Room on a route edge of `edge_length`; `first`: the route's first edge (base_link starts at
/// depart_pos - base_link_to_front). Can be negative (no room at all).
double lane_change_room(double edge_length, bool first, const LaneChangeEgo& ego);

/// The default timing within `room`: the lateral motion starts `lead` after base_link may start
/// (min(kLaneChangeLead, 20 % of the room)) and lasts `length` (min(kLaneChangeLength, the rest
/// less kLaneChangeEndMargin)).
struct LaneChangeTimingDefault {
  double lead = 0.0;
  double length = 0.0;
};
LaneChangeTimingDefault default_lane_change(double room);

/// Lateral distance [m] between the centres of lanes `from` and `to` of an edge with these lane
/// widths (by index), >= 0.
double lane_shift(const std::vector<double>& widths, int from, int to);

/// The shortest lateral motion [m] that shifts `shift` metres drivably at `speed` (see above).
double min_lane_change_length(double shift, double speed, const LaneChangeEgo& ego);

/// The least room whose default lane change is `length` long; infinity beyond kLaneChangeLength.
double lane_change_room_needed(double length);

/// Whether the default lane change in `room` is at least min_lane_change_length long.
bool lane_change_fits(double room, double shift, double speed, const LaneChangeEgo& ego);

}  // namespace signalsim::sumo
