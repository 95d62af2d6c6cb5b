#include "core/polyline.hpp"

#include <algorithm>

namespace signalsim {

Polyline::Polyline(std::vector<Vec2> points) {
  points_.reserve(points.size());
  cumulative_.reserve(points.size());
  for (const Vec2& p : points) {
    if (!points_.empty() && distance(points_.back(), p) < 1e-9) continue;
    cumulative_.push_back(points_.empty() ? 0.0 : cumulative_.back() + distance(points_.back(), p));
    points_.push_back(p);
  }
}

std::size_t Polyline::segment_at(double s) const {
  if (points_.size() < 2) return 0;
  auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), s);
  std::size_t i = it == cumulative_.begin() ? 0 : static_cast<std::size_t>(it - cumulative_.begin()) - 1;
  return std::min(i, points_.size() - 2);
}

Vec2 Polyline::point_at(double s) const {
  if (points_.empty()) return {};
  if (points_.size() == 1) return points_.front();
  s = std::clamp(s, 0.0, length());
  const std::size_t i = segment_at(s);
  const double seg = cumulative_[i + 1] - cumulative_[i];
  const double t = seg > 0.0 ? (s - cumulative_[i]) / seg : 0.0;
  return points_[i] + t * (points_[i + 1] - points_[i]);
}

double Polyline::heading_at(double s) const {
  if (points_.size() < 2) return 0.0;
  const std::size_t i = segment_at(std::clamp(s, 0.0, length()));
  return azimuth(points_[i], points_[i + 1]);
}

void Polyline::append(const Polyline& other) {
  for (const Vec2& p : other.points_) {
    if (!points_.empty() && distance(points_.back(), p) < 1e-9) continue;
    cumulative_.push_back(points_.empty() ? 0.0 : cumulative_.back() + distance(points_.back(), p));
    points_.push_back(p);
  }
}

}  // namespace signalsim
