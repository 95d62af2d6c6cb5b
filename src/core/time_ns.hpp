// Times in integer nanoseconds, as rclcpp::Time compares them (docs/behaviour.md §L1.5 choice): the one
// conversion the light judge, the perception model, the V2I channel and the behaviour modules' clocks
// (approval, hold and departure waits, docs/behaviour.md §T8.2) share.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace signalsim {

/// Seconds to nanoseconds, saturated at +-4e18 ns (about 127 years): llround of a larger finite time
/// is unspecified, and the difference of two saturated times (now - stamp) stays within int64
/// (fuzzing found `now - stamp` overflowing for a stamp of 1e300 s).
inline std::int64_t to_ns(double seconds) {
  constexpr double kMaxNs = 4e18;
  return static_cast<std::int64_t>(std::llround(std::clamp(seconds * 1e9, -kMaxNs, kMaxNs)));
}

}  // namespace signalsim
