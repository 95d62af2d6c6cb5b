#include "traffic_light/judge_line.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {

// docs/behaviour.md §L2.2. Written with std::pow and the reference's evaluation order so results match the
// reference bit for bit on the same libm.
double calc_judge_line_dist_with_jerk_limit(double v, double a0, double a_s, double j_s, double t_d) {
  if (v <= 0.0) {
    return 0.0;
  }
  // t0: decide to stop, t1: braking starts (dead time), t2: a_s reached, t3: standstill.
  const double t1 = t_d;
  const double x1 = v * t1;

  const double v2 = v + (std::pow(a_s, 2) - std::pow(a0, 2)) / (2.0 * j_s);

  if (v2 <= 0.0) {
    // Case B (docs/behaviour.md §L2.2 quirk 1: a_s where the physical root has a0).
    const double t2 = -1.0 * (a_s + std::sqrt(a0 * a0 - 2.0 * j_s * v)) / j_s;
    const double x2 = v * t2 + a0 * std::pow(t2, 2) / 2.0 + j_s * std::pow(t2, 3) / 6.0;
    return std::max(0.0, x1 + x2);
  }

  // Case A (docs/behaviour.md §L2.2 quirk 2: t2 < 0 when a0 < a_s).
  const double t2 = (a_s - a0) / j_s;
  const double x2 = v * t2 + a0 * std::pow(t2, 2) / 2.0 + j_s * std::pow(t2, 3) / 6.0;
  const double x3 = -1.0 * std::pow(v2, 2) / (2.0 * a_s);
  return std::max(0.0, x1 + x2 + x3);
}

double calc_judge_line_dist_with_acc_limit(double v, double a_s, double t_d) {
  // docs/behaviour.md §L2.2 acceleration-only variant.
  return (v * v) / (2.0 * (-a_s)) + t_d * v;
}

}  // namespace signalsim
