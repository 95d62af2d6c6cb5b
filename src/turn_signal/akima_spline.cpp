#include "turn_signal/akima_spline.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace signalsim {
namespace {

// Below this sum of Akima weights the neighbouring secants are (almost) collinear: average them.
constexpr double kFlatWeightSum = 1e-5;

struct CubicPiece {
  double cubic = 0.0;     // coefficient of h^3
  double quadratic = 0.0; // coefficient of h^2
  double slope = 0.0;     // coefficient of h (slope at the piece's left knot)
  double value = 0.0;     // value at the piece's left knot
  double at(double h) const { return value + (slope + (quadratic + cubic * h) * h) * h; }
};

std::vector<double> secant_slopes(const std::vector<double>& keys, const std::vector<double>& values) {
  std::vector<double> m(keys.size() - 1);
  for (std::size_t i = 0; i + 1 < keys.size(); ++i) m[i] = (values[i + 1] - values[i]) / (keys[i + 1] - keys[i]);
  return m;
}

// Checked in this order, as in the reference: the last knot before the knot next to either end.
std::vector<double> knot_slopes(const std::vector<double>& m) {
  const std::size_t n = m.size() + 1;
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 0) {
      t[i] = m.front();
    } else if (i == n - 1) {
      t[i] = m.back();
    } else if (i == 1 || i == n - 2) {
      t[i] = (m[i - 1] + m[i]) / 2.0;
    } else {
      const double w_left = std::abs(m[i + 1] - m[i]);
      const double w_right = std::abs(m[i - 1] - m[i - 2]);
      const double weight_sum = w_left + w_right;
      t[i] = std::abs(weight_sum) < kFlatWeightSum ? (m[i - 1] + m[i]) / 2.0
                                                    : (w_left * m[i - 1] + w_right * m[i]) / weight_sum;
    }
  }
  return t;
}

// Cubic Hermite piece between knots i and i+1 with the knot slopes t.
std::vector<CubicPiece> hermite_pieces(const std::vector<double>& keys, const std::vector<double>& values,
                                       const std::vector<double>& m, const std::vector<double>& t) {
  std::vector<CubicPiece> pieces(m.size());
  for (std::size_t i = 0; i < m.size(); ++i) {
    const double h = keys[i + 1] - keys[i];
    pieces[i].cubic = (t[i] + t[i + 1] - 2.0 * m[i]) / (h * h);
    pieces[i].quadratic = (3.0 * m[i] - 2.0 * t[i] - t[i + 1]) / h;
    pieces[i].slope = t[i];
    pieces[i].value = values[i];
  }
  return pieces;
}

// A query exactly on an inner knot is evaluated at the END of the piece to its left (the reference
// advances while knot[j+1] < query); outside the keys the first/last piece is extended.
std::size_t piece_index(const std::vector<double>& keys, double query) {
  const auto first_right_knot = keys.begin() + 1;
  const auto last_right_knot = keys.end() - 1;
  return static_cast<std::size_t>(std::lower_bound(first_right_knot, last_right_knot, query) - first_right_knot);
}

}  // namespace

std::vector<double> akima_interpolate(const std::vector<double>& base_keys, const std::vector<double>& base_values,
                                      const std::vector<double>& query_keys) {
  if (base_keys.size() != base_values.size()) {
    throw std::invalid_argument("akima_interpolate: base_keys and base_values differ in size");
  }
  if (base_keys.size() < 2) {
    return std::vector<double>(query_keys.size(), base_values.empty() ? 0.0 : base_values.front());
  }
  const std::vector<double> m = secant_slopes(base_keys, base_values);
  const std::vector<CubicPiece> pieces = hermite_pieces(base_keys, base_values, m, knot_slopes(m));

  std::vector<double> result;
  result.reserve(query_keys.size());
  for (const double q : query_keys) {
    const std::size_t j = piece_index(base_keys, q);
    result.push_back(pieces[j].at(q - base_keys[j]));
  }
  return result;
}

}  // namespace signalsim
