// LaneData<Api>: the static net data of SumoSession (lane counts, widths, edges, permissions),
// asked over the client library `Api` (session_impl.hpp) once and kept: they do not change during a
// run, and a lane change would otherwise ask for them every step. Also the session's id-list helper.
// Include it after <libsumo/libsumo.h> or <libsumo/libtraci.h>, through session_impl.hpp.
#pragma once

#include <algorithm>
#include <string>
#include <unordered_map>
#include <vector>

namespace signalsim::sumo {

/// Whether `ids` (a SUMO id list) holds `id`.
inline bool contains_id(const std::vector<std::string>& ids, const std::string& id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

template <class Api>
class LaneData {
 public:
  /// The number of lanes of `edge_id`.
  int lane_count(const std::string& edge_id) const {
    auto it = lane_counts_.find(edge_id);
    if (it == lane_counts_.end()) it = lane_counts_.emplace(edge_id, Api::Edge::getLaneNumber(edge_id)).first;
    return it->second;
  }
  /// [m]
  double lane_width(const std::string& lane_id) const {
    auto it = lane_widths_.find(lane_id);
    if (it == lane_widths_.end()) it = lane_widths_.emplace(lane_id, Api::Lane::getWidth(lane_id)).first;
    return it->second;
  }
  /// The edge `lane_id` belongs to.
  const std::string& lane_edge(const std::string& lane_id) const {
    auto it = lane_edges_.find(lane_id);
    if (it == lane_edges_.end()) it = lane_edges_.emplace(lane_id, Api::Lane::getEdgeID(lane_id)).first;
    return it->second;
  }

  /// The index of `lane_id` among the lanes of `edge_id` (SUMO names them <edge>_<index>), or -1.
  int lane_index_on(const std::string& edge_id, const std::string& lane_id) const {
    const int lanes = lane_count(edge_id);
    for (int k = 0; k < lanes; ++k)
      if (edge_id + "_" + std::to_string(k) == lane_id) return k;
    return -1;
  }

  /// Signed lateral distance [m, left positive] from the centre of lane `from` to the centre of lane
  /// `to` on one edge (index 0 is the rightmost lane): half of both widths plus the lanes between.
  double centre_distance(const std::string& edge_id, int from, int to) const {
    if (from == to) return 0.0;
    const int lo = std::min(from, to), hi = std::max(from, to);
    const auto width = [&](int k) { return lane_width(edge_id + "_" + std::to_string(k)); };
    double d = 0.5 * (width(lo) + width(hi));
    for (int k = lo + 1; k < hi; ++k) d += width(k);
    return to > from ? d : -d;
  }

  /// Whether vehicles of class `vclass` may use `lane_id` (SUMO keeps a vehicle off lanes it may not
  /// use, also sideways in the sublane model: a sidewalk is a road border).
  bool permits(const std::string& lane_id, const std::string& vclass) const {
    const std::string key = lane_id + "\n" + vclass;
    auto it = permits_.find(key);
    if (it == permits_.end()) {
      const auto allowed = Api::Lane::getAllowed(lane_id);  // empty: every class
      const bool ok = !contains_id(Api::Lane::getDisallowed(lane_id), vclass) &&
                      (allowed.empty() || contains_id(allowed, vclass));
      it = permits_.emplace(key, ok).first;
    }
    return it->second;
  }

 private:
  mutable std::unordered_map<std::string, int> lane_counts_;
  mutable std::unordered_map<std::string, double> lane_widths_;
  mutable std::unordered_map<std::string, std::string> lane_edges_;
  mutable std::unordered_map<std::string, bool> permits_;
};

}  // namespace signalsim::sumo
