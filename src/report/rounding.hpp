// The rounding of every metric value: 1 mm / 1 ms, so that summary.json and results.csv are
// byte-stable across platforms and runs.
#pragma once

#include <cmath>

namespace signalsim {

/// `v` rounded to 3 decimals; never -0.
inline double round3(double v) {
  const double r = std::round(v * 1000.0) / 1000.0;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

}  // namespace signalsim
