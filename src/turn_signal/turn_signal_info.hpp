// One blinker request (docs/behaviour.md §T1.2) expressed on the route coordinate s.
#pragma once

#include <cstdint>
#include <string_view>

namespace signalsim {

/// Autoware TurnIndicatorsCommand values (docs/behaviour.md §T1.1). Not SUMO's signal bits.
enum class TurnIndicator : std::uint8_t { NoCommand = 0, Disable = 1, EnableLeft = 2, EnableRight = 3 };

/// Autoware HazardLightsCommand values (docs/behaviour.md §T1.1).
enum class HazardLights : std::uint8_t { NoCommand = 0, Disable = 1, Enable = 2 };

/// Which request a blinker came from; printed in the timeline's `blinker_source` column.
enum class RequestSource : std::uint8_t {
  None,
  Intersection,
  RoundaboutEntry,
  RoundaboutExit,
  LaneChange,
  Avoidance,
  PullOut,
  PullOver,
  Sumo,  ///< not a request: SUMO's own blinker logic, observed (`run --driver sumo`, docs/behaviour.md §S5)
  Sut,   ///< not a request: a decider under test decided (docs/decider.md)
};

/// ENABLE_LEFT or ENABLE_RIGHT (not NO_COMMAND, not DISABLE).
inline bool is_enable(TurnIndicator command) {
  return command == TurnIndicator::EnableLeft || command == TurnIndicator::EnableRight;
}

std::string_view to_string(RequestSource source);
std::string_view to_string(TurnIndicator command);

/// A request: a desired section (the blinker may be on) and a required section (used only to break
/// conflicts). Every point is a route position s. Start points are compared with the vehicle front,
/// end points with base_link (docs/behaviour.md §T2). A default-constructed info is EMPTY (NO_COMMAND).
struct TurnSignalInfo {
  TurnIndicator turn = TurnIndicator::NoCommand;
  HazardLights hazard = HazardLights::NoCommand;
  RequestSource source = RequestSource::None;
  double desired_start = 0.0;   ///< s of the desired start point
  double desired_end = 0.0;     ///< s of the desired end point
  double required_start = 0.0;  ///< s of the required start point
  double required_end = 0.0;    ///< s of the required end point
};

/// The ego on the route: front bumper and base_link (rear-axle centre) positions.
struct EgoOnRoute {
  double s_front = 0.0;  ///< route position of the front bumper [m]
  double s_base = 0.0;   ///< s_front - base_link_to_front [m]
  double speed = 0.0;    ///< signed longitudinal speed [m/s]
  double base_link_to_front() const { return s_front - s_base; }
};

}  // namespace signalsim
