#include "turn_signal/exit_signal_marking.hpp"

#include <vector>

namespace signalsim {
namespace {

bool in_roundabout(const Lanelet& l) { return l.roundabout_role != RoundaboutRole::None && !l.roundabout_id.empty(); }

// Marks one passage [first, end) of the same roundabout.
void mark_passage(std::vector<Lanelet>& lanelets, std::size_t first, std::size_t end) {
  if (lanelets[end - 1].roundabout_role != RoundaboutRole::Exit) return;  // the route ends on the ring
  std::size_t exit_front = end - 1;
  while (exit_front > first && lanelets[exit_front - 1].roundabout_role == RoundaboutRole::Exit) --exit_front;
  // The ring lanelet the ego's exit branches from is exit_front - 1: search the branching point before it.
  std::size_t mark_from = first;
  for (std::size_t i = first; i + 1 < exit_front; ++i) {
    if (lanelets[i].roundabout_role == RoundaboutRole::Internal && lanelets[i].leaves_ring_at_end) mark_from = i + 1;
  }
  for (std::size_t i = mark_from; i < exit_front; ++i) {
    if (lanelets[i].roundabout_role != RoundaboutRole::Internal) continue;  // the entry is never marked
    lanelets[i].params.try_emplace("enable_exit_turn_signal", "true");       // an existing value is kept
  }
}

}  // namespace

RouteMap mark_exit_signal_lanes(RouteMap route) {
  std::vector<Lanelet> lanelets(route.lanelets().begin(), route.lanelets().end());
  std::size_t i = 0;
  while (i < lanelets.size()) {
    if (!in_roundabout(lanelets[i])) {
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    while (end < lanelets.size() && in_roundabout(lanelets[end]) &&
           lanelets[end].roundabout_id == lanelets[i].roundabout_id)
      ++end;
    mark_passage(lanelets, i, end);
    i = end;
  }
  return RouteMap(std::move(lanelets));
}

RouteMap route_for_decider(RouteMap route, const TurnSignalParameters& params) {
  if (!params.turn_signal_roundabout_exit_signal_from_previous_exit) return route;
  return mark_exit_signal_lanes(std::move(route));
}

}  // namespace signalsim
