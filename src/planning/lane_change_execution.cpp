#include "planning/lane_change_execution.hpp"

#include <algorithm>

#include "planning/operator_approval.hpp"

namespace signalsim {

const char* to_string(LaneChangePhase phase) {
  switch (phase) {
    case LaneChangePhase::Pending: return "pending";
    case LaneChangePhase::WaitingApproval: return "waiting_approval";
    case LaneChangePhase::Running: return "running";
    case LaneChangePhase::Done: return "done";
    case LaneChangePhase::Missed: return "missed";
  }
  return "?";
}

double LaneChangeExecution::prepare_distance(double speed, double accel, double max_speed, double duration) {
  const double v0 = std::clamp(speed, 0.0, std::max(max_speed, 0.0));
  if (duration <= 0.0) return 0.0;
  if (accel == 0.0) return v0 * duration;
  // Until the speed reaches its bound (max_speed accelerating, 0 braking), then constant.
  const double bound = accel > 0.0 ? std::max(max_speed, v0) : 0.0;
  const double t_bound = std::min(duration, (bound - v0) / accel);
  const double ramp = v0 * t_bound + 0.5 * accel * t_bound * t_bound;
  return ramp + bound * (duration - t_bound);
}

double LaneChangeExecution::candidate_start(const Step& step) const {
  // The prepare segment on the original lane (docs/behaviour.md §T8.2), driven in prepare_duration.
  const double prepared =
      step.s_base + prepare_distance(step.speed, step.accel, step.max_speed, step.prepare_duration);
  const double start = std::min(std::max(timing_.earliest_start, prepared), timing_.latest_start);
  return std::max(start, step.s_base);  // never behind base_link (only past the hold point)
}

ShiftLine LaneChangeExecution::line(const Step& step) const {
  if (approved_) return *approved_;
  return line_from(candidate_start(step));
}

bool LaneChangeExecution::target_lane_clear(const Step& step) const {
  const double rear_bumper = step.s_base + step.base_link_to_front - step.vehicle_length;
  const double from = rear_bumper - gaps_.rear;
  const double to = line(step).s_end + step.base_link_to_front + gaps_.front;
  return std::none_of(step.target_lane.begin(), step.target_lane.end(),
                      [&](const OccupiedSpan& v) { return v.front >= from && v.rear <= to; });
}

std::optional<double> LaneChangeExecution::distance_to_hold_point(double s_base) const {
  if (phase_ != LaneChangePhase::WaitingApproval) return std::nullopt;
  return timing_.latest_start - timing_.hold_margin - s_base;
}

bool LaneChangeExecution::update(const Step& step) {
  const LaneChangePhase before = phase_;
  if (step.blinker_on_since) blinker_on_since_ = step.blinker_on_since;
  if (phase_ == LaneChangePhase::Pending && step.module_active) phase_ = LaneChangePhase::WaitingApproval;
  // Past the last start without approval: the lateral motion could not end on its edge any more.
  if ((phase_ == LaneChangePhase::Pending || phase_ == LaneChangePhase::WaitingApproval) &&
      step.s_base > timing_.latest_start + kLatestStartTolerance)
    phase_ = LaneChangePhase::Missed;
  if (phase_ == LaneChangePhase::WaitingApproval) {
    const double since = step.blinker_on_since.value_or(step.now);
    if (approval_due(step.now, since, timing_.approval_delay) && target_lane_clear(step)) {
      approved_ = line_from(candidate_start(step));  // the path is fixed from here on
      approval_ = Approval{step.now, step.s_base, step.prepare_duration, step.blinker_on_since};
      phase_ = LaneChangePhase::Running;
    }
  }
  if (phase_ == LaneChangePhase::Running && approved_ && step.s_base > approved_->s_end)
    phase_ = LaneChangePhase::Done;
  return phase_ != before;
}

}  // namespace signalsim
