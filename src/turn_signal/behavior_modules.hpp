// The behaviour modules' blinker requests (docs/behaviour.md §T8.2) and their state (docs/behaviour.md §T8.3).
//
// Each module is a small object fed once per step with the previous module's request and its own
// inputs; it returns the merged request the next module sees. merge_behavior_requests chains them
// in Autoware's slot order and hands the decider one behaviour TurnSignalInfo (docs/behaviour.md §T3.1, §T8):
//
//   B := EMPTY
//   B := PullOutSignal::update(B, ...)       slot 1 start_planner        -> USE_PRIOR_INFO
//   B := AvoidanceSignal::update(B, ...)     slot 2 static_obstacle_avoidance -> OVERWRITE
//   B := LaneChangeSignal::update(B, ...)    slot 2 lane_change           -> OVERWRITE (running)
//   B := PullOverSignal::update(B, ...)      slot 3 goal_planner          -> OVERWRITE
//   decider: hazard if B.hazard == ENABLE, else RESOLVE(intersection, roundabout, B)
//
// A module without input this step passes B through unchanged. Within slot 2 Autoware runs the
// approved modules in launch order; signalsim fixes avoidance before lane change.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <vector>

#include "turn_signal/behavior_signal.hpp"
#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

/// A registered avoidance shift line (Autoware's ShiftLine with its UUID).
struct AvoidanceShiftLine {
  std::uint64_t id = 0;      ///< stable id; the ignore set is keyed by it
  double s_start = 0.0;      ///< [m] route s
  double s_end = 0.0;        ///< [m]
  double shift_start = 0.0;  ///< lateral offset at s_start [m], left positive, from the reference lane centre
  double shift_end = 0.0;    ///< lateral offset at s_end [m]
};

/// Static obstacle avoidance (docs/behaviour.md §T8.2 "Avoidance", §T12.1.13). State: the permanent set of
/// ignored shift-line ids (docs/behaviour.md §T8.3).
///
/// Waiting for approval (nothing registered yet), Autoware's planWaitingApproval: with the policy
/// all_candidate, or stopped_candidate while |v| < 0.3 m/s, the candidate lines give the request
/// exactly as registered lines would (the same steps, the same ignore set); otherwise (none,
/// stop_on_approval) the previous request passes through.
class AvoidanceSignal {
 public:
  enum class Phase { WaitingApproval, Running };

  struct Input {
    Phase phase = Phase::Running;  ///< Running: the lines are registered (also while holding on approval)
    CandidateTurnSignalPolicy policy = CandidateTurnSignalPolicy::None;  ///< candidate_path_turn_signal
    std::vector<AvoidanceShiftLine> shift_lines;  ///< registered (or candidate) lines ordered by s_start (filtered here)
    double planned_shift_at_ego = 0.0;  ///< the planned (smooth) path's offset at the ego's s_base [m]
    /// Path span, lane bounds, current_shift_length, hatched flags, ...; shift_line, the flags,
    /// is_driving_forward and source are set by the module.
    BehaviorSignalInput signal;
  };

  /// One step. Returns `previous` unchanged while waiting without a candidate request (see the class
  /// comment), when no line ends at or ahead of base_link, when
  /// |current_shift_length - planned_shift_at_ego| > 1.0 m, or when the target line is ignored;
  /// otherwise OVERWRITE(previous, BEHAVIOR_SIGNAL(target line)) and latches the line if ignored.
  TurnSignalInfo update(const TurnSignalInfo& previous, const Input& input, const EgoOnRoute& ego,
                        const BehaviorSignalParameters& params);

  /// docs/behaviour.md §T8.2 target line among `lines` (already filtered, ordered): the first line s1, unless
  /// the first following line on the opposite side (sign of start - end differs; a zero counts as
  /// opposite) s2 exists, s1's start is not ahead of base_link and s2's start is within
  /// v * max_prepare_time of base_link (strict). nullopt for no lines.
  static std::optional<AvoidanceShiftLine> target_line(const std::vector<AvoidanceShiftLine>& lines,
                                                       const EgoOnRoute& ego, const BehaviorSignalParameters& params);

  /// Waiting for approval: does the policy show the candidate lines' request at `speed` [m/s]?
  static bool signals_candidate(CandidateTurnSignalPolicy policy, double speed);

  /// Autoware's helper isVehicleStopped: |v| below this [m/s] (stopped_candidate).
  static constexpr double kStoppedSpeed = 0.3;

  bool is_ignored(std::uint64_t id) const { return ignored_.count(id) != 0; }
  const std::set<std::uint64_t>& ignored_ids() const { return ignored_; }
  void reset() { ignored_.clear(); }

 private:
  std::set<std::uint64_t> ignored_;
};

