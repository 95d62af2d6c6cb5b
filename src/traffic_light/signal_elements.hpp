// Value types for one traffic-light observation and the pure helpers the judge applies to them
// (docs/behaviour.md §L1.3, §L1.4, §L1.8). No SUMO types: the SUMO adapter converts link states into these
// (docs/behaviour.md §S3 "Link state -> signal elements").
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace signalsim {

/// Bulb color. Values equal autoware_perception_msgs/TrafficLightElement (docs/behaviour.md §L1.4).
enum class SignalColor : std::uint8_t { Unknown = 0, Red = 1, Amber = 2, Green = 3, White = 4 };

/// Bulb shape. Values equal autoware_perception_msgs/TrafficLightElement (docs/behaviour.md §L1.4).
enum class SignalShape : std::uint8_t {
  Unknown = 0,
  Circle = 1,
  LeftArrow = 2,
  RightArrow = 3,
  UpArrow = 4,
  UpLeftArrow = 5,
  UpRightArrow = 6,
  DownArrow = 7,
  DownLeftArrow = 8,
  DownRightArrow = 9,
  Cross = 10,
};

/// Bulb status. Values equal autoware_perception_msgs/TrafficLightElement (docs/behaviour.md §L1.4).
/// Ignored by the stop/go rule; used only by the arrow-aware yellow tracker (docs/behaviour.md §L1.8).
enum class SignalStatus : std::uint8_t { Unknown = 0, SolidOff = 1, SolidOn = 2, Flashing = 3 };

/// Autoware's lanelet attribute `turn_direction` of the lane that owns the light (docs/behaviour.md §L1.4).
/// `Else` is Autoware's default for a lane without the attribute: arrows are then ignored.
/// (Named apart from map's TurnDirection so this layer does not depend on map/.)
enum class LaneTurnDirection : std::uint8_t { Else, Straight, Left, Right };

/// One recognised bulb of a light group.
struct SignalElement {
  SignalColor color = SignalColor::Unknown;     ///< recognised color
  SignalShape shape = SignalShape::Unknown;     ///< recognised shape
  SignalStatus status = SignalStatus::SolidOn;  ///< lamp status (steady, flashing, ...)
  double confidence = 1.0;                      ///< recognition confidence, nominally in [0, 1]

  friend bool operator==(const SignalElement&, const SignalElement&) = default;
};

/// What the judge receives for its light group in one step: every detection (several per bulb are
/// allowed; the judge reduces them with highest_confidence_per_shape) and the capture time.
struct SignalObservation {
  std::vector<SignalElement> elements;  ///< all detections of the group; empty = nothing recognised
  double stamp = 0.0;                   ///< capture time [s], simulation clock (<= delivery time)

  friend bool operator==(const SignalObservation&, const SignalObservation&) = default;
};

/// One entry of a V2I message's `predictions[]` (docs/behaviour.md §L1.7): the elements the light group will
/// show from `stamp` on (absolute simulation time [s]).
struct SignalPrediction {
  double stamp = 0.0;                   ///< [s] when these elements are predicted to come on
  std::vector<SignalElement> elements;  ///< what the group will show then

  friend bool operator==(const SignalPrediction&, const SignalPrediction&) = default;
};

std::string_view to_string(SignalColor c);
std::string_view to_string(SignalShape s);
std::string_view to_string(SignalStatus s);
std::string_view to_string(LaneTurnDirection d);

/// Parses Autoware's attribute text: "left", "right", "straight"; anything else (including "" and
/// "else") is `Else`, as Autoware's default (docs/behaviour.md §L1.4 step 2). Never throws.
LaneTurnDirection lane_turn_direction_from_string(std::string_view text);

/// Decision "highest reliability wins" (docs/behaviour.md §L0; §L1.3 notes): for every shape present,
/// keeps the one detection with the highest confidence. Ties are broken without looking at input
/// order, so the result does not depend on the order detections arrive in:
///   1. higher confidence (NaN counts as lowest);
///   2. the more cautious color: Red > Unknown > Amber > White > Green;
///   3. the smaller status value.
/// The result holds one element per shape, sorted by ascending shape value. Never throws.
std::vector<SignalElement> highest_confidence_per_shape(const std::vector<SignalElement>& detections);
/// The same into `best` (cleared first; its storage is reused: the judge calls it every step).
void highest_confidence_per_shape(const std::vector<SignalElement>& detections, std::vector<SignalElement>& best);

/// The arrow shape that lets a lane of this turn direction go (docs/behaviour.md §L1.4 steps 3-5):
/// Left -> LeftArrow, Right -> RightArrow, Straight -> UpArrow; none for Else.
std::optional<SignalShape> matching_arrow_shape(LaneTurnDirection turn_direction);

/// docs/behaviour.md §L1.4 `isTrafficSignalStop`, with the Decision that the matching arrow must be GREEN:
///   1. a GREEN CIRCLE present                                  -> false (go)
///   2. turn_direction == Else                                  -> true  (stop)
///   3-5. a GREEN arrow of the lane's direction present         -> false (go)
///   6. otherwise (no elements, UNKNOWN, AMBER, RED, wrong arrow)-> true  (stop)
/// Status is ignored (a flashing amber is an amber). Never throws.
bool is_traffic_signal_stop(LaneTurnDirection turn_direction, const std::vector<SignalElement>& elements);

/// docs/behaviour.md §L1.4 `isTrafficSignalRedStop` (the V2I helper of §L1.7): a RED CIRCLE is present and,
/// for a lane with a turn direction (an intersection lanelet), no GREEN arrow of that direction is
/// (arrows count only when green, as in the reference's newest version, docs/behaviour.md §L1.4). A
/// lane of direction `Else` ignores arrows: a red circle is a red stop. Never throws.
bool is_traffic_signal_red_stop(LaneTurnDirection turn_direction, const std::vector<SignalElement>& elements);

/// docs/behaviour.md §L1.4 step 1 / §L1.8: some element is a GREEN CIRCLE.
bool has_green_circle(const std::vector<SignalElement>& elements);

/// docs/behaviour.md §L1.8 "yellow now": some element (any shape) is AMBER with status SOLID_ON or UNKNOWN.
bool is_yellow(const std::vector<SignalElement>& elements);

}  // namespace signalsim
