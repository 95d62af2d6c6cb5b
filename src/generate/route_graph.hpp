// The net as the generator walks it: normal edges a passenger car may drive and the turns between
// them, as a plain value (built once per net from the NetIndex by net_graph.hpp; SUMO-free here).
//
// Random walk (the route choice of `signalsim generate`, fixed so that a seed gives the same routes
// on every machine; every draw is Rng::index):
//   1. target := Rng::between(min_length, max_length) whole metres;
//   2. start  := edges_with_successors[Rng::index(count)] (edges sorted by id, only those with at
//                least one successor);
//   3. repeat while length < target: the candidates are the successors of the last edge (sorted by
//      id) whose end junction the walk has not visited yet (the route never visits a junction
//      twice: no loops, every junction id on it is unique); none -> stop; else take
//      candidates[Rng::index(count)] and add its connection's internal length and its own length;
//   4. accepted when min_length <= length <= max_length, else rejected (a dead end, or the last
//      edge overshot). The length is the planned lanes' length, as build_route will measure it
//      (the first internal lane of each connection stands for the junction).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "generate/rng.hpp"

namespace signalsim::generate {

struct GraphEdge {
  std::string id;
  std::string from_junction;
  std::string to_junction;
  double length = 0.0;  ///< [m] (its longest lane a passenger car may use)
};

struct GraphLink {
  std::size_t to = 0;         ///< index of the successor edge
  double via_length = 0.0;    ///< [m] the connection's internal lane(s) through the junction
};

class RouteGraph {
 public:
  /// `edges` in any order; `links[i]` the successors of edges[i] (same order as `edges`). The graph
  /// sorts both by edge id, so the file order of the net does not matter.
  RouteGraph(std::vector<GraphEdge> edges, std::vector<std::vector<GraphLink>> links);

  const std::vector<GraphEdge>& edges() const { return edges_; }
  const std::vector<GraphLink>& successors(std::size_t edge) const { return links_.at(edge); }
  /// Indices of the edges with at least one successor, ascending (by id).
  const std::vector<std::size_t>& starts() const { return starts_; }

 private:
  std::vector<GraphEdge> edges_;
  std::vector<std::vector<GraphLink>> links_;
  std::vector<std::size_t> starts_;
};

struct WalkLimits {
  double min_length = 300.0;   ///< [m]
  double max_length = 1500.0;  ///< [m]
};

struct Walk {
  std::vector<std::size_t> edges;  ///< graph indices, in driving order
  double length = 0.0;             ///< [m] as the walk measured it
};

/// One random walk (algorithm above). nullopt when rejected; it always consumes the same draws for
/// the same graph state, so the sequence of walks is a function of the seed.
std::optional<Walk> random_walk(const RouteGraph& graph, Rng& rng, const WalkLimits& limits);

}  // namespace signalsim::generate
