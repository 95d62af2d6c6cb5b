#include "sumo/lane_plan.hpp"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace signalsim::sumo {
namespace {

constexpr int kImpossible = std::numeric_limits<int>::max() / 4;

/// The connection to lane `to` that a vehicle on lane `from` takes: from `from` itself, else the
/// one whose from-lane is closest (ties: the rightmost). Null when no connection reaches `to`.
const NetConnection* link_to(const std::vector<const NetConnection*>& links, int from, int to) {
  const NetConnection* best = nullptr;
  for (const NetConnection* c : links) {
    if (c->to_lane != to) continue;
    if (c->from_lane == from) return c;
    if (best == nullptr) {
      best = c;
      continue;
    }
    const int d = std::abs(c->from_lane - from);
    const int best_d = std::abs(best->from_lane - from);
    if (d < best_d || (d == best_d && c->from_lane < best->from_lane)) best = c;
  }
  return best;
}

}  // namespace

LanePlan plan_lanes(const std::vector<std::vector<bool>>& usable,
                    const std::vector<std::vector<const NetConnection*>>& all_links,
                    const std::vector<int>& required_exit) {
  const std::size_t n = usable.size();
  LanePlan plan;
  if (n == 0 || all_links.size() + 1 != n) return plan;
  const auto required = [&](std::size_t i) { return i < required_exit.size() ? required_exit[i] : -1; };
  // A requested exit lane keeps only the connections leaving from it.
  std::vector<std::vector<const NetConnection*>> links = all_links;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (required(i) < 0) continue;
    std::erase_if(links[i], [&](const NetConnection* c) { return c->from_lane != required(i); });
  }

  // cost[i][l]: fewest lane changes from entering edge i on lane l to the end of the route.
  std::vector<std::vector<int>> cost(n);
  std::vector<std::vector<int>> next(n);
  for (std::size_t i = 0; i < n; ++i) {
    cost[i].assign(usable[i].size(), kImpossible);
    next[i].assign(cost[i].size(), -1);
  }
  for (std::size_t l = 0; l < cost[n - 1].size(); ++l) {
    if (!usable[n - 1][l]) continue;
    const int r = required(n - 1);
    if (r < 0) cost[n - 1][l] = 0;
    else if (static_cast<int>(l) != r && r < static_cast<int>(usable[n - 1].size()) &&
             usable[n - 1][static_cast<std::size_t>(r)])
      cost[n - 1][l] = std::abs(static_cast<int>(l) - r);
  }

  for (std::size_t i = n - 1; i-- > 0;) {
    for (int l = 0; l < static_cast<int>(cost[i].size()); ++l) {
      if (!usable[i][static_cast<std::size_t>(l)] || l == required(i)) continue;
      for (int m = 0; m < static_cast<int>(cost[i + 1].size()); ++m) {
        const int after = cost[i + 1][static_cast<std::size_t>(m)];
        if (after >= kImpossible) continue;
        const NetConnection* c = link_to(links[i], l, m);
        if (c == nullptr || c->from_lane < 0 || c->from_lane >= static_cast<int>(cost[i].size()) ||
            !usable[i][static_cast<std::size_t>(c->from_lane)])
          continue;
        const int total = std::abs(c->from_lane - l) + after;
        if (total < cost[i][static_cast<std::size_t>(l)]) {  // strict: ties keep the lowest m
          cost[i][static_cast<std::size_t>(l)] = total;
          next[i][static_cast<std::size_t>(l)] = m;
        }
      }
    }
  }

  int lane = -1;
  for (int l = 0; l < static_cast<int>(cost[0].size()); ++l) {
    if (cost[0][static_cast<std::size_t>(l)] < kImpossible &&
        (lane < 0 || cost[0][static_cast<std::size_t>(l)] < cost[0][static_cast<std::size_t>(lane)])) {
      lane = l;
    }
  }
  if (lane < 0) return plan;

  plan.lane_changes = cost[0][static_cast<std::size_t>(lane)];
  plan.lanes.push_back(lane);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const int m = next[i][static_cast<std::size_t>(lane)];
    plan.links.push_back(link_to(links[i], lane, m));
    plan.exit_lanes.push_back(plan.links.back()->from_lane);
    plan.lanes.push_back(m);
    lane = m;
  }
  plan.exit_lanes.push_back(required(n - 1) >= 0 ? required(n - 1) : lane);
  return plan;
}

}  // namespace signalsim::sumo