/// Lane change (docs/behaviour.md §T8.2 "Lane change", §T12.1.14). Does not use BEHAVIOR_SIGNAL.
///
/// LC_SIGNAL(start, end) = {direction, desired_start = required_start = start, desired_end = end,
/// required_end = boundary crossing (signalsim default, lane_change_required_end_at_boundary) or end}.
///
/// signalsim activation (docs/differences.md): the module signals from the step where the front is within
/// max(v * turn_signal_search_time, turn_signal_minimum_search_distance) of lane_changing_start
/// (the §T8.1 comparison: on when prep >= front_to_start), latched until reset(); before that it
/// passes `previous` through (in Autoware the module is not running yet). Once active the variants
/// of [LC] apply with the ego pose (s_base) as start, exactly as §T8.2.
/// State: the activation latch and the blinker-on timestamp (set when the module's own command is
/// output, cleared when the previous module's request wins the OVERWRITE, as [LC]).
class LaneChangeSignal {
 public:
  enum class Phase { WaitingApproval, Running };

  struct Input {
    Phase phase = Phase::Running;
    TurnIndicator direction = TurnIndicator::NoCommand;  ///< EnableLeft / EnableRight; else NONE
    double lane_changing_start = 0.0;  ///< [m] s where the lateral motion begins (the path start)
    double lane_changing_end = 0.0;    ///< [m] s where it ends
    std::optional<double> boundary_crossing;  ///< [m] s where the path crosses the adjacent lane's boundary
    // Waiting-for-approval guards and the terminal variant ([LC] get_current_turn_signal_info).
    bool is_normal_type = true;     ///< NORMAL lane change (not avoidance-by-lane-change / external)
    bool has_current_lanes = true;
    bool previous_path_empty = false;
    double previous_path_front = 0.0;  ///< [m] s of the previous module path's first point
    double previous_path_end = 0.0;    ///< [m] s of its last point
    bool has_valid_path = true;        ///< false: LC_SIGNAL(ego, previous_path_end) (PR #8571)
    double current_dist_buffer_min = 0.0;  ///< [m] transient_data.current_dist_buffer.min
  };

  /// One step at time `now` [s]. See the class comment. Never throws.
  TurnSignalInfo update(const TurnSignalInfo& previous, const Input& input, const EgoOnRoute& ego, double now,
                        const BehaviorSignalParameters& params);

  /// [LC] calc_actual_prepare_duration: max(max_prepare_duration - blinker_on_time,
  /// min_prepare), where min_prepare = min_prepare_duration at or above min_lane_changing_velocity,
  /// else max((min_lane_changing_velocity - speed) / max_longitudinal_acc, min_prepare_duration)
  /// (max_prepare_duration when the acceleration is ~0). blinker_on_time = now - timestamp, 0 if off.
  double actual_prepare_duration(double now, double speed, const BehaviorSignalParameters& params) const;

  /// The floor of the prepare duration at `speed` (the min_prepare above): however long the blinker
  /// has been on, the prepare segment lasts at least this long.
  static double min_prepare_duration_at(double speed, const BehaviorSignalParameters& params);

  bool active() const { return active_; }
  std::optional<double> blinker_on_since() const { return blinker_on_since_; }
  void reset() {
    active_ = false;
    blinker_on_since_.reset();
  }

  /// LC_SIGNAL as described above (stateless).
  static TurnSignalInfo lc_signal(TurnIndicator direction, double start, double end, std::optional<double> crossing,
                                  const BehaviorSignalParameters& params);

 private:
  void set_signal_activation_time(double now, bool reset_time);

  bool active_ = false;
  std::optional<double> blinker_on_since_;
};

/// Start planner, pull out (docs/behaviour.md §T8.2 "Start planner"). State: the latched ignore lanelet
/// (docs/behaviour.md §T8.3): set while BEHAVIOR_SIGNAL says ignore, cleared by the first step that does not.
class PullOutSignal {
 public:
  struct Input {
    double pull_out_start = 0.0;  ///< [m] s of the path point nearest the pull-out start pose
    double pull_out_end = 0.0;    ///< [m] s of the path point nearest the pull-out end pose
    double shift_at_start = 0.0;  ///< lateral offset of the path there from the lane centre [m]
    double shift_at_end = 0.0;    ///< [m], normally 0 (back on the centre line)
    bool driving_forward = true;  ///< false on a backward segment -> hazard
    bool override_ego_stopped_check = false;  ///< see override_stopped_check()
    std::size_t closest_lanelet = 0;  ///< route index of the lanelet closest to the ego (ignore key)
    // Centre-line start special case (docs/behaviour.md §T8.2).
    bool enable_back = true;  ///< start_planner enable_back: backward driving allowed
    std::optional<double> time_since_first_engaged_forward;  ///< [s]; empty: not yet engaged
    /// Path span (the full pull-out path), lane bounds, current_shift_length, route_start, ...;
    /// shift_line, the flags and source are set by the module.
    BehaviorSignalInput signal;
  };

