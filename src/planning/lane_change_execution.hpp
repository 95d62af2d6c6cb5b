// When a lane change's lateral motion starts: the phases of Autoware's lane-change module
// (docs/behaviour.md §T8.2 "Lane change") executed on the route coordinate s.
//
//   Pending          the module is not running yet (its blinker is off); the ego keeps its lane.
//   WaitingApproval  the module signals (waiting-for-approval request); the ego keeps its lane. It is
//                    approved at the first step where the approval delay has passed since the
//                    blinker came on (an operator's RTC approval, operator_approval.hpp; 0 =
//                    automatic) and the target lane is clear of other vehicles around the candidate path.
//   Running          the path is fixed at approval: a prepare segment on the original lane (the
//                    distance driven in prepare_duration at the current speed and acceleration,
//                    Autoware's v*t + a*t^2/2, capped at the maximum speed and at standstill), then
//                    the lateral motion over `length`.
//   Done             base_link has passed the end of the lateral motion.
//   Missed           not approved before base_link passed the last possible start: the lane change
//                    can no longer end on its edge and is given up (never executed half).
//
// prepare_duration is the module's calc_actual_prepare_duration: max(max_prepare_duration -
// blinker-on time, min_prepare_duration) (docs/behaviour.md §T8.2), so a blinker that has been on for a while
// shortens the prepare segment. At a constant speed the lateral motion therefore starts
// max(max_prepare, blinker-on time at approval + min_prepare) seconds after the blinker came on.
//
// signalsim bounds (the scenario's, not Autoware's): the lateral motion never starts before
// `earliest_start` and never after `latest_start` (the last start that still ends with the front on
// the edge; a later approval cuts the prepare segment short). While waiting for approval the ego is
// brought to rest at the hold point, `hold_margin` before `latest_start` (room for the prepare
// segment from rest), as Autoware stops before the end of the lane when it cannot change lanes.
#pragma once

#include <optional>
#include <vector>

#include "core/vehicle_defaults.hpp"
#include "planning/shift_line.hpp"

namespace signalsim {

/// The fixed facts of one lane change, decided when the scenario is planned.
struct LaneChangeTiming {
  double earliest_start = 0.0;  ///< [m] base_link s: the lateral motion starts here at the earliest
  double latest_start = 0.0;    ///< [m] base_link s: the last start that still ends on the edge
  double length = 50.0;         ///< [m] of s over which the ego moves one lane sideways
  double shift_start = 0.0;     ///< [m] lateral offset of the original lane from the target lane's centre
  double approval_delay = 0.0;  ///< [s] the earliest approval after the blinker came on
  double hold_margin = 0.0;     ///< [m] the hold point lies this far before latest_start
};

/// Where another vehicle occupies the target lane, in route s [m] (rear, front).
struct OccupiedSpan {
  double rear = 0.0;
  double front = 0.0;
};

/// The safety margins of the approval's target-lane check (a stand-in for Autoware's RSS check).
struct LaneChangeGaps {
  double rear = 10.0;   ///< [m] kept free behind the ego's rear bumper
  double front = 10.0;  ///< [m] kept free beyond the candidate path's end (front bumper there)
};

enum class LaneChangePhase { Pending, WaitingApproval, Running, Done, Missed };

/// "pending", "waiting_approval", "running", "done", "missed".
const char* to_string(LaneChangePhase phase);

/// The phase machine of one lane change (see the file comment). A value type; no SUMO.
class LaneChangeExecution {
 public:
  struct Step {
    double now = 0.0;           ///< [s]
    double s_base = 0.0;        ///< [m] base_link's route s
    double speed = 0.0;         ///< [m/s]
    double accel = 0.0;         ///< [m/s^2] the acceleration the prepare segment is driven with
    double max_speed = 1e9;     ///< [m/s] the speed it accelerates to at most
    bool module_active = false; ///< the lane-change module signals (LaneChangeSignal::active)
    std::optional<double> blinker_on_since;  ///< [s] the module's blinker timestamp
    double prepare_duration = 0.0;           ///< [s] the module's actual prepare duration now
    double vehicle_length = vehicle_defaults::kLength;  ///< [m]
    double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< [m]
    std::vector<OccupiedSpan> target_lane;   ///< other vehicles on the target lane
  };

  LaneChangeExecution() = default;
  LaneChangeExecution(LaneChangeTiming timing, LaneChangeGaps gaps) : timing_(timing), gaps_(gaps) {}

  /// Advances the phase for this step (at most one transition per step, in order). Returns true when
  /// the phase changed.
  bool update(const Step& step);

  LaneChangePhase phase() const { return phase_; }
  const LaneChangeTiming& timing() const { return timing_; }

  /// The shift line the ego follows: fixed once running; before that the candidate path at `step`
  /// (its start `s_base + v * prepare_duration`, bounded to [earliest_start, latest_start]).
  ShiftLine line(const Step& step) const;
  /// The fixed line (Running / Done); nullopt before approval.
  const std::optional<ShiftLine>& approved_line() const { return approved_; }
  /// What held at approval.
  struct Approval {
    double time = 0.0;                       ///< [s]
    double s_base = 0.0;                     ///< [m]
    double prepare_duration = 0.0;           ///< [s] the module's, at approval
    std::optional<double> blinker_on_since;  ///< [s]
  };
  const std::optional<Approval>& approval() const { return approval_; }
  std::optional<double> approval_time() const {
    return approval_ ? std::optional<double>(approval_->time) : std::nullopt;
  }

  /// While waiting for approval the ego must come to rest with base_link at the hold point
  /// (latest_start - hold_margin) at the latest: the distance left to it [m]; nullopt in every
  /// other phase (pending: the module does not signal yet and may be approved at once).
  std::optional<double> distance_to_hold_point(double s_base) const;

  /// The module's blinker timestamp as last seen (kept when never approved).
  std::optional<double> blinker_on_since() const { return blinker_on_since_; }

  /// base_link may pass latest_start by this much (stopping tolerance) before the lane change counts
  /// as missed [m].
  static constexpr double kLatestStartTolerance = 0.05;

  /// Is the target lane clear for the candidate line at `step`: no span overlaps
  /// [rear bumper - gaps.rear, candidate end + base_link_to_front + gaps.front].
  bool target_lane_clear(const Step& step) const;

  /// The candidate's start at `step` (see line()).
  double candidate_start(const Step& step) const;

  /// The distance driven in `duration` from `speed` at constant `accel`, the speed kept within
  /// [0, max_speed] [m].
  static double prepare_distance(double speed, double accel, double max_speed, double duration);

 private:
  ShiftLine line_from(double start) const { return {start, start + timing_.length, timing_.shift_start, 0.0}; }

  LaneChangeTiming timing_;
  LaneChangeGaps gaps_;
  LaneChangePhase phase_ = LaneChangePhase::Pending;
  std::optional<ShiftLine> approved_;
  std::optional<Approval> approval_;
  std::optional<double> blinker_on_since_;
};

}  // namespace signalsim
