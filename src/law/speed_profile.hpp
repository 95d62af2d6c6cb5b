// The ego's speed along its route as the generator predicts it, from the rules alone (no SUMO run):
//
//   planned   the step loop's own speed planner (planning/speed_limit_planner: lane limits ahead,
//             accel / decel) rolled out from the departure with SUMO's position update
//             (s += v_new * dt): the speed the ego commands when nothing stops it.
//   upper     planned + kSpeedSlack: the ego is never faster (SUMO can only slow it).
//   lower     what the ego has at least, when it may have to stop on the way:
//               0 in every stop zone [p - braking distance, p] before a point p where it may stop
//               (a light's stop line: the judge may stop it, docs/behaviour.md §L; a link where SUMO makes it
//               yield: minor, stop, all-way stop, zipper, blinking light), and after p at most the
//               restart from rest sqrt(2 * kRestartShare * accel * (s - p - ramp)), ramp =
//               accel^3 / (3 jerk^2) (the jerk-limited start), and no more than the lowest limit
//               within a braking distance ahead (accelerating from below, the ego approaches a
//               lower limit ahead without passing it, docs/behaviour.md §P1.3);
//             the lesser of that and planned - kSpeedSlack, never below 0.
// Queries are O(log n) binary searches on the rollout's samples.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "map/route_map.hpp"
#include "law/speed_bounds.hpp"
#include "planning/speed_limit_planner.hpp"

namespace signalsim::law {

/// [m/s] the planned rollout agrees with the ego's speed in SUMO to well within this (one step of
/// accel or decel at 0.1 s is 0.1 m/s).
inline constexpr double kSpeedSlack = 0.3;
/// Share of the ego's accel assumed when it restarts from rest (the rest is margin).
inline constexpr double kRestartShare = 0.9;

/// Where the ego may have to stop and how far before it braking may begin.
struct StopPoint {
  double s = 0.0;        ///< route s of the front bumper at the point [m]
  double braking = 0.0;  ///< [m] braking for it may start this far before
  std::string what;      ///< "light 51", "yield at junction 12 (link m)" (for the file's comment)
};

/// Braking distance before a light: the judge's normal jerk-limited stop (-1 m/s^2, -1 m/s^3,
/// braking from 0.9 of it, planning/stop) from v, with a generous margin: v^2 / 1.6 + 2 v + 10 m.
double light_braking_distance(double v);
/// Braking distance before a yielding link: SUMO brakes with the vType decel (4.5 m/s^2) to stop
/// at the link and sees the junction from 4.5 m: v^2 / 6 + 15 m (margin included).
double yield_braking_distance(double v);

class SpeedProfile : public SpeedBounds {
 public:
  /// Rolls the planner out from (depart_front, depart_speed) to the end of the route.
  SpeedProfile(const RouteMap& route, double depart_front, double depart_speed, const SpeedLimits& limits,
               double dt, std::vector<StopPoint> stops);

  double planned(double s) const;   ///< [m/s] at front position s (clamped to the rollout)
  double upper(double s) const;     ///< planned + slack
  double lower(double s) const override;  ///< see the file comment
  /// Why lower(s) is what it is: "planned - 0.3 m/s", "may be braking for light 51", "restarting
  /// from rest at light 51".
  std::string lower_reason(double s) const override;
  /// Highest planned speed over [from, to] (sampled every metre and at the ends).
  double max_planned(double from, double to) const override;
  /// Simulated seconds the rollout takes to the route's end (no stops).
  double travel_time() const { return travel_time_; }
  const std::vector<StopPoint>& stops() const { return stops_; }
  /// Whether s lies in a stop zone, and which stop (index), if any.
  const StopPoint* stop_zone_at(double s) const;

 private:
  std::vector<double> s_, v_;  // rollout samples: front position and speed, s ascending
  std::vector<StopPoint> stops_;
  double restart_speed(double from_rest) const;  // the lower bound after a rest [m/s]
  double restart_cap(double s) const;  // a restarted ego stays below the next lower limit ahead [m/s]
  std::vector<std::pair<double, double>> limits_;  // (lanelet start s, its limit), s ascending
  double accel_ = 1.0;
  double ramp_ = 0.0;  // [m]
  double travel_time_ = 0.0;
};

}  // namespace signalsim::law
