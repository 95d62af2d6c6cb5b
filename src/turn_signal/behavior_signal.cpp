#include "turn_signal/behavior_signal.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {
namespace {

constexpr double kStoppedSpeed = 0.1;  // docs/behaviour.md §T8.1 / §T10: hard-coded stop speed [m/s]

// docs/behaviour.md §T1.2: TurnSignalInfo(path front, path back) with NO_COMMAND.
TurnSignalInfo none_info(const BehaviorSignalInput& in) {
  TurnSignalInfo info;
  info.source = in.source;
  info.desired_start = info.required_start = in.path_front;
  info.desired_end = info.required_end = in.path_back;
  return info;
}

BehaviorSignalResult none(const BehaviorSignalInput& in, bool is_ignore) { return {none_info(in), is_ignore}; }

double path_shift(const BehaviorSignalInput& in, double s) {
  if (in.path_shift_at) return in.path_shift_at(s);
  const BehaviorShiftLine& l = in.shift_line;
  const double length = l.s_end - l.s_start;
  if (length <= 0.0) return l.shift_end;
  const double u = std::clamp((s - l.s_start) / length, 0.0, 1.0);
  return l.shift_start + (l.shift_end - l.shift_start) * u;
}

double path_slope(const BehaviorSignalInput& in, double s) {
  if (in.path_heading_at) return in.path_heading_at(s);
  if (in.path_shift_at) {
    constexpr double h = 0.01;
    return (in.path_shift_at(s + h) - in.path_shift_at(s - h)) / (2.0 * h);
  }
  const BehaviorShiftLine& l = in.shift_line;
  const double length = l.s_end - l.s_start;
  return length > 0.0 ? (l.shift_end - l.shift_start) / length : 0.0;
}

}  // namespace

std::optional<CandidateTurnSignalPolicy> candidate_turn_signal_policy(const std::string& text) {
  if (text == "none") return CandidateTurnSignalPolicy::None;
  if (text == "stopped_candidate") return CandidateTurnSignalPolicy::StoppedCandidate;
  if (text == "all_candidate") return CandidateTurnSignalPolicy::AllCandidate;
  if (text == "stop_on_approval") return CandidateTurnSignalPolicy::StopOnApproval;
  return std::nullopt;
}

BehaviorSignalParameters behavior_signal_parameters(const TurnSignalParameters& decider,
                                                    BehaviorSignalParameters base) {
  base.turn_signal_shift_length_threshold = decider.turn_signal_shift_length_threshold;
  base.turn_signal_remaining_shift_length_threshold = decider.turn_signal_remaining_shift_length_threshold;
  base.turn_signal_search_time = decider.turn_signal_search_time;
  base.turn_signal_minimum_search_distance = decider.turn_signal_minimum_search_distance;
  base.turn_signal_on_swerving = decider.turn_signal_on_swerving;
  base.turn_signal_remaining_distance_to_bound_threshold =
      decider.turn_signal_remaining_distance_to_bound_threshold;
  base.base_link_to_front = decider.base_link_to_front;
  return base;
}

// docs/behaviour.md §T8.1 hatched-only test: the four shift classes of the reference (HPP isAvoidShift etc.).
bool is_avoid_shift(double a, double b, double th) { return std::abs(a) < th && std::abs(b) > th; }
bool is_return_shift(double a, double b, double th) { return std::abs(a) > th && std::abs(b) < th; }
bool is_left_middle_shift(double a, double b, double th) { return a > th && b > th; }
bool is_right_middle_shift(double a, double b, double th) { return a < th && b < th; }

bool is_adjacent_to_hatched_road_marking_ok(double a, double b, bool left_only, bool right_only, double th) {
  const double rel = b - a;
  if (is_avoid_shift(a, b, th)) {
    if (rel > 0.0 && left_only) return false;   // left avoid, nothing but hatching on the left
    if (rel < 0.0 && right_only) return false;  // right avoid
  }
  if (is_return_shift(a, b, th)) {
    if (rel > 0.0 && right_only) return false;  // return from the right
    if (rel < 0.0 && left_only) return false;   // return from the left
  }
  if (is_left_middle_shift(a, b, th) && left_only) return false;
  if (is_right_middle_shift(a, b, th) && right_only) return false;
  return true;
}

