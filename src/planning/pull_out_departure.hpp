// When a pull out may leave its start: engagement and the start planner's wait with the blinker
// before driving forward (docs/behaviour.md §T8.2 "Pull out"), on the run's clock.
//
//   engaged           signalsim's stand-in for Autoware's operation mode AUTONOMOUS (the engage
//                     button): from `engage_time` on (the run's first step + pull_out.engage_delay).
//                     Before it the ego stands still.
//   first engaged forward  the first step engaged and driving forward (after any backing up):
//                     Autoware's first_engaged_and_driving_forward_time, cleared whenever either
//                     condition fails.
//   holds             not engaged yet, or engaged forward for less than prepare_time_before_start
//                     (strict, integer ns): Autoware's run() plans the waiting-approval stop path
//                     then (needToPrepareBlinkerBeforeStartDrivingForward), the ego stays at rest.
#pragma once

#include <optional>

namespace signalsim {

/// The clock of one pull out. A value type; no SUMO.
class PullOutDeparture {
 public:
  PullOutDeparture() = default;
  /// `engage_time` [s]: SUMO time the ego is engaged from; `prepare_time` [s]: prepare_time_before_start.
  PullOutDeparture(double engage_time, double prepare_time) : engage_time_(engage_time), prepare_time_(prepare_time) {}

  /// Engaged at `now` [s]: now >= engage_time (integer ns).
  bool engaged(double now) const;

  /// A step at `now` driving forward or not (backing up); notes or clears the first engaged forward time.
  void observe(double now, bool driving_forward);

  /// [s] since the first engaged forward step, in whole nanoseconds; nullopt while not engaged or not
  /// driving forward.
  std::optional<double> time_since_first_engaged_forward(double now) const;

  /// The start planner holds the ego at `now` (see the file comment).
  bool holds(double now) const;

 private:
  double engage_time_ = 0.0;
  double prepare_time_ = 0.0;
  std::optional<double> first_engaged_forward_;
};

}  // namespace signalsim
