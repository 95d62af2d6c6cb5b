// Intersection turn-signal requests (docs/behaviour.md §T4): groups of turn lanelets ahead of the ego.
#pragma once

#include <cstddef>
#include <map>
#include <vector>

#include "map/route_map.hpp"
#include "turn_signal/turn_signal_info.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// A group of consecutive route lanelets with the same turn direction (docs/behaviour.md §T4.2).
struct TurnLaneGroup {
  std::size_t front_index = 0;  ///< route index of the first lanelet (the stored-start key)
  std::size_t back_index = 0;   ///< route index of the last lanelet
  TurnDirection direction = TurnDirection::None;
};

/// Geometry of a run of route lanelets [front_index, back_index] that depends on the map only.
struct LaneSpanGeometry {
  bool has_centerline = false;  ///< the merged centerline has >= 2 points
  double required_end_s = 0.0;  ///< route s of the required end (docs/behaviour.md §T7)
};

/// Owns the remembered desired starts (docs/behaviour.md §T1.5, §T4.4). Keys are route lanelet indices, not
/// lane ids: on a looped route the second pass of a lane is a different key, so a stale start is
/// never reused (the reference keys by lane id, docs/behaviour.md §T12.1.5; documented in docs/differences.md).
class IntersectionRequests {
 public:
  /// One planning cycle. `window` is the path P (route indices around the ego); `behavior_command`
  /// is the merged behaviour command (it decides which straight lanes count, §T4.1).
  /// Returns the first active request of the queue (§T4.3 FIRST_ACTIVE) or EMPTY.
  TurnSignalInfo update(const RouteMap& route, RouteMap::Window window, const EgoOnRoute& ego,
                        TurnIndicator behavior_command, const TurnSignalParameters& params);

  /// The group's geometry, computed once (it depends on the map only).
  const LaneSpanGeometry& geometry(const RouteMap& route, const TurnLaneGroup& group, double angle_threshold_deg);

  const std::map<std::size_t, double>& desired_starts() const { return desired_starts_; }

 private:
  std::map<std::size_t, double> desired_starts_;    // group front index -> s_base when stored
  std::map<std::size_t, LaneSpanGeometry> geometry_cache_;  // group front index -> geometry
  // Scratch of update(), kept so that a step allocates nothing once they have grown.
  std::vector<TurnLaneGroup> groups_;
  std::vector<TurnSignalInfo> queue_;
};

/// docs/behaviour.md §T4.2: the group starting at `index`, walking route successors with the same direction
/// (possibly beyond the window).
TurnLaneGroup group_from(const RouteMap& route, std::size_t index);

/// docs/behaviour.md §T4.2 / [LL2U combine_lanelets_shape]: the chain's centerlines joined, skipping any
/// point within 0.01 m of any point already taken.
Polyline merged_centerline(const RouteMap& route, const TurnLaneGroup& group);

/// The merged centerline's required end for an angle threshold, on the route coordinate: the
/// resampling runs along the polyline while SUMO lane positions use the lane `length` (netconvert may
/// set it slightly differently from the shape length), so the arc length is scaled onto s.
LaneSpanGeometry lane_span_geometry(const RouteMap& route, std::size_t front_index, std::size_t back_index,
                                    double angle_threshold_deg);

}  // namespace signalsim