bool straddles_lane_bound(const BehaviorSignalInput& in, const BehaviorSignalParameters& p) {
  const BehaviorShiftLine& l = in.shift_line;
  const double step = p.bound_check_interval > 0.0 ? p.bound_check_interval : 1.0;
  const double half = 0.5 * p.vehicle_width;
  // Path points start_idx .. end_idx-1 (docs/behaviour.md §T8.1): samples s_start + k*step < s_end.
  for (int k = 0;; ++k) {
    const double s = l.s_start + k * step;
    if (!(s < l.s_end)) break;
    const double offset = path_shift(in, s);
    const double yaw = std::atan(path_slope(in, s));
    const double c = std::cos(yaw);
    const double sn = std::sin(yaw);
    // Lateral extent of the rotated footprint rectangle (corners x in {front, -rear}, y in {+-half}).
    const double lon_lo = std::min(p.base_link_to_front * sn, -p.rear_overhang * sn);
    const double lon_hi = std::max(p.base_link_to_front * sn, -p.rear_overhang * sn);
    const double lo = offset + lon_lo - half * c;
    const double hi = offset + lon_hi + half * c;
    const double left_bound = in.lane.left(s);
    const double right_bound = -in.lane.right(s);
    if (lo <= left_bound && left_bound <= hi) return true;
    if (lo <= right_bound && right_bound <= hi) return true;
  }
  return false;
}

double pull_out_distance_to_bound(const BehaviorSignalInput& in, const EgoOnRoute& ego,
                                  const BehaviorSignalParameters& p, bool left) {
  const double yaw = in.ego_relative_yaw;
  const double y = (left ? 0.5 : -0.5) * p.vehicle_width;
  const double corner_s = ego.s_base + p.base_link_to_front * std::cos(yaw) - y * std::sin(yaw);
  const double corner_lat = in.current_shift_length + p.base_link_to_front * std::sin(yaw) + y * std::cos(yaw);
  return left ? in.lane.left(corner_s) - corner_lat : corner_lat + in.lane.right(corner_s);
}

BehaviorSignalResult behavior_signal(const BehaviorSignalInput& in, const EgoOnRoute& ego,
                                     const BehaviorSignalParameters& p) {
  // docs/behaviour.md §T8.1: backward driving (start planner's back path) -> hazard, not ignored.
  if (!in.is_driving_forward) {
    TurnSignalInfo info;
    info.hazard = HazardLights::Enable;
    info.source = in.source;
    info.desired_start = info.required_start = in.route_start;
    info.desired_end = info.required_end = ego.s_base;
    return {info, false};
  }

  const BehaviorShiftLine& line = in.shift_line;
  // docs/behaviour.md §T8.1: start/end index out of range of the path -> EMPTY, ignore.
  if (line.s_start > in.path_back || line.s_end > in.path_back) return {TurnSignalInfo{}, true};

  // docs/behaviour.md §T8.1: lane-change style shifts are defined relative to the target lane.
  double a = line.shift_start;
  double b = line.shift_end;
  if (!in.egos_lane_is_shifted) {
    a = line.shift_end;
    b = -line.shift_start;
  }
  const double rel = b - a;

  // Strict '<': a shift of exactly the threshold signals.
  if (std::abs(rel) < p.turn_signal_shift_length_threshold) return none(in, true);
  if (std::abs(b - in.current_shift_length) < p.turn_signal_remaining_shift_length_threshold) return none(in, true);

  const double prepare_distance =
      std::max(ego.speed * p.turn_signal_search_time, p.turn_signal_minimum_search_distance);
  const double front_to_start = line.s_start - ego.s_front;  // arclen(base_link -> start) - base_link2front
  if (prepare_distance < front_to_start) return none(in, false);  // too early, retry next cycle

  // docs/behaviour.md §T12.1.1: the flag disables every shift-based blinker (not ignored).
  if (!p.turn_signal_on_swerving) return none(in, false);

  if (!in.route_lanelet_found) return none(in, true);

  const double th = p.turn_signal_shift_length_threshold;
  if (!in.is_pull_out && !in.is_lane_change && !in.is_pull_over &&
      !is_adjacent_to_hatched_road_marking_ok(a, b, in.left_hatched_road_marking_only,
                                              in.right_hatched_road_marking_only, th)) {
    return none(in, true);
  }

  // Pull out and pull over signal even when the ego stays inside its lane.
  if (!in.is_pull_out && !in.is_pull_over && !straddles_lane_bound(in, p)) return none(in, true);

  // Stopped near the end of a return shift and already back inside the lane (boost within: strict).
  if (ego.speed < kStoppedSpeed && !in.override_ego_stopped_check && is_return_shift(a, b, th)) {
    const double offset = in.current_shift_length;
    const bool inside_lane = -in.lane.right(ego.s_base) < offset && offset < in.lane.left(ego.s_base);
    if (inside_lane) return none(in, true);
  }

  const bool left = rel > 0.0;
  if (in.is_pull_out && !in.is_lane_change) {
    const double d = in.distance_to_bound ? *in.distance_to_bound : pull_out_distance_to_bound(in, ego, p, left);
    if (std::abs(d) < p.turn_signal_remaining_distance_to_bound_threshold) return none(in, true);
  }

  TurnSignalInfo info;
  info.turn = left ? TurnIndicator::EnableLeft : TurnIndicator::EnableRight;
  info.source = in.source;
  info.desired_start = front_to_start > 0.0 ? ego.s_base : line.s_start;
  info.required_start = line.s_start;
  info.desired_end = info.required_end = line.s_end;
  return {info, false};
}

}  // namespace signalsim
