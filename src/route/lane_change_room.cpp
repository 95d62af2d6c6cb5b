#include "route/lane_change_room.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace signalsim::sumo {
namespace {

// Peak curvature of the quintic shift of d metres over L: (10 / sqrt 3) d / L^2 (its second
// derivative; the slope only lowers the true curvature, so this errs on the safe side).
constexpr double kQuinticPeak = 5.773502691896258;

}  // namespace

double lane_change_room(double edge_length, bool first, const LaneChangeEgo& ego) {
  // base_link runs from its earliest position to edge end - base_link_to_front; on the first edge
  // it starts at depart_pos - base_link_to_front, so the room is edge length - depart_pos.
  const double start = first ? ego.depart_pos - ego.base_link_to_front : 0.0;
  return edge_length - ego.base_link_to_front - start;
}

double lane_change_speed(double edge_length, bool first, const EdgeSpeeds& speeds, const LaneChangeEgo& ego) {
  const double top = std::min(ego.max_speed, speeds.limit);
  const double room = lane_change_room(edge_length, first, ego);
  if (room <= 0.0) return top;
  const LaneChangeTimingDefault t = default_lane_change(room);
  const double base_start = first ? ego.depart_pos - ego.base_link_to_front : 0.0;
  const double from = base_start + t.lead + ego.base_link_to_front;  // the front on the edge [m]
  const double to = from + std::max(0.0, t.length);
  const double entry_at = first ? ego.depart_pos : 0.0;
  const double entry = first ? (ego.depart_speed >= 0.0 ? ego.depart_speed : top) : speeds.entry;
  double fastest = 0.0;
  for (double x = from;; x = std::min(x + 1.0, to)) {  // metre by metre (at most kLaneChangeLength)
    double v = top;
    if (std::isfinite(entry)) v = std::min(v, std::sqrt(entry * entry + 2.0 * ego.accel * std::max(0.0, x - entry_at)));
    if (std::isfinite(speeds.exit))
      v = std::min(v, std::sqrt(speeds.exit * speeds.exit + 2.0 * ego.decel * std::max(0.0, edge_length - x)));
    fastest = std::max(fastest, v);
    if (x >= to) break;
  }
  return fastest;
}

LaneChangeTimingDefault default_lane_change(double room) {
  LaneChangeTimingDefault out;
  out.lead = std::min(kLaneChangeLead, 0.2 * room);
  out.length = std::min(kLaneChangeLength, room - out.lead - kLaneChangeEndMargin);
  return out;
}

double lane_shift(const std::vector<double>& widths, int from, int to) {
  if (from == to) return 0.0;
  const int lo = std::min(from, to);
  const int hi = std::max(from, to);
  double shift = 0.5 * widths[static_cast<std::size_t>(lo)] + 0.5 * widths[static_cast<std::size_t>(hi)];
  for (int k = lo + 1; k < hi; ++k) shift += widths[static_cast<std::size_t>(k)];
  return shift;
}

double min_lane_change_length(double shift, double speed, const LaneChangeEgo& ego) {
  const double v = std::max(speed, 0.0);
  // The sharpest curvature the ego can drive at v: its steering, and its grip (a_lat = v^2 k).
  double curvature = 1.0 / kMinTurningRadius;
  if (v > 0.0 && ego.max_lateral_accel > 0.0) curvature = std::min(curvature, ego.max_lateral_accel / (v * v));
  const double needed = std::sqrt(kQuinticPeak * std::abs(shift) / curvature);
  return std::max(needed, kMinLaneChangeLength);
}

double lane_change_room_needed(double length) {
  if (length > kLaneChangeLength) return std::numeric_limits<double>::infinity();
  // length = room - lead - margin, lead = 20 % of the room (its kLaneChangeLead cap is never reached
  // for a length up to kLaneChangeLength).
  static_assert(0.2 * (kLaneChangeLength + kLaneChangeEndMargin) / 0.8 <= kLaneChangeLead);
  return (std::max(length, 0.0) + kLaneChangeEndMargin) / 0.8;
}

bool lane_change_fits(double room, double shift, double speed, const LaneChangeEgo& ego) {
  return default_lane_change(room).length >= min_lane_change_length(shift, speed, ego) - 1e-9;
}

}  // namespace signalsim::sumo
