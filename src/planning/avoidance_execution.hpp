// When an avoidance's shift lines take effect: the waiting-for-approval phase of Autoware's static
// obstacle avoidance module and its stop_on_approval hold (docs/behaviour.md §T8.2 "Avoidance"),
// executed on the route coordinate s.
//
//   Pending          the module does not run yet.
//   WaitingApproval  the module runs, nothing is registered: the ego keeps its lane and brakes to rest
//                    with base_link at the wait point. Approved at the first step where the approval
//                    delay has passed since the module began to wait (operator_approval.hpp; 0: the
//                    module's first step, as Autoware's automatic mode).
//   Holding          candidate_path_turn_signal stop_on_approval only: approved while the ego stood
//                    at the wait point (the step before: stopped, base_link within 0.5 m of it).
//                    The lines are registered, the ego stays where it is until
//                    turn_signal_on_approval_hold_duration has passed since approval (>=, integer ns).
//   Running          the lines are registered: the ego drives them.
//
// All transitions of one step happen in update(), before the module runs that step: an approval
// (or a release) is seen by the step it comes in.
#pragma once

#include <optional>

namespace signalsim {

/// The fixed facts of one avoidance, decided when the scenario is planned.
struct AvoidanceTiming {
  /// [m] base_link s the ego waits at: the first line's start less stop_buffer (docs/behaviour.md §T8.2).
  double wait_point = 0.0;
  double approval_delay = 0.0;  ///< [s] after the module began to wait
};

/// Autoware's avoidance.stop.stop_buffer [m]: the wait point lies this far before the first shift.
inline constexpr double kAvoidanceStopBuffer = 1.0;

enum class AvoidancePhase { Pending, WaitingApproval, Holding, Running };

/// "pending", "waiting_approval", "holding", "running".
const char* to_string(AvoidancePhase phase);

/// The phase machine of one avoidance (see the file comment). A value type; no SUMO.
class AvoidanceExecution {
 public:
  struct Step {
    double now = 0.0;     ///< [s]
    double s_base = 0.0;   ///< [m] base_link's route s
    bool stopped = false;  ///< Autoware's isVehicleStopped (|v| < 0.3 m/s, AvoidanceSignal::kStoppedSpeed)
  };

  AvoidanceExecution() = default;
  /// `stop_on_approval`: the policy of that name; `hold_duration` [s]: turn_signal_on_approval_hold_duration.
  AvoidanceExecution(AvoidanceTiming timing, bool stop_on_approval, double hold_duration)
      : timing_(timing), stop_on_approval_(stop_on_approval), hold_duration_(hold_duration) {}

  /// A step of the running module. Returns true when the phase changed.
  bool update(const Step& step);

  AvoidancePhase phase() const { return phase_; }
  const AvoidanceTiming& timing() const { return timing_; }
  /// The lines are registered (Holding or Running).
  bool approved() const { return phase_ == AvoidancePhase::Holding || phase_ == AvoidancePhase::Running; }

  /// Where base_link must come to rest [m from s_base]: the wait point while waiting for approval,
  /// 0 (here) while holding; nullopt otherwise.
  std::optional<double> distance_to_hold_point(double s_base) const;

  /// updateEgoBehavior's TH_STOP_POSITION [m]: "at the stop point" within this of it.
  static constexpr double kAtStopPoint = 0.5;

 private:
  AvoidanceTiming timing_;
  bool stop_on_approval_ = false;
  double hold_duration_ = 0.0;
  AvoidancePhase phase_ = AvoidancePhase::Pending;
  double waiting_since_ = 0.0;
  double holding_since_ = 0.0;
  bool stopped_at_wait_point_ = false;  // seen at the previous waiting step
};

}  // namespace signalsim