  /// One step: centre-line special case -> previous with cmd forced; ignored lanelet -> previous;
  /// else USE_PRIOR_INFO(previous, BEHAVIOR_SIGNAL(is_pull_out)). Never throws.
  TurnSignalInfo update(const TurnSignalInfo& previous, const Input& input, const EgoOnRoute& ego,
                        const BehaviorSignalParameters& params);

  /// [SP]: not yet departed, or (geometric planner and |ego to the first partial path's end| < 1 m).
  static bool override_stopped_check(bool has_departed, bool geometric_planner, double distance_to_first_path_end);

  /// docs/behaviour.md §T8.2 centre-line start condition.
  static bool is_centerline_start(const Input& input, const BehaviorSignalParameters& params);

  std::optional<std::size_t> ignored_lanelet() const { return ignore_; }
  void reset() { ignore_.reset(); }

 private:
  std::optional<std::size_t> ignore_;
};

/// Goal planner, pull over (docs/behaviour.md §T8.2 "Goal planner"). State: the latched ignore lanelet.
class PullOverSignal {
 public:
  /// PR #11512: while decelerating before the pull-over path is decided.
  struct PreemptiveDecel {
    double decel_start = 0.0;          ///< [m] s where the deceleration starts (desired/required start)
    double stop_path_end = 0.0;        ///< [m] s of the stop path's end (desired/required end)
    std::optional<double> stop_pose;   ///< [m] s of the stop pose; when known it is the required start
    bool parking_left = false;         ///< parking_policy left side -> LEFT, else RIGHT
  };

  struct Input {
    bool path_decided = true;  ///< false: only the pre-emptive request (if any) is merged
    std::optional<PreemptiveDecel> preemptive;
    double pull_over_start = 0.0;  ///< [m] s of the path point nearest the pull-over start pose
    double pull_over_end = 0.0;    ///< [m] s of the path point nearest the modified goal
    double shift_at_start = 0.0;   ///< lateral offset of the path there [m], normally 0
    double shift_at_end = 0.0;     ///< [m] the road-side offset at the goal
    bool override_ego_stopped_check = false;  ///< see override_stopped_check()
    std::size_t closest_lanelet = 0;  ///< route index of the lanelet closest to the ego (ignore key)
    /// Path span, lane bounds, current_shift_length, ...; shift_line, flags and source set here.
    BehaviorSignalInput signal;
  };

  /// One step: path not decided -> OVERWRITE(previous, pre-emptive) or previous; ignored lanelet
  /// -> previous; else OVERWRITE(previous, BEHAVIOR_SIGNAL(is_pull_over)). Never throws.
  TurnSignalInfo update(const TurnSignalInfo& previous, const Input& input, const EgoOnRoute& ego,
                        const BehaviorSignalParameters& params);

  /// [GP]: not the shift planner and |ego to the first partial path's end| < 1 m.
  static bool override_stopped_check(bool shift_planner, double distance_to_first_path_end);

  /// The PR #11512 request: TurnSignalInfo(decel_start, stop_path_end), required_start = stop pose
  /// when known, cmd by parking side.
  static TurnSignalInfo preemptive_signal(const PreemptiveDecel& decel);

  std::optional<std::size_t> ignored_lanelet() const { return ignore_; }
  void reset() { ignore_.reset(); }

 private:
  std::optional<std::size_t> ignore_;
};

/// The four modules of one ego, with their state.
struct BehaviorModules {
  PullOutSignal pull_out;
  AvoidanceSignal avoidance;
  LaneChangeSignal lane_change;
  PullOverSignal pull_over;

  void reset() {
    pull_out.reset();
    avoidance.reset();
    lane_change.reset();
    pull_over.reset();
  }
};

/// This step's inputs; a null pointer = the module is not running (its request passes through).
struct BehaviorRequests {
  const PullOutSignal::Input* pull_out = nullptr;
  const AvoidanceSignal::Input* avoidance = nullptr;
  const LaneChangeSignal::Input* lane_change = nullptr;
  const PullOverSignal::Input* pull_over = nullptr;
  double now = 0.0;  ///< simulation time [s] (lane change blinker timestamp)
};

/// Chains the modules in Autoware's order (see the file comment) starting from EMPTY and returns
/// the merged behaviour request for the decider (docs/behaviour.md §T3.1, §T6.4, §T8). Never throws.
TurnSignalInfo merge_behavior_requests(BehaviorModules& modules, const BehaviorRequests& requests,
                                       const EgoOnRoute& ego, const BehaviorSignalParameters& params);

}  // namespace signalsim
