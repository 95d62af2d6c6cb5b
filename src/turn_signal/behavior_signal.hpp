// The generic shift-based blinker request BEHAVIOR_SIGNAL (docs/behaviour.md §T8.1) on the route coordinate s.
//
// Autoware's getBehaviorTurnSignalInfo, restated on s and lateral offsets. The steps, in order (the
// first that applies returns; NONE = {NO_COMMAND, section = [path_front, path_back]}):
//
//   not driving forward                      -> hazard {route_start .. ego base_link}, keep
//   shift line outside the path              -> EMPTY, ignore
//   (a, b) := raw (shift_start, shift_end); if !egos_lane_is_shifted: (a, b) := (b_raw, -a_raw)
//   rel := b - a
//   |rel| < turn_signal_shift_length_threshold               -> NONE, ignore   (0.3 signals)
//   |b - current_shift_length| < ..._remaining_shift_length_threshold -> NONE, ignore (0.1 signals)
//   max(v * search_time, minimum_search_distance) < front_to_start -> NONE, keep (too early)
//   !turn_signal_on_swerving                                 -> NONE, keep  (docs/behaviour.md §T12.1.1)
//   no route lanelet at the query point                      -> NONE, ignore
//   avoidance only: hatched-road-marking-only side           -> NONE, ignore
//   not pull out / pull over: footprint never meets a bound  -> NONE, ignore
//   v < 0.1, !override_ego_stopped_check, return shift, ego inside its lane -> NONE, ignore
//   pull out (not lane change): front corner within 1.3 m of the far bound  -> NONE, ignore
//   otherwise {rel > 0 ? LEFT : RIGHT, desired_start = front_to_start > 0 ? ego base_link : start,
//              required_start = start, desired_end = required_end = end}, keep
//
// `ignore` tells the calling module to latch "no blinker" (docs/behaviour.md §T8.3).
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "core/vehicle_defaults.hpp"
#include "turn_signal/turn_signal_info.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// avoidance.policy.candidate_path_turn_signal (docs/behaviour.md §T8.2 "Avoidance"): the avoidance's
/// blinker while it waits for approval.
enum class CandidateTurnSignalPolicy {
  None,              ///< "none": the previous module's request (the shipped value)
  StoppedCandidate,  ///< "stopped_candidate": the candidate lines' request while |v| < 0.3 m/s
  AllCandidate,      ///< "all_candidate": the candidate lines' request
  StopOnApproval,    ///< "stop_on_approval": as "none"; at approval the ego holds with the blinker
};

/// The policy named `text` as Autoware spells it; nullopt for any other text.
std::optional<CandidateTurnSignalPolicy> candidate_turn_signal_policy(const std::string& text);

