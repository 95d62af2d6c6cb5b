// How the systems under test's messages write seconds: "5", "0.5" (a timeout), "12.30" (a step's time).
#pragma once

#include <cstdio>
#include <string>

namespace signalsim {

/// Shortest form of a duration [s]: 5 -> "5", 0.5 -> "0.5".
inline std::string seconds_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", seconds);
  return text;
}

/// A step's time [s] with two decimals: "12.30".
inline std::string time_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", seconds);
  return text;
}

}  // namespace signalsim
