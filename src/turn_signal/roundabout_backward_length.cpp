#include "turn_signal/roundabout_backward_length.hpp"

#include <algorithm>
#include <set>
#include <string>
#include <unordered_set>
#include <vector>

namespace signalsim {
namespace {

// Route predecessors of a route lanelet: the previous route lanelet (the route is a line).
std::vector<std::size_t> route_predecessors(std::size_t index) {
  if (index == 0) return {};
  return {index - 1};
}

// docs/behaviour.md §T5.4 (calculateMaxDistanceToDesiredStartPoint): the largest candidate, 0 when none.
double max_distance_to_desired_start(const RouteMap& route, std::size_t start, const std::string& ring,
                                     int max_depth, const std::map<std::size_t, double>& desired_starts) {
  struct SearchNode {
    std::size_t index = 0;
    double accumulated = 0.0;
    int depth = 0;
  };
  std::vector<SearchNode> stack{{start, 0.0, 0}};
  std::unordered_set<std::size_t> visited{start};
  std::set<std::size_t> desired_start_lanelets;
  double max_total = 0.0;

  while (!stack.empty()) {
    const SearchNode node = stack.back();
    stack.pop_back();
    const double accumulated_with_node = node.accumulated + route.at(node.index).length;
    if (max_depth >= 0 && node.depth >= max_depth) continue;  // depth guard
    for (const std::size_t prev : route_predecessors(node.index)) {
      if (visited.contains(prev)) continue;
      const Lanelet& p = route.at(prev);
      if (p.roundabout_role == RoundaboutRole::Entry && p.roundabout_id == ring) {
        // An entry of this roundabout: the lanelet holding its stored desired start, if any.
        if (const auto it = desired_starts.find(prev); it != desired_starts.end())
          desired_start_lanelets.insert(route.index_at(it->second));
      } else if (desired_start_lanelets.contains(prev)) {
        max_total = std::max(max_total, accumulated_with_node + p.length);
      }
      visited.insert(prev);
      stack.push_back({prev, accumulated_with_node, node.depth + 1});
    }
  }
  return max_total;
}

}  // namespace

double roundabout_backward_length(const RouteMap& route, std::size_t current_index, double default_backward_length,
                                  int max_depth, const std::map<std::size_t, double>& desired_starts) {
  if (current_index >= route.size()) return default_backward_length;
  const Lanelet& current = route.at(current_index);
  const bool in_ring_or_exit =
      current.roundabout_role == RoundaboutRole::Internal || current.roundabout_role == RoundaboutRole::Exit;
  if (!in_ring_or_exit || current.roundabout_id.empty()) return default_backward_length;
  return std::max(default_backward_length, max_distance_to_desired_start(route, current_index, current.roundabout_id,
                                                                          max_depth, desired_starts));
}

}  // namespace signalsim
