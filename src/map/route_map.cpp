#include "map/route_map.hpp"

#include <algorithm>

namespace signalsim {

RouteMap::RouteMap(std::vector<Lanelet> lanelets) : lanelets_(std::move(lanelets)) {
  starts_.reserve(lanelets_.size());
  for (std::size_t i = 0; i < lanelets_.size(); ++i) {
    starts_.push_back(lanelets_[i].s_start);
    by_lane_id_[lanelets_[i].lane_id].push_back(i);
    by_edge_id_[lanelets_[i].edge_id].push_back(i);
    if (!lanelets_[i].junction_id.empty()) by_junction_id_[lanelets_[i].junction_id].push_back(i);
  }
}

std::size_t RouteMap::index_at(double s) const {
  if (lanelets_.empty()) return 0;
  auto it = std::upper_bound(starts_.begin(), starts_.end(), s);
  if (it == starts_.begin()) return 0;
  return static_cast<std::size_t>(it - starts_.begin()) - 1;
}

std::size_t RouteMap::index_at(double s, std::size_t hint) const {
  const bool in_hint = hint < starts_.size() && starts_[hint] <= s && (hint + 1 == starts_.size() || s < starts_[hint + 1]);
  return in_hint ? hint : index_at(s);  // in_hint: hint is the last start at or before s
}

RouteMap::Window RouteMap::window(double s_from, double s_to) const {
  if (lanelets_.empty() || s_to < s_from) return {};
  const std::size_t first = index_at(s_from);
  std::size_t last = index_at(s_to) + 1;
  return {first, std::min(last, lanelets_.size())};
}


namespace {
std::optional<std::size_t> first_at_or_after(
    const std::unordered_map<std::string, std::vector<std::size_t>>& index, const std::string& key,
    std::size_t from_index) {
  auto it = index.find(key);
  if (it == index.end()) return std::nullopt;
  for (std::size_t i : it->second)
    if (i >= from_index) return i;
  return std::nullopt;
}
}  // namespace

std::optional<std::size_t> RouteMap::find_lane(const std::string& lane_id, std::size_t from_index) const {
  return first_at_or_after(by_lane_id_, lane_id, from_index);
}

std::optional<std::size_t> RouteMap::find_edge(const std::string& edge_id, std::size_t from_index) const {
  return first_at_or_after(by_edge_id_, edge_id, from_index);
}

std::optional<double> RouteMap::s_of(const std::string& lane_id, const std::string& edge_id, double lane_pos,
                                     std::size_t hint_index) const {
  auto index = find_lane(lane_id, hint_index);
  if (!index && !edge_id.empty() && edge_id.front() != ':') index = find_edge(edge_id, hint_index);
  if (!index && !edge_id.empty() && edge_id.front() == ':') {
    // An internal lane of another connection: place it in the same junction of the route.
    const std::string junction = edge_id.substr(1, edge_id.rfind('_') - 1);
    index = first_at_or_after(by_junction_id_, junction, hint_index);
  }
  if (!index) return std::nullopt;
  return lanelets_[*index].s_start + std::min(lane_pos, lanelets_[*index].length);
}

}  // namespace signalsim
