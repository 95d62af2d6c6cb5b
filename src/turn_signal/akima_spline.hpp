// Akima spline interpolation of one scalar series, as Autoware's autoware::interpolation::splineByAkima
// (the x/y interpolator behind motion_utils::resamplePoseVector's default call; docs/behaviour.md §T7).
#pragma once

#include <vector>

namespace signalsim {

/// Values at `query_keys` of the Akima spline through (base_keys[i], base_values[i]).
///
/// Preconditions: base_keys strictly increasing and as long as base_values. Queries are normally
/// inside [base_keys.front(), base_keys.back()]; outside, the first/last cubic piece is extended.
/// Slopes at the knots (m_i = secant slope of piece i):
///  - t_0 = m_0 and t_{n-1} = m_{n-2} (the end knots take their piece's secant),
///  - t_1 = (m_0 + m_1) / 2 and t_{n-2} = (m_{n-3} + m_{n-2}) / 2,
///  - otherwise Akima's weighted mean (|m_{i+1} - m_i| m_{i-1} + |m_{i-1} - m_{i-2}| m_i) / (sum of
///    weights), or the plain mean of m_{i-1} and m_i when the weights sum to less than 1e-5.
/// Two knots therefore give a straight line. One knot gives a constant; none gives zeros.
/// Throws std::invalid_argument when the key and value counts differ.
std::vector<double> akima_interpolate(const std::vector<double>& base_keys,
                                      const std::vector<double>& base_values,
                                      const std::vector<double>& query_keys);

}  // namespace signalsim
