#include "turn_signal/behavior_modules.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "turn_signal/resolver.hpp"

namespace signalsim {
namespace {

constexpr double kLargeDeviation = 1.0;          // docs/behaviour.md §T8.2 / §T10: avoidance large-deviation guard [m]
constexpr double kFirstPathEndDistance = 1.0;    // [SP]/[GP] distance_threshold [m]

TurnIndicator centerline_start_command(const std::string& value) {
  if (value == "LEFT" || value == "Left" || value == "left") return TurnIndicator::EnableLeft;
  return TurnIndicator::EnableRight;
}

}  // namespace

// ---- Avoidance (docs/behaviour.md §T8.2) ------------------------------------------------------------------

std::optional<AvoidanceShiftLine> AvoidanceSignal::target_line(const std::vector<AvoidanceShiftLine>& lines,
                                                               const EgoOnRoute& ego,
                                                               const BehaviorSignalParameters& params) {
  if (lines.empty()) return std::nullopt;
  const AvoidanceShiftLine& s1 = lines.front();
  const double r1 = s1.shift_start - s1.shift_end;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const AvoidanceShiftLine& s2 = lines[i];
    const double r2 = s2.shift_start - s2.shift_end;
    if ((r1 > 0.0 && r2 > 0.0) || (r1 < 0.0 && r2 < 0.0)) continue;  // same side
    // docs/behaviour.md §T12.1.13: decided at the first opposite-side line, comparing against s1 only.
    if (s1.s_start - ego.s_base > 0.0) return s1;                      // near line still ahead
    if (s2.s_start - ego.s_base < ego.speed * params.max_prepare_time) return s2;  // far line close
    return s1;
  }
  return s1;
}

bool AvoidanceSignal::signals_candidate(CandidateTurnSignalPolicy policy, double speed) {
  // planWaitingApproval: "all_candidate" always, "stopped_candidate" only while stopped.
  return policy == CandidateTurnSignalPolicy::AllCandidate ||
         (policy == CandidateTurnSignalPolicy::StoppedCandidate && std::abs(speed) < kStoppedSpeed);
}

TurnSignalInfo AvoidanceSignal::update(const TurnSignalInfo& previous, const Input& input, const EgoOnRoute& ego,
                                       const BehaviorSignalParameters& params) {
  // Waiting for approval (docs/behaviour.md §T8.2): the candidate lines as if registered, or the previous request.
  if (input.phase == Phase::WaitingApproval && !signals_candidate(input.policy, ego.speed)) return previous;
  // The path shifter keeps only lines whose end is at or ahead of the ego.
  std::vector<AvoidanceShiftLine> lines;
  lines.reserve(input.shift_lines.size());
  for (const AvoidanceShiftLine& l : input.shift_lines)
    if (l.s_end >= ego.s_base) lines.push_back(l);
  if (lines.empty()) return previous;

  const double deviation = input.signal.current_shift_length - input.planned_shift_at_ego;
  if (std::abs(deviation) > kLargeDeviation) return previous;

  const AvoidanceShiftLine target = *target_line(lines, ego, params);
  if (is_ignored(target.id)) return previous;

  BehaviorSignalInput in = input.signal;
  in.shift_line = {target.s_start, target.s_end, target.shift_start, target.shift_end};
  in.is_driving_forward = true;
  in.egos_lane_is_shifted = true;
  in.is_pull_out = in.is_lane_change = in.is_pull_over = false;
  in.source = RequestSource::Avoidance;
  const BehaviorSignalResult result = behavior_signal(in, ego, params);
  if (result.is_ignore) ignored_.insert(target.id);
  return overwrite_turn_signal(ego, previous, result.info);
}

// ---- Lane change (docs/behaviour.md §T8.2) ----------------------------------------------------------------

TurnSignalInfo LaneChangeSignal::lc_signal(TurnIndicator direction, double start, double end,
                                           std::optional<double> crossing, const BehaviorSignalParameters& params) {
  TurnSignalInfo info;
  info.turn = direction;
  info.source = RequestSource::LaneChange;
  info.desired_start = info.required_start = start;
  info.desired_end = end;
  info.required_end = (params.lane_change_required_end_at_boundary && crossing) ? *crossing : end;
  return info;
}

