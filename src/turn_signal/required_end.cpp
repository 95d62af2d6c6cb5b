#include "turn_signal/required_end.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

#include "turn_signal/akima_spline.hpp"

namespace signalsim {
namespace {

constexpr double kResampleInterval = 1.0;        // hard-coded in the reference (docs/behaviour.md §T10)
constexpr double kTerminalMergeThreshold = 0.1;  // motion_utils overlap_threshold (docs/behaviour.md §T7)
constexpr double kOverlapPointEpsilon = 1e-8;    // motion_utils removeOverlapPoints, per axis
constexpr double kDuplicatePointDistance = 1e-6; // motion_utils resample_utils close_s_threshold

struct StationPose {
  double s = 0.0;  ///< arc length along the lane centerline
  double yaw = 0.0;
};

// Yaw of each point toward the next one; the last point copies the one before (motion_utils
// insertOrientation, forward direction).
std::vector<double> forward_yaws(const std::vector<Vec2>& points) {
  std::vector<double> yaws(points.size(), 0.0);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) yaws[i] = azimuth(points[i], points[i + 1]);
  if (points.size() >= 2) yaws.back() = yaws[points.size() - 2];
  return yaws;
}

std::vector<double> cumulative_lengths(const std::vector<Vec2>& points) {
  std::vector<double> s(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) s[i] = s[i - 1] + distance(points[i - 1], points[i]);
  return s;
}

// 0, 1, 2, ... (< length), then the end: it replaces the last sample when closer than 0.1 m.
std::vector<double> resample_stations(double length) {
  std::vector<double> stations;
  for (double s = 0.0; s < length; s += kResampleInterval) stations.push_back(s);
  if (stations.empty()) return stations;
  if (length - stations.back() < kTerminalMergeThreshold) {
    stations.back() = length;
  } else {
    stations.push_back(length);
  }
  return stations;
}

std::vector<Vec2> without_overlapping_points(const std::vector<Vec2>& points) {
  std::vector<Vec2> kept;
  kept.reserve(points.size());
  for (const Vec2& p : points) {
    if (!kept.empty() && std::abs(p.x - kept.back().x) < kOverlapPointEpsilon &&
        std::abs(p.y - kept.back().y) < kOverlapPointEpsilon) {
      continue;
    }
    kept.push_back(p);
  }
  return kept;
}

// motion_utils validate_arguments: when this fails, resamplePoseVector returns its input unchanged.
bool can_resample(const std::vector<Vec2>& points, const std::vector<double>& stations) {
  if (points.size() < 2 || stations.size() < 2) return false;
  if (cumulative_lengths(points).back() < stations.back()) return false;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    if (distance(points[i], points[i + 1]) < kDuplicatePointDistance) return false;
  }
  return true;
}

// Akima in x and y over the points' own arc length, yaws from consecutive resampled points.
std::vector<StationPose> akima_resampled(const std::vector<Vec2>& points, const std::vector<double>& stations) {
  const std::vector<double> keys = cumulative_lengths(points);
  std::vector<double> xs;
  std::vector<double> ys;
  xs.reserve(points.size());
  ys.reserve(points.size());
  for (const Vec2& p : points) {
    xs.push_back(p.x);
    ys.push_back(p.y);
  }
  const std::vector<double> rx = akima_interpolate(keys, xs, stations);
  const std::vector<double> ry = akima_interpolate(keys, ys, stations);

  std::vector<Vec2> resampled(stations.size());
  for (std::size_t i = 0; i < stations.size(); ++i) resampled[i] = {rx[i], ry[i]};
  const std::vector<double> yaws = forward_yaws(resampled);

  std::vector<StationPose> poses(stations.size());
  for (std::size_t i = 0; i < stations.size(); ++i) poses[i] = {stations[i], yaws[i]};
  return poses;
}

// The reference's fallback: the raw centerline poses (yaw toward the next raw point).
std::vector<StationPose> raw_poses(const std::vector<Vec2>& points) {
  const std::vector<double> s = cumulative_lengths(points);
  const std::vector<double> yaws = forward_yaws(points);
  std::vector<StationPose> poses(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) poses[i] = {s[i], yaws[i]};
  return poses;
}

}  // namespace

double required_end_arc_length(const Polyline& centerline, double angle_threshold_deg) {
  const std::vector<Vec2>& raw = centerline.points();
  if (raw.size() < 2) return 0.0;

  const std::vector<double> stations = resample_stations(cumulative_lengths(raw).back());
  if (stations.empty()) return 0.0;

  // Resampling drops overlapping points first; if the rest cannot be resampled the raw poses are
  // scanned instead (e.g. a lane shorter than 0.1 m has a single station).
  const std::vector<Vec2> distinct = without_overlapping_points(raw);
  const std::vector<StationPose> poses =
      can_resample(distinct, stations) ? akima_resampled(distinct, stations) : raw_poses(raw);

  // docs/behaviour.md §T7 (code, not the design doc): scan from the END backward for the first pose whose
  // heading still differs from the final heading by at least the threshold.
  const double end_yaw = poses.back().yaw;
  const double threshold = deg_to_rad(angle_threshold_deg);
  for (auto it = poses.rbegin(); it != poses.rend(); ++it) {
    if (std::abs(normalize_angle(it->yaw - end_yaw)) >= threshold) return it->s;
  }
  return poses.back().s;
}

}  // namespace signalsim
