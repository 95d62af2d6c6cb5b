// The phases of one avoidance; see avoidance_execution.hpp.
#include "planning/avoidance_execution.hpp"

#include <cmath>

#include "core/time_ns.hpp"
#include "planning/operator_approval.hpp"

namespace signalsim {

const char* to_string(AvoidancePhase phase) {
  switch (phase) {
    case AvoidancePhase::Pending: return "pending";
    case AvoidancePhase::WaitingApproval: return "waiting_approval";
    case AvoidancePhase::Holding: return "holding";
    case AvoidancePhase::Running: return "running";
  }
  return "?";
}

std::optional<double> AvoidanceExecution::distance_to_hold_point(double s_base) const {
  // insertWaitPoint: an ego more than stop_buffer past the wait point has overrun it, and no wait
  // point is inserted (docs/behaviour.md §T8.2 "Avoidance").
  if (phase_ == AvoidancePhase::WaitingApproval) {
    const double to_wait_point = timing_.wait_point - s_base;
    return to_wait_point < -kAvoidanceStopBuffer ? std::nullopt : std::optional<double>(to_wait_point);
  }
  if (phase_ == AvoidancePhase::Holding) return 0.0;  // insertDecelPoint at the ego's position
  return std::nullopt;
}

bool AvoidanceExecution::update(const Step& step) {
  const AvoidancePhase before = phase_;
  if (phase_ == AvoidancePhase::Pending) {
    phase_ = AvoidancePhase::WaitingApproval;
    waiting_since_ = step.now;
  }
  if (phase_ == AvoidancePhase::WaitingApproval) {
    if (approval_due(step.now, waiting_since_, timing_.approval_delay)) {
      // updateEgoBehavior: the hold needs the wait point inserted the cycle before and the ego
      // stopped at it then (stopped_on_avoidance_stop_point_).
      phase_ = stop_on_approval_ && stopped_at_wait_point_ ? AvoidancePhase::Holding : AvoidancePhase::Running;
      holding_since_ = step.now;
    } else {
      stopped_at_wait_point_ = step.stopped && std::abs(step.s_base - timing_.wait_point) < kAtStopPoint;
    }
  }
  // stillStopAndOutputTurnSignal: released at the first step with elapsed >= the hold duration (the
  // approval step itself for a duration of 0).
  if (phase_ == AvoidancePhase::Holding && to_ns(step.now) - to_ns(holding_since_) >= to_ns(hold_duration_))
    phase_ = AvoidancePhase::Running;
  return phase_ != before;
}

}  // namespace signalsim
