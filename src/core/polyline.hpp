// A polyline with cumulative arc length: lane shapes and route centerlines.
#pragma once

#include <vector>

#include "core/geometry.hpp"

namespace signalsim {

class Polyline {
 public:
  Polyline() = default;
  /// Consecutive duplicate points (closer than 1e-9 m) are dropped.
  explicit Polyline(std::vector<Vec2> points);

  const std::vector<Vec2>& points() const { return points_; }
  /// Arc length at each point; cumulative()[0] == 0.
  const std::vector<double>& cumulative() const { return cumulative_; }
  double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }
  bool empty() const { return points_.empty(); }
  std::size_t size() const { return points_.size(); }

  /// Point at arc length s, clamped to [0, length()].
  Vec2 point_at(double s) const;
  /// Heading of the segment containing s (the last segment at the end). 0 for < 2 points.
  double heading_at(double s) const;

  /// Index of the segment [i, i+1] containing arc length s (clamped).
  std::size_t segment_at(double s) const;

  /// Appends other, skipping its first point when it coincides with our last one.
  void append(const Polyline& other);

 private:
  std::vector<Vec2> points_;
  std::vector<double> cumulative_;
};

}  // namespace signalsim
