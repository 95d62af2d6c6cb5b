// get_turn_signal of autoware_core's path_generator (planning/autoware_path_generator/src/utils.cpp,
// commit 2d693b82) on route s. The source walks the path's lanelets in order, each once:
//   skip a lanelet without a next lanelet within the route (get_next_lanelet_within_route: the goal);
//   until the ego's lanelet is found, skip lanelets that do not contain base_link (geometry::inside);
//   a lanelet with turn_direction sets the command (left, right, straight -> DISABLE), then
//     - ahead of the ego: return it, or NO_COMMAND when the front's distance to the lanelet's start
//       exceeds turn_signal_distance (default search_distance + v * search_time);
//     - containing the ego: return it while base_link has not passed the required end point; with no
//       required end point go on to the next lanelet without measuring this one;
//   then the front's distance to the next lanelet's start is measured (this lanelet's length less
//   base_link's arc and base_link_to_front for the ego's lanelet, plus the length for the others).
// After the loop the last command set is returned (NO_COMMAND when none was).
#include "turn_signal_rule.hpp"

namespace signalsim::autoware_core {
namespace {

Command command_of(TurnDirection direction) {
  switch (direction) {
    case TurnDirection::Left: return Command::Left;
    case TurnDirection::Right: return Command::Right;
    default: return Command::Disable;  // "straight"
  }
}

// base_link's arc on the lanelet's centerline (toArcCoordinates): its share of the lane on s, on the
// centerline's own length.
double ego_arc(const Lane& lane, double s_base) {
  const double s_length = lane.s_end - lane.s_start;
  return s_length > 0.0 ? (s_base - lane.s_start) * lane.geometric_length / s_length : 0.0;
}

bool contains(const Lane& lane, double s_base) { return lane.s_start <= s_base && s_base < lane.s_end; }

}  // namespace

Command get_turn_signal(const std::vector<Lane>& route, const EgoState& ego, const Settings& settings) {
  Command command = Command::NoCommand;
  const double base_search_distance = settings.search_distance + ego.speed * settings.search_time;
  std::optional<double> front_to_lane_start;
  for (std::size_t i = 0; i + 1 < route.size(); ++i) {  // the goal lanelet has no next: skipped
    const Lane& lane = route[i];
    // The path: path_length.backward behind base_link to path_length.forward ahead.
    if (lane.s_end <= ego.s_base - settings.path_backward) continue;
    if (lane.s_start >= ego.s_base + settings.path_forward) break;
    if (!front_to_lane_start && !contains(lane, ego.s_base)) continue;
    if (lane.turn_direction != TurnDirection::None) {
      command = command_of(lane.turn_direction);
      if (front_to_lane_start) {  // the lanelet lies ahead of the ego
        if (*front_to_lane_start > lane.turn_signal_distance.value_or(base_search_distance)) {
          command = Command::NoCommand;
        }
        return command;
      }
      if (!lane.required_end_arc) continue;  // ego inside, no required end: not measured
      if (ego_arc(lane, ego.s_base) <= *lane.required_end_arc) return command;
    }
    if (front_to_lane_start) {
      *front_to_lane_start += lane.geometric_length;
    } else {
      front_to_lane_start = lane.geometric_length - ego_arc(lane, ego.s_base) - settings.base_link_to_front;
    }
  }
  return command;
}

}  // namespace signalsim::autoware_core
