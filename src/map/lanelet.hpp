// One lanelet of the ego's route: a SUMO lane (normal or internal) placed on the route coordinate s.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/polyline.hpp"

namespace signalsim {

/// Autoware's lanelet attribute `turn_direction` (docs/behaviour.md §T1.3; SUMO mapping docs/behaviour.md §S3).
enum class TurnDirection { None, Straight, Left, Right };

std::string_view to_string(TurnDirection d);

/// Role of a lanelet in a roundabout (docs/behaviour.md §T5; taken from `<roundabout>`, docs/behaviour.md §S3).
enum class RoundaboutRole { None, Entry, Internal, Exit };

std::string_view to_string(RoundaboutRole r);

/// The traffic light controlling the connection that leaves this lanelet along the route.
struct TrafficLightLink {
  std::string tls_id;    ///< `<tlLogic id>`
  int link_index = -1;   ///< index into the light's state string
};

struct Lanelet {
  std::string lane_id;                 ///< SUMO lane id (":J_0_0" for an internal lane)
  std::string edge_id;                 ///< SUMO edge id (":J_0" for an internal edge)
  std::string junction_id;             ///< junction an internal lane lies in; empty for normal lanes
  bool is_internal = false;            ///< a junction (via) lane
  double s_start = 0.0;                ///< route position of the lane start [m]
  double length = 0.0;                 ///< SUMO lane length [m]; lane positions use this unit
  double speed_limit = 0.0;            ///< [m/s]
  double width = 3.2;                  ///< [m]
  Polyline shape;                      ///< centerline in net coordinates
  TurnDirection turn_direction = TurnDirection::None;  ///< from the connection's `dir` (internal lanes)
  std::vector<TurnDirection> successor_turn_directions;  ///< of all map successors, on or off route
  RoundaboutRole roundabout_role = RoundaboutRole::None;
  std::string roundabout_id;           ///< which `<roundabout>` (its position in the net file), if any
  // For an internal ring -> ring lane (inside a ring junction): the junction has an exit off the ring.
  bool leaves_ring_at_end = false;  ///< a ring lanelet whose end has a connection off the ring (an exit branches there)
  std::optional<double> turn_signal_distance;  ///< per-lanelet search distance (docs/behaviour.md §T4.3)
  std::map<std::string, std::string> params;   ///< lane params, merged with the approach lane's (docs/behaviour.md §S3)
  std::optional<TrafficLightLink> traffic_light;  ///< light of the connection leaving this lanelet
  double stop_offset = 0.0;            ///< `<stopOffset>` applying to this lane's end [m]

  double s_end() const { return s_start + length; }
  /// Route s of the stop line at this lane's end: the end moved upstream by <stopOffset> (docs/behaviour.md §S2).
  double stop_line_s() const { return s_end() - stop_offset; }
};

}  // namespace signalsim