/// Everything the behaviour modules read from the parameter set. Names are Autoware's; defaults are
/// docs/behaviour.md §T10 (and the Autoware module YAMLs where §T10 has none).
struct BehaviorSignalParameters {
  // Shared with the decider (docs/behaviour.md §T10).
  double turn_signal_shift_length_threshold = 0.3;            ///< [m] smaller shifts never signal
  double turn_signal_remaining_shift_length_threshold = 0.1;  ///< [m] shift counted as done
  double turn_signal_search_time = 3.0;                       ///< [s] prep distance = max(v*this, min)
  double turn_signal_minimum_search_distance = 10.0;          ///< [m] floor of the prep distance
  bool turn_signal_on_swerving = true;                        ///< false disables every shift blinker
  double turn_signal_remaining_distance_to_bound_threshold = 1.3;  ///< [m] pull out turn-off
  // Vehicle (Autoware vehicle_info).
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< rear-axle centre to front bumper [m] (max_longitudinal_offset)
  double rear_overhang = 0.8;       ///< rear-axle centre to rear bumper [m] (not in the schema)
  double vehicle_width = vehicle_defaults::kWidth;  ///< [m] (not in the schema)
  // Lane change (docs/behaviour.md §T8.2, lane_change.param.yaml).
  double min_length_for_turn_signal_activation = 10.0;  ///< [m] terminal-variant buffer
  double max_prepare_duration = 4.0;        ///< [s] trajectory.max_prepare_duration (not in the schema)
  double min_prepare_duration = 2.0;        ///< [s] trajectory.min_prepare_duration (not in the schema)
  double min_lane_changing_velocity = 2.78; ///< [m/s] trajectory.min_lane_changing_velocity (not in the schema)
  double max_longitudinal_acc = 1.0;        ///< [m/s^2] trajectory.max_longitudinal_acc (not in the schema)
  /// signalsim: the lane change's required end is where the path crosses the adjacent lane's
  /// boundary (a signalsim choice, docs/differences.md). false: the lane-changing end, as LC_SIGNAL in [LC].
  bool lane_change_required_end_at_boundary = true;
  // Avoidance (docs/behaviour.md §T8.2).
  double max_prepare_time = 3.0;  ///< [s] the far opposite shift line is chosen within v*this
  /// avoidance.policy.candidate_path_turn_signal (signalsim's default is the shipped "none"; the
  /// module's struct default is "stopped_candidate").
  CandidateTurnSignalPolicy candidate_path_turn_signal = CandidateTurnSignalPolicy::None;
  double turn_signal_on_approval_hold_duration = 3.0;  ///< [s] stop_on_approval's hold
  // Start planner (docs/behaviour.md §T8.2).
  std::string turn_signal_on_centerline_start = "RIGHT";  ///< "LEFT" / "RIGHT"
  double minimum_shift_length = 0.5;                      ///< [m]
  double th_distance_to_middle_of_the_road = 0.5;         ///< [m]
  double prepare_time_before_start = 0.0;                 ///< [s] the wait with the blinker after engaging
  bool enable_back = true;                                ///< backing up allowed (start_planner.enable_back)
  /// signalsim: spacing of the footprint samples of the lane-bound test [m] (Autoware: path points).
  double bound_check_interval = 1.0;

  bool operator==(const BehaviorSignalParameters&) const = default;
};

/// The shared decider values copied into `base` (thresholds, search time/distance, swerving flag,
/// base_link_to_front). Everything else keeps `base`'s values.
BehaviorSignalParameters behavior_signal_parameters(const TurnSignalParameters& decider,
                                                    BehaviorSignalParameters base = {});

/// The current lanelets' bounds as lateral positions from the reference lane's centre line:
/// the left bound at +left(s), the right bound at -right(s). Constant unless the functions are set.
struct LaneBounds {
  double left_half_width = 1.6;   ///< [m] used when left_at is empty
  double right_half_width = 1.6;  ///< [m] used when right_at is empty
  std::function<double(double s)> left_at;   ///< optional: half width to the left bound at s
  std::function<double(double s)> right_at;  ///< optional: half width to the right bound at s

  double left(double s) const { return left_at ? left_at(s) : left_half_width; }
  double right(double s) const { return right_at ? right_at(s) : right_half_width; }
};

/// The four numbers of a shift line as BEHAVIOR_SIGNAL sees it: the path points at the line's
/// start and end and the path's raw lateral shift there (docs/behaviour.md §T8.1 shift[start_idx], shift[end_idx]).
struct BehaviorShiftLine {
  double s_start = 0.0;      ///< route s of the shift start (base_link) [m]
  double s_end = 0.0;        ///< route s of the shift end [m]
  double shift_start = 0.0;  ///< raw lateral shift of the path at s_start [m], left positive
  double shift_end = 0.0;    ///< raw lateral shift of the path at s_end [m]
};

