// RouteGraph (sorted by id) and the seeded random walk.
#include "generate/route_graph.hpp"

#include <algorithm>
#include <numeric>
#include <set>

namespace signalsim::generate {

RouteGraph::RouteGraph(std::vector<GraphEdge> edges, std::vector<std::vector<GraphLink>> links) {
  links.resize(edges.size());
  std::vector<std::size_t> order(edges.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return edges[a].id < edges[b].id; });
  std::vector<std::size_t> new_index(edges.size());
  for (std::size_t k = 0; k < order.size(); ++k) new_index[order[k]] = k;
  edges_.reserve(edges.size());
  links_.resize(edges.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    edges_.push_back(std::move(edges[order[k]]));
    for (GraphLink link : links[order[k]]) {
      if (link.to >= new_index.size()) continue;
      link.to = new_index[link.to];
      links_[k].push_back(link);
    }
  }
  for (auto& out : links_) {
    std::sort(out.begin(), out.end(), [&](const GraphLink& a, const GraphLink& b) {
      return a.to != b.to ? a.to < b.to : a.via_length < b.via_length;
    });
    // One link per successor edge (several lanes connect the same pair): the shortest.
    out.erase(std::unique(out.begin(), out.end(), [](const GraphLink& a, const GraphLink& b) { return a.to == b.to; }),
              out.end());
  }
  for (std::size_t k = 0; k < links_.size(); ++k)
    if (!links_[k].empty()) starts_.push_back(k);
}

std::optional<Walk> random_walk(const RouteGraph& graph, Rng& rng, const WalkLimits& limits) {
  const double target = static_cast<double>(rng.between(static_cast<long long>(limits.min_length),
                                                        static_cast<long long>(limits.max_length)));
  if (graph.starts().empty()) return std::nullopt;
  Walk walk;
  const std::size_t start = graph.starts()[rng.index(graph.starts().size())];
  const auto& edges = graph.edges();
  walk.edges.push_back(start);
  walk.length = edges[start].length;
  std::set<std::string> visited = {edges[start].from_junction, edges[start].to_junction};
  std::vector<const GraphLink*> candidates;
  while (walk.length < target) {
    candidates.clear();
    for (const GraphLink& link : graph.successors(walk.edges.back()))
      if (!visited.contains(edges[link.to].to_junction)) candidates.push_back(&link);
    if (candidates.empty()) break;
    const GraphLink& next = *candidates[rng.index(candidates.size())];
    walk.edges.push_back(next.to);
    walk.length += next.via_length + edges[next.to].length;
    visited.insert(edges[next.to].to_junction);
  }
  if (walk.length < limits.min_length || walk.length > limits.max_length) return std::nullopt;
  return walk;
}

}  // namespace signalsim::generate
