// get_turn_signal_required_end_point of autoware_core's path_generator (utils.cpp, commit 2d693b82),
// step by step:
// 1. Centerline poses; fewer than 4 are resampled linearly at L/4 steps (s = 0; s < L; s += L/4,
//    the last station replaced by L when within motion_utils' overlap_threshold 0.1 m, else L
//    appended); still fewer than 4: nullopt.
// 2. A Trajectory<Pose>: x and y are natural cubic splines over the chord arc length
//    (autoware_trajectory's CubicSpline), orientations aligned with the spline's azimuth at every
//    base (align_orientation_with_trajectory_direction).
// 3. terminal_yaw = the yaw at the end; find_intervals over the bases (max_iter 0, so an interval
//    starts exactly at a base) of |normalize(yaw - terminal_yaw)| < threshold; the first interval's
//    start is the required end point (a centerline point, so its arc length is its base).
#include "required_end_point.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace signalsim::autoware_core {
namespace {

constexpr double kOverlapThreshold = 0.1;  // autoware::motion_utils::overlap_threshold [m]
constexpr double kDuplicateDistance = 1e-6;  // [m] points closer than this coincide
constexpr double kPi = 3.14159265358979323846;

double normalize_radian(double a) {
  const double v = std::fmod(a + kPi, 2.0 * kPi);
  return v < 0.0 ? v + kPi : v - kPi;
}

Point2 point_at(const std::vector<Point2>& pts, double s) {
  double acc = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const double seg = std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y);
    if (s <= acc + seg || i + 1 == pts.size()) {
      const double t = seg > 0.0 ? std::min(1.0, std::max(0.0, (s - acc) / seg)) : 0.0;
      return {pts[i - 1].x + t * (pts[i].x - pts[i - 1].x), pts[i - 1].y + t * (pts[i].y - pts[i - 1].y)};
    }
    acc += seg;
  }
  return pts.front();
}

// Step 1: path_generator's resampling of a centerline of fewer than 4 points.
std::vector<Point2> resample_short(const std::vector<Point2>& pts) {
  const double length = polyline_length(pts);
  const double interval = length / 4.0;
  std::vector<double> stations;
  for (double s = 0.0; s < length; s += interval) stations.push_back(s);
  if (!stations.empty() && length - stations.back() < kOverlapThreshold) {
    stations.back() = length;
  } else {
    stations.push_back(length);
  }
  std::vector<Point2> out;
  for (const double s : stations) out.push_back(point_at(pts, s));
  return out;
}

// First derivative of a natural cubic spline through (bases, values) at every base (the
// coefficients of autoware_trajectory's CubicSpline::compute_parameters).
std::vector<double> spline_slopes(const std::vector<double>& bases, const std::vector<double>& values) {
  const std::size_t n = bases.size() - 1;
  std::vector<double> h(n), alpha(n + 1, 0.0), l(n + 1, 1.0), mu(n + 1, 0.0), z(n + 1, 0.0);
  for (std::size_t i = 0; i < n; ++i) h[i] = bases[i + 1] - bases[i];
  for (std::size_t i = 1; i < n; ++i) {
    alpha[i] = 3.0 / h[i] * (values[i + 1] - values[i]) - 3.0 / h[i - 1] * (values[i] - values[i - 1]);
  }
  for (std::size_t i = 1; i < n; ++i) {
    l[i] = 2.0 * (bases[i + 1] - bases[i - 1]) - h[i - 1] * mu[i - 1];
    mu[i] = h[i] / l[i];
    z[i] = (alpha[i] - h[i - 1] * z[i - 1]) / l[i];
  }
  std::vector<double> b(n), c(n + 1, 0.0), d(n);
  for (std::size_t j = n; j-- > 0;) {
    c[j] = z[j] - mu[j] * c[j + 1];
    b[j] = (values[j + 1] - values[j]) / h[j] - h[j] * (c[j + 1] + 2.0 * c[j]) / 3.0;
    d[j] = (c[j + 1] - c[j]) / (3.0 * h[j]);
  }
  std::vector<double> slopes(b);
  slopes.push_back(b[n - 1] + 2.0 * c[n - 1] * h[n - 1] + 3.0 * d[n - 1] * h[n - 1] * h[n - 1]);
  return slopes;
}

}  // namespace

double polyline_length(const std::vector<Point2>& points) {
  double length = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    length += std::hypot(points[i].x - points[i - 1].x, points[i].y - points[i - 1].y);
  }
  return length;
}

std::optional<double> required_end_arc(const std::vector<Point2>& centerline, double angle_threshold_deg) {
  std::vector<Point2> pts = centerline.size() < 4 ? resample_short(centerline) : centerline;
  // The spline drops points that coincide (CubicSpline::build_impl) and fails below 4 points.
  std::vector<Point2> kept;
  for (const Point2& p : pts) {
    if (kept.empty() || std::hypot(p.x - kept.back().x, p.y - kept.back().y) > kDuplicateDistance) kept.push_back(p);
  }
  pts = std::move(kept);
  if (pts.size() < 4) return std::nullopt;
  // Trajectory bases: chord lengths, each at least machine epsilon (Trajectory<Point>::build).
  std::vector<double> bases{0.0}, xs{pts[0].x}, ys{pts[0].y};
  for (std::size_t i = 1; i < pts.size(); ++i) {
    const double dist = std::max(std::hypot(pts[i].x - pts[i - 1].x, pts[i].y - pts[i - 1].y),
                                 std::numeric_limits<double>::epsilon());
    bases.push_back(bases.back() + dist);
    xs.push_back(pts[i].x);
    ys.push_back(pts[i].y);
  }
  const std::vector<double> dx = spline_slopes(bases, xs);
  const std::vector<double> dy = spline_slopes(bases, ys);
  const double terminal_yaw = std::atan2(dy.back(), dx.back());
  const double threshold = angle_threshold_deg * kPi / 180.0;
  for (std::size_t i = 0; i < bases.size(); ++i) {
    if (std::fabs(normalize_radian(std::atan2(dy[i], dx[i]) - terminal_yaw)) < threshold) return bases[i];
  }
  return std::nullopt;
}

}  // namespace signalsim::autoware_core