void LaneChangeSignal::set_signal_activation_time(double now, bool reset_time) {
  if (reset_time) {
    blinker_on_since_.reset();
  } else if (!blinker_on_since_) {
    blinker_on_since_ = now;
  }
}

double LaneChangeSignal::min_prepare_duration_at(double speed, const BehaviorSignalParameters& p) {
  if (speed >= p.min_lane_changing_velocity) return p.min_prepare_duration;
  constexpr double eps = 1e-3;
  return p.max_longitudinal_acc < eps
             ? p.max_prepare_duration
             : std::max((p.min_lane_changing_velocity - speed) / p.max_longitudinal_acc, p.min_prepare_duration);
}

double LaneChangeSignal::actual_prepare_duration(double now, double speed,
                                                 const BehaviorSignalParameters& p) const {
  const double active_signal_duration = blinker_on_since_ ? now - *blinker_on_since_ : 0.0;
  return std::max(p.max_prepare_duration - active_signal_duration, min_prepare_duration_at(speed, p));
}

TurnSignalInfo LaneChangeSignal::update(const TurnSignalInfo& previous, const Input& in, const EgoOnRoute& ego,
                                        double now, const BehaviorSignalParameters& p) {
  if (!is_enable(in.direction)) return previous;  // direction NONE

  // signalsim activation (docs/differences.md): prep distance before the lateral motion, then latched.
  if (!active_) {
    const double prepare_distance =
        std::max(ego.speed * p.turn_signal_search_time, p.turn_signal_minimum_search_distance);
    const double front_to_start = in.lane_changing_start - ego.s_front;
    if (prepare_distance < front_to_start) return previous;
    active_ = true;
  }

  if (in.phase == Phase::Running) {
    // [LC] generateOutput: OVERWRITE(previous, LC_SIGNAL(ego pose, lane_changing_end)).
    const TurnSignalInfo own = lc_signal(in.direction, ego.s_base, in.lane_changing_end, in.boundary_crossing, p);
    TurnSignalInfo out = overwrite_turn_signal(ego, previous, own);
    set_signal_activation_time(now, out.turn != own.turn);
    return out;
  }

  // Waiting for approval ([LC] get_current_turn_signal_info).
  if (!in.is_normal_type || !in.has_current_lanes || in.previous_path_empty) return previous;

  if (is_enable(previous.turn)) {
    // Terminal variant: start min_length_for_turn_signal_activation (+ buffer, + front) before the
    // previous path's end, clamped to its front.
    const double buffer = in.current_dist_buffer_min + p.min_length_for_turn_signal_activation + p.base_link_to_front;
    const double path_length = in.previous_path_end - in.previous_path_front;
    const double start = in.previous_path_front + std::max(path_length - buffer, 0.0);
    const TurnSignalInfo terminal = lc_signal(in.direction, start, in.lane_changing_end, in.boundary_crossing, p);
    TurnSignalInfo out = overwrite_turn_signal(ego, previous, terminal);
    set_signal_activation_time(now, out.turn != terminal.turn);
    return out;
  }

  set_signal_activation_time(now, false);
  if (!in.has_valid_path) return lc_signal(in.direction, ego.s_base, in.previous_path_end, std::nullopt, p);
  return lc_signal(in.direction, ego.s_base, in.lane_changing_end, in.boundary_crossing, p);
}

// ---- Start planner (docs/behaviour.md §T8.2) --------------------------------------------------------------

bool PullOutSignal::override_stopped_check(bool has_departed, bool geometric_planner,
                                           double distance_to_first_path_end) {
  return !has_departed || (geometric_planner && std::abs(distance_to_first_path_end) < kFirstPathEndDistance);
}

bool PullOutSignal::is_centerline_start(const Input& in, const BehaviorSignalParameters& p) {
  const double shift = in.shift_at_end - in.shift_at_start;
  // [SP] calcTurnSignalInfo: not engaged yet, or engaged for less than prepare_time_before_start.
  const bool need_blinker_before_start =
      !in.time_since_first_engaged_forward || *in.time_since_first_engaged_forward < p.prepare_time_before_start;
  return std::abs(shift) < p.minimum_shift_length && !in.enable_back &&
         p.th_distance_to_middle_of_the_road < p.minimum_shift_length && need_blinker_before_start;
}

