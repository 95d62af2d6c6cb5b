// The clock of one pull out; see pull_out_departure.hpp.
#include "planning/pull_out_departure.hpp"

#include "core/time_ns.hpp"

namespace signalsim {

bool PullOutDeparture::engaged(double now) const { return to_ns(now) >= to_ns(engage_time_); }

void PullOutDeparture::observe(double now, bool driving_forward) {
  // updateData: set once engaged and driving forward, reset whenever either fails.
  if (!engaged(now) || !driving_forward) {
    first_engaged_forward_.reset();
  } else if (!first_engaged_forward_) {
    first_engaged_forward_ = now;
  }
}

std::optional<double> PullOutDeparture::time_since_first_engaged_forward(double now) const {
  if (!first_engaged_forward_) return std::nullopt;
  // Whole nanoseconds (as rclcpp::Duration): 2 s after 1.4 s is 2.0 here, not 1.9999999999999998.
  return static_cast<double>(to_ns(now) - to_ns(*first_engaged_forward_)) / 1e9;
}

bool PullOutDeparture::holds(double now) const {
  if (!engaged(now)) return true;  // not AUTONOMOUS: the vehicle does not move
  // needToPrepareBlinkerBeforeStartDrivingForward: elapsed < prepare_time_before_start (strict).
  const std::optional<double> since = time_since_first_engaged_forward(now);
  return since && to_ns(*since) < to_ns(prepare_time_);
}

}  // namespace signalsim
