// Stopping ("pass-judge line") distances used to classify a stop request (docs/behaviour.md §L2.2).
#pragma once

namespace signalsim {

/// docs/behaviour.md §L2.2 `calcJudgeLineDistWithJerkLimit`, reproduced exactly, quirks included.
/// Model: dead time t_d at speed v, then a constant-jerk ramp (j_s) from a0 to a_s, then constant
/// a_s to standstill. a_s and j_s are negative (Autoware's max_accel -2.8, max_jerk -5.0).
///   v <= 0                          -> 0
///   v2 = v + (a_s^2 - a0^2)/(2 j_s)
///   case A (v2 > 0): t2 = (a_s - a0)/j_s, result max(0, v t_d + x2(t2) + (-v2^2/(2 a_s)))
///   case B (v2 <= 0): t2 = -(a_s + sqrt(a0^2 - 2 j_s v))/j_s, result max(0, v t_d + x2(t2))
///   with x2(t) = v t + a0 t^2/2 + j_s t^3/6.
/// Quirk 1: case B uses a_s where the physical root uses a0 (v=0.5, a0=0 -> 0.1948 m, not 0.399).
/// Quirk 2: with a0 < a_s case A runs with a negative t2 (v=10, a0=-3 -> 22.872 m).
/// Quirk 3: a0 is not clamped; a positive a0 lengthens the distance.
/// Returns metres, never negative. NaN arithmetic (e.g. a0^2 - 2 j_s v < 0 for a positive j_s)
/// yields 0, as std::max(0.0, NaN) does in the reference. Never throws.
double calc_judge_line_dist_with_jerk_limit(double v, double a0, double a_s, double j_s, double t_d);

/// docs/behaviour.md §L2.2 `calcJudgeLineDistWithAccLimit`: v^2 / (2 (-a_s)) + t_d v.
/// (Not used by the judge; tested upstream: v=10, a_s=-3, t_d=1 -> 26.67.) Never throws.
double calc_judge_line_dist_with_acc_limit(double v, double a_s, double t_d);

}  // namespace signalsim
