// Stops and red-light crossings of a signalsim-driven run; see light_outcomes.hpp.
#include "step/light_outcomes.hpp"

#include <algorithm>

namespace signalsim {

bool held_by_module(const std::string& speed_limited_by) {
  return speed_limited_by == "lane_change_hold" || speed_limited_by == "avoidance_hold" ||
         speed_limited_by == "pull_out_wait" || speed_limited_by == "pull_over_goal";
}

void LightOutcomes::observe(const TimelineRow& row, const std::vector<LightStep>& lights, const LightStep* stopping,
                            const std::optional<LeaderInfo>& leader, const RouteMap& route, RunRecord& record) {
  // A stop: the first step at rest while a stop is requested; a new one only after moving again.
  // The error is measured against the stop line minus stop_margin, not the judge's stop point,
  // which restart suppression moves to wherever the ego stands (docs/behaviour.md §L1.6).
  // A rest a module's hold or the pull-over goal set (the row's speed_limited_by) is theirs, not a
  // stop at the light ahead: a lane change waiting for a gap before a red light is recorded as such.
  const bool at_rest = row.speed < kRestSpeed;
  if (at_rest && stopping && !resting_ && !held_by_module(row.speed_limited_by)) {
    const double stop_s = stopping->light->s_stop_line - stop_margin_;
    LightStop stop;
    stop.tl_id = stopping->light->tls_id;
    stop.time = row.time;
    stop.stop_s = stop_s;
    stop.rest_s = row.s_front;
    stop.error = row.s_front - stop_s;
    stop.decision = stopping->result.decision;
    stop.worst_level = worst_level_;
    const double to_go = stop_s - row.s_front;
    if (to_go > kQueueGap) {
      if (leader && leader->gap < to_go) stop.queued_behind = leader->id;
      const std::size_t here = route.index_at(row.s_front);
      if (stop.queued_behind.empty() && here != stopping->light->route_index)
        for (std::size_t i = here; i < stopping->light->route_index; ++i)
          if (route.at(i).is_internal) {  // the junction the ego is in, or the next one ahead
            stop.waiting_at = route.at(i).junction_id;
            break;
          }
    }
    record.stops.push_back(stop);
    resting_ = true;
  }
  if (!at_rest) resting_ = false;
  if (row.stop_level) worst_level_ = std::max(worst_level_, *row.stop_level);
  if (!stopping) worst_level_ = StopLevel::Normal;
  // Red crossings (crossed_on_red), at every light in the window, not only the nearest.
  for (const LightStep& light : lights) {
    auto previous = previous_.find(light.light->route_index);
    if (previous != previous_.end() &&
        crossed_on_red(previous->second.front, row.s_front, light.light->s_stop_line, previous->second.state))
      record.red_violations.push_back({light.light->tls_id, row.time, row.s_front});
    previous_[light.light->route_index] = {row.s_front, light.own_state};
  }
}

}  // namespace signalsim