TurnSignalInfo PullOutSignal::update(const TurnSignalInfo& previous, const Input& in, const EgoOnRoute& ego,
                                     const BehaviorSignalParameters& p) {
  if (is_centerline_start(in, p)) {
    TurnSignalInfo out = previous;
    out.turn = centerline_start_command(p.turn_signal_on_centerline_start);
    out.source = RequestSource::PullOut;
    if (!is_enable(previous.turn)) {
      // signalsim: an inactive previous request has no meaningful section; give the forced blinker
      // the span from the ego to the pull-out end so that the decider can show it.
      out.desired_start = out.required_start = ego.s_base;
      out.desired_end = out.required_end = in.pull_out_end;
    }
    return out;
  }

  if (ignore_ && *ignore_ == in.closest_lanelet) return previous;

  BehaviorSignalInput b = in.signal;
  b.shift_line = {in.pull_out_start, in.pull_out_end, in.shift_at_start, in.shift_at_end};
  b.is_driving_forward = in.driving_forward;
  b.egos_lane_is_shifted = true;
  b.override_ego_stopped_check = in.override_ego_stopped_check;
  b.is_pull_out = true;
  b.is_lane_change = b.is_pull_over = false;
  b.source = RequestSource::PullOut;
  const BehaviorSignalResult result = behavior_signal(b, ego, p);
  ignore_ = result.is_ignore ? std::optional<std::size_t>(in.closest_lanelet) : std::nullopt;
  return use_prior_turn_signal(ego, previous, result.info);
}

// ---- Goal planner (docs/behaviour.md §T8.2) ---------------------------------------------------------------

bool PullOverSignal::override_stopped_check(bool shift_planner, double distance_to_first_path_end) {
  return !shift_planner && std::abs(distance_to_first_path_end) < kFirstPathEndDistance;
}

TurnSignalInfo PullOverSignal::preemptive_signal(const PreemptiveDecel& decel) {
  TurnSignalInfo info;
  info.turn = decel.parking_left ? TurnIndicator::EnableLeft : TurnIndicator::EnableRight;
  info.source = RequestSource::PullOver;
  info.desired_start = info.required_start = decel.decel_start;
  info.desired_end = info.required_end = decel.stop_path_end;
  if (decel.stop_pose) info.required_start = *decel.stop_pose;
  return info;
}

TurnSignalInfo PullOverSignal::update(const TurnSignalInfo& previous, const Input& in, const EgoOnRoute& ego,
                                      const BehaviorSignalParameters& p) {
  if (!in.path_decided) {
    if (!in.preemptive) return previous;
    return overwrite_turn_signal(ego, previous, preemptive_signal(*in.preemptive));
  }

  if (ignore_ && *ignore_ == in.closest_lanelet) return previous;

  BehaviorSignalInput b = in.signal;
  b.shift_line = {in.pull_over_start, in.pull_over_end, in.shift_at_start, in.shift_at_end};
  b.is_driving_forward = true;
  b.egos_lane_is_shifted = true;
  b.override_ego_stopped_check = in.override_ego_stopped_check;
  b.is_pull_out = b.is_lane_change = false;
  b.is_pull_over = true;
  b.source = RequestSource::PullOver;
  const BehaviorSignalResult result = behavior_signal(b, ego, p);
  ignore_ = result.is_ignore ? std::optional<std::size_t>(in.closest_lanelet) : std::nullopt;
  return overwrite_turn_signal(ego, previous, result.info);
}

// ---- Merge (docs/behaviour.md §T8, §T6.4) ------------------------------------------------------------------

TurnSignalInfo merge_behavior_requests(BehaviorModules& modules, const BehaviorRequests& requests,
                                       const EgoOnRoute& ego, const BehaviorSignalParameters& params) {
  TurnSignalInfo merged{};  // EMPTY
  if (requests.pull_out) merged = modules.pull_out.update(merged, *requests.pull_out, ego, params);
  if (requests.avoidance) merged = modules.avoidance.update(merged, *requests.avoidance, ego, params);
  if (requests.lane_change)
    merged = modules.lane_change.update(merged, *requests.lane_change, ego, requests.now, params);
  if (requests.pull_over) merged = modules.pull_over.update(merged, *requests.pull_over, ego, params);
  return merged;
}

}  // namespace signalsim
