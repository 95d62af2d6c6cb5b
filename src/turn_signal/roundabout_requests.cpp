#include "turn_signal/roundabout_requests.hpp"

#include "turn_signal/first_active.hpp"

#include <algorithm>
#include <vector>

#include "turn_signal/intersection_requests.hpp"
#include "turn_signal/required_end.hpp"
#include "turn_signal/signal_sections.hpp"

namespace signalsim {
namespace {

bool is_entry_or_exit(const Lanelet& l) {
  return l.roundabout_role == RoundaboutRole::Entry || l.roundabout_role == RoundaboutRole::Exit;
}

}  // namespace

std::vector<RoundaboutConnection> roundabout_connections(const RouteMap& route, RouteMap::Window window) {
  std::vector<RoundaboutConnection> out;
  const std::size_t last = std::min(window.last, route.size());
  for (std::size_t i = window.first; i < last; ++i) {
    if (!is_entry_or_exit(route.at(i))) continue;
    if (!out.empty() && i <= out.back().back_index) continue;  // each lanelet once (§T5.1)
    out.push_back(roundabout_connection_at(route, i));
  }
  return out;
}

const LaneSpanGeometry& RoundaboutRequests::geometry(const RouteMap& route, const RoundaboutConnection& connection,
                                                     double angle_threshold_deg) {
  auto cached = geometry_cache_.find(connection.front_index);
  if (cached != geometry_cache_.end()) return cached->second;
  return geometry_cache_
      .emplace(connection.front_index,
               lane_span_geometry(route, connection.front_index, connection.back_index, angle_threshold_deg))
      .first->second;
}

TurnSignalInfo RoundaboutRequests::update(const RouteMap& route, RouteMap::Window window, const EgoOnRoute& ego,
                                          const TurnSignalParameters& params) {
  if (route.empty() || window.first >= window.last) return {};
  // docs/behaviour.md §T5.1: collect ENTRIES and EXITS in path order.
  std::vector<RoundaboutConnection> entries;
  std::vector<RoundaboutConnection> exits;
  for (const RoundaboutConnection& c : roundabout_connections(route, window))
    (c.role == RoundaboutRole::Entry ? entries : exits).push_back(c);
  if (entries.empty() && exits.empty()) return {};

  const double base_search =
      params.turn_signal_search_time * ego.speed + params.turn_signal_roundabout_search_distance;
  const TurnIndicator on_entry = roundabout_command(params.turn_signal_roundabout_on_entry);
  const TurnIndicator on_exit = roundabout_command(params.turn_signal_roundabout_on_exit);
  const double threshold = params.turn_signal_roundabout_angle_threshold_deg;
  std::vector<TurnSignalInfo> queue;  // the reference's std::queue; in order, front first

  // docs/behaviour.md §T5.2: entry requests, queued first.
  for (const RoundaboutConnection& entry : entries) {
    const LaneSpanGeometry& shape = geometry(route, entry, threshold);
    if (!shape.has_centerline) continue;
    const Lanelet& e = route.at(entry.front_index);
    const double d_front = e.s_start - ego.s_front;  // vehicle front to the entry start
    const double search = e.turn_signal_distance.value_or(base_search);
    // Once a start is stored, the entry is never filtered by distance again.
    if (search <= d_front && !desired_starts_.contains(entry.front_index)) continue;
    const double desired_start = desired_starts_.try_emplace(entry.front_index, ego.s_base).first->second;
    TurnSignalInfo info;
    info.turn = on_entry;
    info.source = RequestSource::RoundaboutEntry;
    info.desired_start = desired_start;
    info.required_start = e.s_start;
    info.required_end = shape.required_end_s;
    info.desired_end = route.at(entry.back_index).s_end();

    // The exit this route uses, and the per-exit override tags on the entry lanelet.
    const std::optional<std::size_t> exit = roundabout_exit_used(route, entry);
    if (const std::optional<TurnIndicator> tagged = exit_tag_command(route, entry)) {
      info.turn = *tagged;
    } else if (on_entry == TurnIndicator::Disable) {
      desired_starts_.erase(entry.front_index);  // no entry signal at all
      continue;
    }
    // Persistence: keep the entry blinker until the end of the exit lanelet.
    if (params.turn_signal_roundabout_entry_indicator_persistence && exit) info.desired_end = route.at(*exit).s_end();
    if (info.desired_end - ego.s_base < 0.0) {
      desired_starts_.erase(entry.front_index);  // already passed
      continue;
    }
    queue.push_back(info);
  }

  // docs/behaviour.md §T5.3: exit requests, queued after all entries. No search distance (§T12.1.8).
  for (const RoundaboutConnection& exit : exits) {
    const LaneSpanGeometry& shape = geometry(route, exit, threshold);
    if (!shape.has_centerline) continue;
    const double s_exit_end = route.at(exit.back_index).s_end();
    if (s_exit_end - ego.s_base < 0.0) {
      desired_starts_.erase(exit.front_index);  // already passed
      continue;
    }
    const double required_start = route.at(exit.front_index).s_start;
    const std::optional<std::size_t> chain = exit_signal_chain_start(route, exit.front_index);
    const double start = chain ? route.at(*chain).s_start : required_start;
    if (start - ego.s_front >= 0.0) continue;  // the front has not reached it yet
    // The stored start is that position, not the ego's.
    const double desired_start = desired_starts_.try_emplace(exit.front_index, start).first->second;
    TurnSignalInfo info;
    info.turn = on_exit;  // may be DISABLE ("None"): it still occupies the queue
    info.source = RequestSource::RoundaboutExit;
    info.desired_start = desired_start;
    info.required_start = required_start;
    info.required_end = shape.required_end_s;
    info.desired_end = s_exit_end;
    queue.push_back(info);
  }

  // docs/behaviour.md §T12.1.7: the queue is "all entries, then all exits", not path order.
  return first_active(queue, ego);
}

}  // namespace signalsim
