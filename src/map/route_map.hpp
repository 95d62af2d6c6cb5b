// RouteMap: the ego's route as an ordered sequence of lanelets on the coordinate s.
//
// Built once per run (from the net, by route/RouteBuilder); every query afterwards is
// O(log n) in the route length and independent of the size of the net.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "map/lanelet.hpp"

namespace signalsim {

class RouteMap {
 public:
  RouteMap() = default;
  /// Lanelets must be contiguous in s: lanelets[i+1].s_start == lanelets[i].s_end().
  explicit RouteMap(std::vector<Lanelet> lanelets);

  std::span<const Lanelet> lanelets() const { return lanelets_; }
  const Lanelet& at(std::size_t index) const { return lanelets_.at(index); }
  std::size_t size() const { return lanelets_.size(); }
  bool empty() const { return lanelets_.empty(); }
  double length() const { return lanelets_.empty() ? 0.0 : lanelets_.back().s_end(); }

  /// Index of the lanelet containing s (s on a boundary belongs to the later lanelet;
  /// clamped to the first/last lanelet outside the route).
  std::size_t index_at(double s) const;
  /// The same, looking at lanelet `hint` first (a front that stays on its lanelet needs no search).
  std::size_t index_at(double s, std::size_t hint) const;

  /// Indices [first, last) of the lanelets overlapping [s_from, s_to] (clamped to the route).
  struct Window {
    std::size_t first = 0;
    std::size_t last = 0;
  };
  Window window(double s_from, double s_to) const;

  /// First route index of a lane id at or after `from_index`, if it lies on the route.
  std::optional<std::size_t> find_lane(const std::string& lane_id, std::size_t from_index = 0) const;

  /// First route index at or after `from_index` on the given edge (normal edges only).
  std::optional<std::size_t> find_edge(const std::string& edge_id, std::size_t from_index = 0) const;

  /// Route position of a lane position: the lane itself at or after `hint_index`; a lane of the
  /// same edge (the ego changed lanes); an internal lane of the same junction (another connection).
  std::optional<double> s_of(const std::string& lane_id, const std::string& edge_id, double lane_pos,
                             std::size_t hint_index = 0) const;

 private:
  std::vector<Lanelet> lanelets_;
  std::vector<double> starts_;
  std::unordered_map<std::string, std::vector<std::size_t>> by_lane_id_;
  std::unordered_map<std::string, std::vector<std::size_t>> by_edge_id_;
  std::unordered_map<std::string, std::vector<std::size_t>> by_junction_id_;
};

}  // namespace signalsim
