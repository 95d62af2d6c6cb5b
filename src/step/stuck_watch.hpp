// The stuck rule (docs/run.md): a run ends early, as not arrived, once the ego has been at rest for
// `stuck_rest_time` seconds while signalsim itself does not hold it, i.e. while it commands a speed
// above rest (no red light, lane-change hold point or pull-over goal keeps it there; SUMO does: a
// leader, right of way at a junction). A run that reaches `duration` first records why too. The
// record says where the ego is and, as far as SUMO tells, why it does not move.
//
//   each step: at rest (speed < 0.01 m/s) and not held -> the stuck clock runs, else it restarts
//              stuck_clock >= stuck_rest_time (> 0)    -> the run ends: NotArrived "stuck"
//   end of `duration` before arriving                    -> NotArrived "duration"
//   reason: the leader SUMO reports (id, gap), else the junction the ego waits in or at the entry
//           of (front within 10 m of it), else "SUMO gives no reason"
#pragma once

#include <optional>
#include <string>

#include "map/route_map.hpp"
#include "report/timeline.hpp"

namespace signalsim {

/// [m/s] below this the ego is at rest: the stuck rule (either direction), a stop at a light, and a
/// commanded speed that holds the ego.
inline constexpr double kRestSpeed = 0.01;

class StuckWatch {
 public:
  /// `stuck_rest_time` [s]; 0 switches the rule off.
  explicit StuckWatch(double stuck_rest_time) : limit_(stuck_rest_time) {}

  /// One step at `time` [s]: the ego's `speed` [m/s] and what of signalsim holds it (`held_by`,
  /// "" when signalsim commands a speed above rest). `queued`: a light ahead asks for a stop while the
  /// ego rests short of it (behind others): the stuck clock pauses, it does not restart. Returns true
  /// when the run must end as stuck.
  bool observe(double time, double speed, const std::string& held_by, bool queued = false);

  /// Whether observe(time, speed, "", false) would end the run: the step at `time` may end it as
  /// stuck when signalsim does not hold the ego (its leader is then asked for, to say why).
  bool may_end_at(double time, double speed) const;

  /// The ego was at rest at the last observation.
  bool at_rest() const { return rest_since_.has_value(); }
  /// [s] how long the ego has been at rest as of the last observation (0 while moving).
  double at_rest_for() const { return rest_since_ ? last_time_ - *rest_since_ : 0.0; }
  /// [s] how long it has been at rest, not held by signalsim and not queued (the stuck clock).
  double stuck_for() const { return free_for_; }
  const std::string& held_by() const { return held_by_; }

 private:
  double limit_;
  double last_time_ = 0.0;
  std::optional<double> rest_since_;  // first row of the current rest
  double free_for_ = 0.0;             // the stuck clock
  bool counting_ = false;             // the previous row counted (at rest, not held, not queued)
  bool observed_ = false;
  std::string held_by_;
};

/// The record of a run that ends at `last` without arriving: `reason` "stuck" or "duration",
/// `duration` [s] the scenario's (for the sentence), the watch's rest times, and SUMO's view
/// (`leader`: SUMO's leader of the ego at `last`, within kLeaderRange, used when the ego is at rest and
/// not held; `route` gives the junction).
NotArrived not_arrived(const std::string& reason, double duration, const TimelineRow& last, const StuckWatch& watch,
                       const std::optional<LeaderInfo>& leader, const RouteMap& route);

}  // namespace signalsim
