#include "route/lane_plan.hpp"

#include <algorithm>
#include <cstdlib>

namespace signalsim::sumo {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The value of a plan from some edge on (criteria 1-3 of plan_lanes).
struct Cost {
  bool possible = false;
  int unfit = 0;
  int changes = 0;
  double tightest = kInfinity;
};

bool better(const Cost& a, const Cost& b) {
  if (!b.possible) return a.possible;
  if (!a.possible) return false;
  if (a.unfit != b.unfit) return a.unfit < b.unfit;
  if (a.changes != b.changes) return a.changes < b.changes;
  return a.tightest > b.tightest;
}

/// `after` preceded by a lane change on edge i from lane `from` to lane `to` (none when equal).
Cost with_change(Cost after, std::size_t i, int from, int to, const std::vector<EdgeRoom>& rooms,
                 const LaneChangeEgo& ego) {
  if (from == to) return after;
  after.changes += std::abs(from - to);
  if (i < rooms.size()) {
    const EdgeRoom& r = rooms[i];
    if (!lane_change_fits(r.room, lane_shift(r.widths, from, to), r.speed, ego)) ++after.unfit;
    after.tightest = std::min(after.tightest, r.room);
  }
  return after;
}

/// Whether the ego may drive every lane from `a` to `b` (both included) of an edge.
bool drivable(const std::vector<bool>& usable, int a, int b, bool cross_unusable) {
  if (a < 0 || b < 0 || a >= static_cast<int>(usable.size()) || b >= static_cast<int>(usable.size())) return false;
  if (!usable[static_cast<std::size_t>(a)] || !usable[static_cast<std::size_t>(b)]) return false;
  if (cross_unusable) return true;
  for (int k = std::min(a, b); k <= std::max(a, b); ++k)
    if (!usable[static_cast<std::size_t>(k)]) return false;
  return true;
}

}  // namespace

LanePlan plan_lanes(const std::vector<std::vector<bool>>& usable,
                    const std::vector<std::vector<const NetConnection*>>& all_links,
                    const std::vector<int>& required_exit, const std::vector<EdgeRoom>& rooms,
                    const LaneChangeEgo& ego, bool cross_unusable) {
  const std::size_t n = usable.size();
  LanePlan plan;
  if (n == 0 || all_links.size() + 1 != n) return plan;
  const auto required = [&](std::size_t i) { return i < required_exit.size() ? required_exit[i] : -1; };

  // Per gap, the connections in the order ties are broken: by to-lane (the lowest next lane first);
  // per lane l they are then tried closest from-lane first (then the rightmost). A requested exit
  // lane keeps only the connections leaving from it.
  std::vector<std::vector<const NetConnection*>> links = all_links;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    if (required(i) >= 0) std::erase_if(links[i], [&](const NetConnection* c) { return c->from_lane != required(i); });
    std::stable_sort(links[i].begin(), links[i].end(),
                     [](const NetConnection* a, const NetConnection* b) { return a->to_lane < b->to_lane; });
  }

  // cost[i][l]: the best plan from entering edge i on lane l to the end of the route.
  std::vector<std::vector<Cost>> cost(n);
  std::vector<std::vector<const NetConnection*>> taken(n);
  for (std::size_t i = 0; i < n; ++i) {
    cost[i].assign(usable[i].size(), Cost{});
    taken[i].assign(usable[i].size(), nullptr);
  }
  for (int l = 0; l < static_cast<int>(cost[n - 1].size()); ++l) {
    const int r = required(n - 1);
    if (r < 0) {
      if (usable[n - 1][static_cast<std::size_t>(l)]) cost[n - 1][static_cast<std::size_t>(l)] = Cost{true};
    } else if (l != r && drivable(usable[n - 1], l, r, cross_unusable)) {
      cost[n - 1][static_cast<std::size_t>(l)] = with_change(Cost{true}, n - 1, l, r, rooms, ego);
    }
  }

  for (std::size_t i = n - 1; i-- > 0;) {
    for (int l = 0; l < static_cast<int>(cost[i].size()); ++l) {
      if (!usable[i][static_cast<std::size_t>(l)] || l == required(i)) continue;
      // Connections grouped by to-lane m (sorted above); within a group, closest from-lane first.
      std::vector<const NetConnection*> order = links[i];
      std::stable_sort(order.begin(), order.end(), [l](const NetConnection* a, const NetConnection* b) {
        if (a->to_lane != b->to_lane) return a->to_lane < b->to_lane;
        const int da = std::abs(a->from_lane - l), db = std::abs(b->from_lane - l);
        return da != db ? da < db : a->from_lane < b->from_lane;
      });
      Cost& best = cost[i][static_cast<std::size_t>(l)];
      for (const NetConnection* c : order) {
        if (c->to_lane < 0 || c->to_lane >= static_cast<int>(cost[i + 1].size())) continue;
        const Cost& after = cost[i + 1][static_cast<std::size_t>(c->to_lane)];
        if (!after.possible || !drivable(usable[i], l, c->from_lane, cross_unusable)) continue;
        const Cost total = with_change(after, i, l, c->from_lane, rooms, ego);
        if (better(total, best)) {  // strict: ties keep the earlier connection
          best = total;
          taken[i][static_cast<std::size_t>(l)] = c;
        }
      }
    }
  }

  int lane = -1;
  for (int l = 0; l < static_cast<int>(cost[0].size()); ++l) {
    if (better(cost[0][static_cast<std::size_t>(l)], lane < 0 ? Cost{} : cost[0][static_cast<std::size_t>(lane)])) lane = l;
  }
  if (lane < 0) return plan;
  // An ego already on a lane of the first edge keeps it when the route goes on from there; else the
  // best plan stands and the ego changes onto its lane on the first edge.
  const int given = ego.first_lane;
  if (given >= 0 && given < static_cast<int>(cost[0].size()) && cost[0][static_cast<std::size_t>(given)].possible)
    lane = given;

  const Cost& total = cost[0][static_cast<std::size_t>(lane)];
  plan.lane_changes = total.changes;
  plan.unfit = total.unfit;
  plan.tightest_room = total.tightest;
  plan.lanes.push_back(lane);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const NetConnection* c = taken[i][static_cast<std::size_t>(lane)];
    plan.links.push_back(c);
    plan.exit_lanes.push_back(c->from_lane);
    lane = c->to_lane;
    plan.lanes.push_back(lane);
  }
  plan.exit_lanes.push_back(required(n - 1) >= 0 ? required(n - 1) : lane);
  return plan;
}

}  // namespace signalsim::sumo
