// An operator's approval of a behaviour module's maneuver (Autoware's RTC with enable_rtc: true), as
// a scenario times it: the one rule the lane change and the avoidance share (docs/behaviour.md §T8.2).
// Approval comes `delay` seconds after the module began to wait for it; a delay of 0 approves at
// once, as Autoware's automatic mode (enable_rtc: false) does a safe maneuver.
#pragma once

#include "core/time_ns.hpp"

namespace signalsim {

/// Has the approval come at `now` [s] for a module waiting since `since` [s]: now - since >= delay,
/// compared in integer nanoseconds (docs/behaviour.md §T8.2).
inline bool approval_due(double now, double since, double delay) {
  return to_ns(now) - to_ns(since) >= to_ns(delay);
}

}  // namespace signalsim
