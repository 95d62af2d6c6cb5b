// Roundabout turn-signal requests (docs/behaviour.md §T5.1-§T5.3): entries and exits of `<roundabout>`s on the
// route window, on the route coordinate s.
//
// Per cycle, for the window P (route indices around the ego) and the ego at (s_front, s_base, v):
//
//   ENTRIES, EXITS := the entry / exit connections in P, in path order                       (§T5.1)
//   if both are empty:  return EMPTY
//   search := turn_signal_search_time * v + turn_signal_roundabout_search_distance
//   for E in ENTRIES:                                                                         (§T5.2)
//     skip E while its start is not strictly within E.turn_signal_distance (or search) of the
//       front, unless a desired start is already stored for E (then it is never re-filtered)
//     desired start := stored s_base of the first cycle E came within reach
//     X := the exit the route actually uses (last lanelet of E's roundabout before leaving it)
//     cmd := ENABLE_LEFT if E's param exit_turn_signal_left lists X, else ENABLE_RIGHT if
//            exit_turn_signal_right lists X, else turn_signal_roundabout_on_entry;
//            a DISABLE entry (on_entry "None", no tag) forgets its start and is skipped
//     desired end := end of E; with ..._entry_indicator_persistence the end of X instead
//     desired end passed by base_link: forget the start, skip;  otherwise queue it
//   for X in EXITS:                                                                           (§T5.3)
//     X's end passed by base_link: forget the start, skip
//     Z := the earliest lanelet of the chain of route predecessors with
//          enable_exit_turn_signal == "true" (none: X itself)
//     skip until the front is strictly past the start of Z (no search distance, §T12.1.8)
//     desired start := start of Z (stored once); cmd := turn_signal_roundabout_on_exit
//   return FIRST_ACTIVE(entries then exits)                                            (§T4.3, §T12.1.7)
//
// SUMO mapping (docs/behaviour.md §S3): a lanelet's roundabout is `roundabout_id`; "E's first roundabout" is
// E's `roundabout_id`. An entry or exit is a *connection* (signal_sections.hpp, the home of the exit-tag
// rule and the enable_exit_turn_signal chain); netconvert may split a connection into two internal
// lanes (an internal junction); the run is then one entry or exit, as one lanelet is in Autoware (its
// key is the run's first route index; centerlines joined as in §T4.2).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "map/route_map.hpp"
#include "turn_signal/intersection_requests.hpp"
#include "turn_signal/signal_sections.hpp"  // RoundaboutConnection, the exit-tag rule
#include "turn_signal/turn_signal_info.hpp"
#include "turn_signal/turn_signal_parameters.hpp"

namespace signalsim {

/// Owns the remembered roundabout desired starts (docs/behaviour.md §T1.5 item 2), for entries and exits alike.
/// Keys are route lanelet indices (the connection's first lanelet), not lane ids, as in
/// IntersectionRequests (docs/differences.md: remembered desired starts are keyed by route position).
class RoundaboutRequests {
 public:
  /// One planning cycle (docs/behaviour.md §T5.1-§T5.3). `window` is the path P. Returns the first active
  /// request of the queue "all entries, then all exits" (§T4.3 FIRST_ACTIVE) or EMPTY. Never throws.
  TurnSignalInfo update(const RouteMap& route, RouteMap::Window window, const EgoOnRoute& ego,
                        const TurnSignalParameters& params);

  /// Geometry of a connection (§T7 with the roundabout angle threshold), computed once.
  const LaneSpanGeometry& geometry(const RouteMap& route, const RoundaboutConnection& connection,
                                   double angle_threshold_deg);

  /// Stored desired starts: connection front index -> route s. An entry stores s_base of the cycle
  /// it came within reach; an exit stores the start of its enable_exit_turn_signal chain (or its own).
  const std::map<std::size_t, double>& desired_starts() const { return desired_starts_; }

 private:
  std::map<std::size_t, double> desired_starts_;
  std::map<std::size_t, LaneSpanGeometry> geometry_cache_;
};

/// docs/behaviour.md §T5.1: the entries and exits in the window, each once, in path order.
std::vector<RoundaboutConnection> roundabout_connections(const RouteMap& route, RouteMap::Window window);

}  // namespace signalsim