struct BehaviorSignalInput {
  BehaviorShiftLine shift_line;
  double path_front = 0.0;  ///< s of the module path's first point (NONE's start) [m]
  double path_back = 0.0;   ///< s of its last point (NONE's end) [m]; a line beyond it -> EMPTY
  double current_shift_length = 0.0;  ///< ego's lateral offset from the reference lane centre [m]
  bool is_driving_forward = true;
  double route_start = 0.0;  ///< s of the route's original start pose (hazard section start) [m]
  bool egos_lane_is_shifted = true;
  bool override_ego_stopped_check = false;
  bool is_pull_out = false;
  bool is_lane_change = false;
  bool is_pull_over = false;
  /// A route lanelet exists at the query point (shift end if egos_lane_is_shifted, else shift start).
  bool route_lanelet_found = true;
  /// Hatched road marking on that side and no same-direction or opposite lanelet there. SUMO nets
  /// have no hatched markings, so signalsim always supplies false (the logic is kept for parity).
  bool left_hatched_road_marking_only = false;
  bool right_hatched_road_marking_only = false;
  LaneBounds lane;  ///< bounds of the current lanelets (lane-bound, stopped and pull-out tests)
  /// Optional lateral offset (and slope) of the module's path at s for the lane-bound test. Empty:
  /// the linear ramp from shift_start to shift_end, which is exactly what avoidance passes (its
  /// linear shifted path, docs/behaviour.md §T8.2). The slope defaults to a central difference of path_shift_at.
  std::function<double(double s)> path_shift_at;
  std::function<double(double s)> path_heading_at;
  double ego_relative_yaw = 0.0;  ///< ego yaw relative to the lane [rad] (pull-out corner)
  /// Optional signed lateral distance from the pull-out front corner to the far bound; empty:
  /// computed from the footprint at the ego, current_shift_length, ego_relative_yaw and `lane`.
  std::optional<double> distance_to_bound;
  RequestSource source = RequestSource::None;  ///< stamped on every non-EMPTY result
};

struct BehaviorSignalResult {
  TurnSignalInfo info;
  bool is_ignore = false;  ///< the module should latch "no blinker" for this line / lanelet
};

/// docs/behaviour.md §T8.1 BEHAVIOR_SIGNAL. Distances follow docs/behaviour.md §T2: front_to_start = s_start - s_front
/// (arclen from base_link minus base_link_to_front), the ego pose is base_link (s_base). Never throws.
BehaviorSignalResult behavior_signal(const BehaviorSignalInput& input, const EgoOnRoute& ego,
                                     const BehaviorSignalParameters& params);

// --- the predicates, exposed for tests (docs/behaviour.md §T8.1; all comparisons as in the reference) ---

/// |a| < th and |b| > th.
bool is_avoid_shift(double a, double b, double th);
/// |a| > th and |b| < th.
bool is_return_shift(double a, double b, double th);
/// a > th and b > th.
bool is_left_middle_shift(double a, double b, double th);
/// a < th and b < th (signed, as in the reference).
bool is_right_middle_shift(double a, double b, double th);
/// false = "no blinker" because the shift goes towards a side with hatched road marking only.
bool is_adjacent_to_hatched_road_marking_ok(double a, double b, bool left_only, bool right_only, double th);

/// The lane-bound test: does the footprint placed at the path samples s_start, s_start + step, ...
/// (< s_end) touch the left or right bound? In lateral terms the footprint is the rectangle
/// [-rear_overhang, base_link_to_front] x [-width/2, width/2] rotated by atan(path slope); it meets a
/// bound when the bound's lateral position lies within the rectangle's lateral extent (touching
/// counts, as boost::geometry::intersects; a footprint wholly beyond a bound does not meet it). The
/// bound is taken as a line parallel to the reference at the half width at the sample's s.
bool straddles_lane_bound(const BehaviorSignalInput& input, const BehaviorSignalParameters& params);

/// Signed lateral distance [m] from the pull-out front corner (front-left for a left shift,
/// front-right for a right one) to that side's bound; positive = the corner is still inside.
double pull_out_distance_to_bound(const BehaviorSignalInput& input, const EgoOnRoute& ego,
                                  const BehaviorSignalParameters& params, bool left);

}  // namespace signalsim
