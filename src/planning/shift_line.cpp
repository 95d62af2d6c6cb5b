#include "planning/shift_line.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>

namespace signalsim {

double shift_blend(double u) {
  if (u <= 0.0) return 0.0;
  if (u >= 1.0) return 1.0;
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

double shift_blend_derivative(double u) {
  if (u <= 0.0 || u >= 1.0) return 0.0;
  const double w = u * (1.0 - u);
  return 30.0 * w * w;
}

double ShiftLine::offset_at(double s) const {
  if (s < s_start) return shift_start;
  if (s >= s_end) return shift_end;  // a zero-length line has jumped at s_start
  return shift_start + relative_shift() * shift_blend((s - s_start) / length());
}

double ShiftLine::heading_at(double s) const {
  const double len = length();
  if (len <= 0.0 || s <= s_start || s >= s_end) return 0.0;
  return relative_shift() * shift_blend_derivative((s - s_start) / len) / len;
}

std::optional<double> ShiftLine::s_at_offset(double offset) const {
  const double lo = std::min(shift_start, shift_end);
  const double hi = std::max(shift_start, shift_end);
  if (offset < lo || offset > hi) return std::nullopt;
  if (offset == shift_start || length() <= 0.0) return s_start;
  if (offset == shift_end) return s_end;  // the profile is flat there: invert the endpoint exactly
  // Solve B(u) = target by bisection: B is monotone, 60 halvings reach double precision.
  const double target = (offset - shift_start) / relative_shift();
  double a = 0.0;
  double b = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (a + b);
    if (shift_blend(m) < target) {
      a = m;
    } else {
      b = m;
    }
  }
  return s_start + b * length();
}

ShiftPlan::ShiftPlan(std::vector<ShiftLine> lines) : lines_(std::move(lines)) {
  for (std::size_t i = 0; i < lines_.size(); ++i) {
    if (!(lines_[i].s_end >= lines_[i].s_start))
      throw std::invalid_argument("shift line " + std::to_string(i) + " ends before it starts");
    if (i > 0 && lines_[i - 1].s_end > lines_[i].s_start)
      throw std::invalid_argument("shift lines " + std::to_string(i - 1) + " and " + std::to_string(i) +
                                  " overlap or are out of order");
  }
}

double ShiftPlan::offset_at(double s) const {
  if (lines_.empty()) return 0.0;
  if (s < lines_.front().s_start) return lines_.front().shift_start;
  // The last line starting at or before s decides: inside it its profile, after it its end.
  const auto it = std::upper_bound(lines_.begin(), lines_.end(), s,
                                   [](double value, const ShiftLine& line) { return value < line.s_start; });
  return std::prev(it)->offset_at(s);
}

double ShiftPlan::heading_at(double s) const {
  if (lines_.empty() || s < lines_.front().s_start) return 0.0;
  const auto it = std::upper_bound(lines_.begin(), lines_.end(), s,
                                   [](double value, const ShiftLine& line) { return value < line.s_start; });
  return std::prev(it)->heading_at(s);
}

double shift_time_from_limits(double lateral, double jerk, double accel) {
  const double l = std::abs(lateral);
  if (l == 0.0) return 0.0;
  double t = 0.0;
  // Quintic: peak jerk 60 l / T^3, peak acceleration (10 / sqrt(3)) l / T^2.
  if (jerk > 0.0) t = std::max(t, std::cbrt(60.0 * l / jerk));
  if (accel > 0.0) t = std::max(t, std::sqrt(10.0 / std::sqrt(3.0) * l / accel));
  return t;
}

double ShiftLengthPolicy::length_for(double lateral, double speed) const {
  if (fixed_length > 0.0) return fixed_length;
  const double t = shift_time_from_limits(lateral, lateral_jerk, lateral_accel);
  return std::max(std::abs(speed) * t, min_length);
}

ShiftPlan plan_lane_change(double s0, double width, double length) {
  return ShiftPlan({ShiftLine{s0, s0 + std::max(length, 0.0), 0.0, width}});
}

double avoidance_offset(const AvoidanceRequest& request) {
  bool pass_left = true;
  switch (request.side) {
    case AvoidSide::Left: pass_left = true; break;
    case AvoidSide::Right: pass_left = false; break;
    case AvoidSide::Auto: pass_left = 0.5 * (request.object_left + request.object_right) <= 0.0; break;
  }
  const double half = 0.5 * request.vehicle_width;
  return pass_left ? request.object_left + request.clearance + half
                   : request.object_right - request.clearance - half;
}

ShiftPlan plan_avoidance(const AvoidanceRequest& request) {
  const double offset = avoidance_offset(request);
  double out_end = request.s_object_start - request.longitudinal_margin - request.base_link_to_front;
  double back_start = request.s_object_end + request.longitudinal_margin + request.rear_overhang;
  if (back_start < out_end) out_end = back_start = 0.5 * (out_end + back_start);
  const double out_length = request.lengths.length_for(offset, request.speed);
  const double back_length = request.lengths.length_for(offset, request.speed);
  return ShiftPlan({ShiftLine{out_end - out_length, out_end, 0.0, offset},
                    ShiftLine{back_start, back_start + back_length, offset, 0.0}});
}

ShiftPlan plan_pull_out(double s0, double start_offset, double length) {
  return ShiftPlan({ShiftLine{s0, s0 + std::max(length, 0.0), start_offset, 0.0}});
}

ShiftPlan plan_pull_over(double s_goal, double goal_offset, double length) {
  return ShiftPlan({ShiftLine{s_goal - std::max(length, 0.0), s_goal, 0.0, goal_offset}});
}

}  // namespace signalsim
