// SUMO's best-lanes computation (MSVehicle::updateBestLanes) on signalsim's NetIndex; see the header.
#include "route/sumo_lane_choice.hpp"

#include <algorithm>
#include <cstdlib>

namespace signalsim::sumo {
namespace {

// One lane of an edge in the look-ahead (SUMO's LaneQ).
struct LaneQ {
  double length = 0.0;
  double current_length = 0.0;
  int offset = 0;              // bestLaneOffset
  bool continues = true;       // allowsContinuation
  int next = -1;               // the lane index of its best continuation on the next edge
  int priority = -1;           // nextLinkPriority: of the link to `next` (1 priority, 0 not, -1 none)
};

// The connections from lane `from` of edge `a` to edge `b`.
std::vector<const NetConnection*> links(const NetIndex& net, const NetEdge& a, int from, const NetEdge& b) {
  std::vector<const NetConnection*> out;
  for (const NetConnection& c : net.connections_from_lane(a.lanes[static_cast<std::size_t>(from)].id))
    if (c.to_edge == b.id && c.to_lane >= 0 && c.to_lane < static_cast<int>(b.lanes.size())) out.push_back(&c);
  return out;
}

// MSLink::havePriority: an upper-case link state. A signalised link's state is the light's at the
// moment; it counts as a priority link (a green phase), the same for every lane of the approach.
int priority_of(const NetConnection& c) {
  if (!c.tl.empty()) return 1;
  return (c.state >= 'A' && c.state <= 'Z') ? 1 : 0;
}

// The brake gap of SUMO's Krauss model, semi-implicit Euler (MSCFModel::brakeGapEuler).
double brake_gap(double speed, double decel, double tau, double dt) {
  const double reduction = decel * dt;
  if (reduction <= 0.0) return speed * tau;
  const int steps = static_cast<int>(speed / reduction);
  return dt * (steps * speed - reduction * steps * (steps + 1) / 2.0) + speed * tau;
}

// Offsets towards the best lanes [lo, hi] and the lanes a lane change may not reach (the lane to
// the right or left forbids the class): SUMO's "set bestLaneOffset for all lanes".
void set_offsets(std::vector<LaneQ>& lanes, const NetEdge& edge, int best, int best_max, const SumoLookahead& v,
                 bool by_priority) {
  bool right_forbidden = false;
  int left_forbidden = -1;
  const LaneQ& reference = lanes[static_cast<std::size_t>(best)];  // live, as SUMO's clanes[bestThisIndex]
  for (int index = 0; index < static_cast<int>(lanes.size()); ++index) {
    LaneQ& j = lanes[static_cast<std::size_t>(index)];
    const bool worse = j.length < reference.length ||
                       (by_priority && ((j.length == reference.length && std::abs(j.offset) > std::abs(reference.offset)) ||
                                        j.priority < reference.priority));
    if (!worse) {
      if (by_priority) j.offset = 0;
      continue;
    }
    j.offset = std::abs(best - index) < std::abs(best_max - index) ? best - index : best_max - index;
    if (by_priority && j.priority < reference.priority) j.length = j.current_length;
    const auto permits_at = [&](int k) {
      return k >= 0 && k < static_cast<int>(edge.lanes.size()) && lane_permits(edge.lanes[static_cast<std::size_t>(k)], v.vclass);
    };
    if (j.offset < 0 && (!permits_at(index - 1) || right_forbidden)) {
      right_forbidden = true;
      if (!by_priority || j.length == j.current_length) j.length = 0.0;
    } else if (j.offset > 0 && !permits_at(index + 1)) {
      left_forbidden = index;
    }
  }
  for (int k = left_forbidden; k >= 0; --k) {
    LaneQ& j = lanes[static_cast<std::size_t>(k)];
    if (!by_priority || j.length == j.current_length) j.length = 0.0;
  }
}

// The lanes of each edge SUMO looks at from route edge `start` on (at least 4 edges, more up to its
// look-ahead distance): each permitted lane's length, and whether it continues to the next edge.
std::vector<std::vector<LaneQ>> lookahead_lanes(const NetIndex& net, const std::vector<const NetEdge*>& route,
                                                std::size_t start, const SumoLookahead& v) {
  std::vector<std::vector<LaneQ>> edges;
  const double start_length = route[start]->lanes.front().length;
  const double max_brake = start_length + v.tau * v.max_speed + brake_gap(v.max_speed, v.decel, v.tau, v.step_length) + v.min_gap;
  int seen = 0;
  double seen_length = 0.0;
  for (std::size_t k = start; k < route.size();) {
    const NetEdge& e = *route[k];
    std::vector<LaneQ> lanes(e.lanes.size());
    for (std::size_t l = 0; l < e.lanes.size(); ++l) {
      LaneQ& q = lanes[l];
      q.length = q.current_length = lane_permits(e.lanes[l], v.vclass) ? e.lanes[l].length : 0.0;
      if (k + 1 < route.size()) {  // MSEdge::allowedLanes(next edge, class)
        bool allowed = false;
        if (lane_permits(e.lanes[l], v.vclass))
          for (const NetConnection* c : links(net, e, static_cast<int>(l), *route[k + 1]))
            allowed = allowed || lane_permits(route[k + 1]->lanes[static_cast<std::size_t>(c->to_lane)], v.vclass);
        q.continues = allowed;
      }
    }
    edges.push_back(std::move(lanes));
    ++seen;
    seen_length += e.lanes.front().length;
    ++k;
    const bool progress = (seen <= 4 || seen_length < std::max(max_brake, 3000.0)) &&
                          (seen <= 8 || seen_length < std::max(max_brake, 200.0));
    if (!progress) break;
  }
  return edges;
}

// The last edge looked at: its longest lanes are the best, the others get offsets towards them.
void set_last_edge_offsets(std::vector<LaneQ>& last, const NetEdge& edge, const SumoLookahead& v) {
  double best_length = -1.0;
  int best = 0, best_max = 0;
  for (int i = 0; i < static_cast<int>(last.size()); ++i) {
    if (last[static_cast<std::size_t>(i)].length > best_length) {
      best_length = last[static_cast<std::size_t>(i)].length;
      best = best_max = i;
    } else if (last[static_cast<std::size_t>(i)].length == best_length) {
      best_max = i;
    }
  }
  set_offsets(last, edge, best, best_max, v, false);
}

// The best lanes [best, best_max] of an edge.
struct BestRange {
  int best = 0, best_max = 0;
};

// Each lane of `clanes` continues on the best permitted next lane it has a link to (`out`: its
// links): the longest, then the one with the smallest offset; it adds that lane's length (the next
// edge's longest when the chosen lane is the longest linked one and at most one lane off the best)
// and takes its offset. Returns the best lanes of this edge: the longest, then the smallest offset,
// then the highest link priority.
BestRange continue_connected(std::vector<LaneQ>& clanes, const std::vector<LaneQ>& next, const NetEdge& next_edge,
                             const std::vector<std::vector<const NetConnection*>>& out, double best_connected,
                             double best_length, const SumoLookahead& v) {
  int best = 0, best_max = 0;
  for (int index = 0; index < static_cast<int>(clanes.size()); ++index) {
    LaneQ& j = clanes[static_cast<std::size_t>(index)];
    const LaneQ* chosen = nullptr;
    int chosen_lane = -1, chosen_priority = -1;
    if (j.continues) {
      for (std::size_t m = 0; m < next.size(); ++m) {
        if (!lane_permits(next_edge.lanes[m], v.vclass)) continue;
        const auto link = std::find_if(out[static_cast<std::size_t>(index)].begin(), out[static_cast<std::size_t>(index)].end(),
                                       [&](const NetConnection* c) { return c->to_lane == static_cast<int>(m); });
        if (link == out[static_cast<std::size_t>(index)].end()) continue;
        const LaneQ& q = next[m];
        if (chosen == nullptr || chosen->length < q.length ||
            (chosen->length == q.length && std::abs(chosen->offset) > std::abs(q.offset))) {
          chosen = &q;
          chosen_lane = static_cast<int>(m);
          chosen_priority = priority_of(**link);
        }
      }
      if (chosen != nullptr) {
        j.length += (chosen->length == best_connected && std::abs(chosen->offset) < 2) ? best_length : chosen->length;
        j.offset = chosen->offset;
      }
    }
    if (chosen != nullptr && (chosen->continues || chosen->length > 0.0)) {
      j.next = chosen_lane;
      j.priority = chosen_priority;
    } else {
      j.continues = false;
    }
    const LaneQ& b = clanes[static_cast<std::size_t>(best)];
    if (b.length < j.length || (b.length == j.length && std::abs(b.offset) > std::abs(j.offset)) ||
        (b.length == j.length && std::abs(b.offset) == std::abs(j.offset) && b.priority < j.priority)) {
      best = best_max = index;
    } else if (b.length == j.length && std::abs(b.offset) == std::abs(j.offset) && b.priority == j.priority) {
      best_max = index;
    }
  }
  return {best, best_max};
}

// A disconnected route (every lane of the next edge this edge links to has length 0): the lane with
// a link to the lane of the smallest offset goes on, and is the only best lane.
BestRange continue_disconnected(std::vector<LaneQ>& clanes, const std::vector<LaneQ>& next,
                                const std::vector<std::vector<const NetConnection*>>& out) {
  int best = 0, best_next = 0, best_dist = static_cast<int>(clanes.size());
  for (int index = 0; index < static_cast<int>(clanes.size()); ++index) {
    if (!clanes[static_cast<std::size_t>(index)].continues) continue;
    for (const NetConnection* c : out[static_cast<std::size_t>(index)])
      if (best_dist > std::abs(next[static_cast<std::size_t>(c->to_lane)].offset)) {
        best_dist = std::abs(next[static_cast<std::size_t>(c->to_lane)].offset);
        best = index;
        best_next = c->to_lane;
      }
  }
  clanes[static_cast<std::size_t>(best)].length += next[static_cast<std::size_t>(best_next)].length;
  clanes[static_cast<std::size_t>(best)].next = best_next;
  return {best, best};
}

// One edge of the backward pass: each lane of `clanes` (edge `here`) continues on a lane of `next`
// (edge `next_edge`, already done), then the offsets towards this edge's best lanes are set.
void continue_lanes(const NetIndex& net, const NetEdge& here, const NetEdge& next_edge, std::vector<LaneQ>& clanes,
                    const std::vector<LaneQ>& next, const SumoLookahead& v) {
  // Per lane of this edge, the next lanes it has a link to (and the link).
  std::vector<std::vector<const NetConnection*>> out(clanes.size());
  std::vector<bool> approached(next.size(), false);
  for (std::size_t l = 0; l < clanes.size(); ++l) {
    out[l] = links(net, here, static_cast<int>(l), next_edge);
    for (const NetConnection* c : out[l]) approached[static_cast<std::size_t>(c->to_lane)] = true;
  }
  double best_connected = -1.0, best_length = -1.0;
  for (std::size_t m = 0; m < next.size(); ++m) {
    if (approached[m]) best_connected = std::max(best_connected, next[m].length);
    best_length = std::max(best_length, next[m].length);
  }
  const BestRange best = best_connected > 0.0
                             ? continue_connected(clanes, next, next_edge, out, best_connected, best_length, v)
                             : continue_disconnected(clanes, next, out);
  set_offsets(clanes, here, best.best, best.best_max, v, true);
}

// The best lanes from route edge `start` on: per edge of the look-ahead, its lanes.
std::vector<std::vector<LaneQ>> best_lanes(const NetIndex& net, const std::vector<const NetEdge*>& route,
                                           std::size_t start, const SumoLookahead& v) {
  std::vector<std::vector<LaneQ>> edges = lookahead_lanes(net, route, start, v);
  set_last_edge_offsets(edges.back(), *route[start + edges.size() - 1], v);
  // Backwards: each lane's best continuation.
  for (std::size_t n = edges.size() - 1; n-- > 0;)
    continue_lanes(net, *route[start + n], *route[start + n + 1], edges[n], edges[n + 1], v);
  return edges;
}

}  // namespace

std::vector<std::vector<int>> sumo_next_lanes(const NetIndex& net, const std::vector<const NetEdge*>& route,
                                              const SumoLookahead& vehicle) {
  std::vector<std::vector<int>> out;
  for (std::size_t i = 0; i + 1 < route.size(); ++i) {
    const std::vector<std::vector<LaneQ>> lanes = best_lanes(net, route, i, vehicle);
    std::vector<int> next;
    for (const LaneQ& q : lanes.front()) next.push_back(lanes.size() > 1 ? q.next : -1);
    out.push_back(std::move(next));
  }
  return out;
}

}  // namespace signalsim::sumo
