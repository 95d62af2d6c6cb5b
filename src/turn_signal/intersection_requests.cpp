#include "turn_signal/intersection_requests.hpp"

#include <algorithm>
#include <vector>
#include <optional>
#include <set>

#include "turn_signal/first_active.hpp"
#include "turn_signal/required_end.hpp"
#include "turn_signal/signal_sections.hpp"

namespace signalsim {
namespace {

constexpr double kStopSpeed = 0.1;  // docs/behaviour.md §T10: hard-coded stop speed [m/s]

std::optional<TurnDirection> expected_direction(TurnIndicator behavior_command) {
  if (behavior_command == TurnIndicator::EnableLeft) return TurnDirection::Left;
  if (behavior_command == TurnIndicator::EnableRight) return TurnDirection::Right;
  return std::nullopt;  // "unknown"
}

bool is_turn(TurnDirection d) { return d == TurnDirection::Left || d == TurnDirection::Right; }

// docs/behaviour.md §T4.1 "near": the next lanelet ahead with a map successor turning the expected way
// starts within turn_signal_minimum_search_distance.
bool near_next_turn_lane(const RouteMap& route, RouteMap::Window window, const EgoOnRoute& ego,
                         std::optional<TurnDirection> expected, double minimum_search_distance) {
  if (!expected) return false;  // d_next undefined for "unknown"
  for (std::size_t i = route.index_at(ego.s_base); i < window.last; ++i) {
    const Lanelet& lanelet = route.at(i);
    const auto& successors = lanelet.successor_turn_directions;
    if (std::find(successors.begin(), successors.end(), *expected) != successors.end())
      return lanelet.s_end() - ego.s_base < minimum_search_distance;
  }
  return false;
}

// docs/behaviour.md §T4.1 "inside": base_link inside a predecessor turn lanelet (same direction) of the closest
// lanelet. SUMO lanes abut without overlapping, so this holds only on the shared boundary.
bool inside_predecessor_turn_lane(const RouteMap& route, const EgoOnRoute& ego,
                                  std::optional<TurnDirection> expected) {
  if (!expected) return false;
  const std::size_t closest = route.index_at(ego.s_base);
  if (closest == 0) return false;
  const Lanelet& q = route.at(closest - 1);
  return is_turn(q.turn_direction) && q.turn_direction == *expected && ego.s_base >= q.s_start &&
         ego.s_base <= q.s_end();
}

}  // namespace

TurnLaneGroup group_from(const RouteMap& route, std::size_t index) {
  TurnLaneGroup group{index, index, route.at(index).turn_direction};
  while (group.back_index + 1 < route.size() &&
         route.at(group.back_index + 1).turn_direction == group.direction)
    ++group.back_index;
  return group;
}

Polyline merged_centerline(const RouteMap& route, const TurnLaneGroup& group) {
  std::vector<Vec2> taken;
  for (std::size_t i = group.front_index; i <= group.back_index; ++i) {
    for (const Vec2& p : route.at(i).shape.points()) {
      const bool duplicate = std::any_of(taken.begin(), taken.end(),
                                         [&](const Vec2& q) { return distance(p, q) < 0.01; });
      if (!duplicate) taken.push_back(p);
    }
  }
  return Polyline(std::move(taken));
}

LaneSpanGeometry lane_span_geometry(const RouteMap& route, std::size_t front_index, std::size_t back_index,
                                    double angle_threshold_deg) {
  const Polyline merged = merged_centerline(route, TurnLaneGroup{front_index, back_index, TurnDirection::None});
  const double s_front = route.at(front_index).s_start;
  const double s_back = route.at(back_index).s_end();
  const double scale = merged.length() > 0.0 ? (s_back - s_front) / merged.length() : 1.0;
  return {merged.size() >= 2, s_front + required_end_arc_length(merged, angle_threshold_deg) * scale};
}

const LaneSpanGeometry& IntersectionRequests::geometry(const RouteMap& route, const TurnLaneGroup& group,
                                                       double angle_threshold_deg) {
  auto cached = geometry_cache_.find(group.front_index);
  if (cached != geometry_cache_.end()) return cached->second;
  return geometry_cache_
      .emplace(group.front_index, lane_span_geometry(route, group.front_index, group.back_index, angle_threshold_deg))
      .first->second;
}

TurnSignalInfo IntersectionRequests::update(const RouteMap& route, RouteMap::Window window,
                                            const EgoOnRoute& ego, TurnIndicator behavior_command,
                                            const TurnSignalParameters& params) {
  if (route.empty() || window.first >= window.last) return {};
  // docs/behaviour.md §T4.1: inputs computed once per cycle.
  const double base_search =
      params.turn_signal_search_time * ego.speed + params.turn_signal_intersection_search_distance;
  const auto expected = expected_direction(behavior_command);
  const bool near =
      near_next_turn_lane(route, window, ego, expected, params.turn_signal_minimum_search_distance);
  const bool inside = inside_predecessor_turn_lane(route, ego, expected);
  const auto needs = [&](TurnDirection attr) {
    if (is_turn(attr)) return true;
    return (near || inside) && ego.speed < kStopSpeed;  // docs/behaviour.md §T4.1 NEEDS
  };

  // docs/behaviour.md §T4.2: group consecutive lanelets with the same direction.
  std::vector<TurnLaneGroup>& groups = groups_;
  groups.clear();
  std::size_t next_unprocessed = window.first;
  for (std::size_t i = window.first; i < window.last; ++i) {
    if (i < next_unprocessed) continue;
    const Lanelet& lanelet = route.at(i);
    if (lanelet.roundabout_role != RoundaboutRole::None) continue;  // handled by §T5
    if (!needs(lanelet.turn_direction)) continue;
    groups.push_back(group_from(route, i));
    next_unprocessed = groups.back().back_index + 1;
  }

  // docs/behaviour.md §T4.3: groups -> queue of requests.
  std::vector<TurnSignalInfo>& queue = queue_;  // the reference's std::queue; in order, front first
  queue.clear();
  for (const TurnLaneGroup& group : groups) {
    const Lanelet& front = route.at(group.front_index);
    const double s_lane_start = front.s_start;
    const double s_lane_end = route.at(group.back_index).s_end();
    const LaneSpanGeometry& shape =
        geometry(route, group, params.turn_signal_intersection_angle_threshold_deg);
    if (!shape.has_centerline) continue;
    const double search = front.turn_signal_distance.value_or(base_search);  // per-lanelet override
    const double d_front = s_lane_start - ego.s_front;  // vehicle front to lane start
    const double d_back = s_lane_end - ego.s_base;      // base_link to lane end
    if (d_back < 0.0) {
      desired_starts_.erase(group.front_index);  // lane already passed
      continue;
    }
    if (search <= d_front) continue;  // strictly inside the search distance to activate (§T4.4)
    // docs/behaviour.md §T4.4: the desired start is the ego pose when the lane first came within reach.
    const double desired_start = desired_starts_.try_emplace(group.front_index, ego.s_base).first->second;
    TurnSignalInfo info;
    info.turn = command_of(group.direction);
    info.source = RequestSource::Intersection;
    info.desired_start = desired_start;
    info.required_start = s_lane_start;
    info.required_end = shape.required_end_s;
    info.desired_end = s_lane_end;
    queue.push_back(info);
  }

  return first_active(queue, ego);  // docs/behaviour.md §T4.3
}

}  // namespace signalsim
