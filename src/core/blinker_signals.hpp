// The blinker and SUMO's signal bits: the one home of the blinker a run records and of its encoding
// as the TraCI signal mask the ego shows in SUMO (docs/behaviour.md §S4; the libsumo headers do not
// define the bits). The session writes and reads the mask, the step loop commands it, the report
// compares it with the timeline's blinker and `run --driver sumo` decodes SUMO's own.
#pragma once

namespace signalsim {

/// The blinker the timeline records (`blinker` column).
enum class Blinker { None, Left, Right, Hazard };

namespace sumo {

/// TraCI signal bits (docs/behaviour.md §S4).
inline constexpr int kBlinkerRight = 1;
inline constexpr int kBlinkerLeft = 2;
inline constexpr int kBlinkerEmergency = 4;
inline constexpr int kBlinkerMask = kBlinkerRight | kBlinkerLeft | kBlinkerEmergency;
inline constexpr int kBrakeLight = 8;  ///< SUMO computes it each step; its junction model reads it

}  // namespace sumo

/// The TraCI signal bits that show `blinker` in SUMO: left 2, right 1, hazard 4 (the emergency bit).
constexpr int signal_mask(Blinker blinker) {
  switch (blinker) {
    case Blinker::Left: return sumo::kBlinkerLeft;
    case Blinker::Right: return sumo::kBlinkerRight;
    case Blinker::Hazard: return sumo::kBlinkerEmergency;
    case Blinker::None: break;
  }
  return 0;
}

/// The blinker a TraCI signal mask shows: hazard for the emergency bit or both direction bits, else
/// left or right; other bits (brake lights, ...) ignored.
constexpr Blinker blinker_of_signals(int mask) {
  const bool left = mask & sumo::kBlinkerLeft, right = mask & sumo::kBlinkerRight;
  if ((mask & sumo::kBlinkerEmergency) || (left && right)) return Blinker::Hazard;
  if (left) return Blinker::Left;
  if (right) return Blinker::Right;
  return Blinker::None;
}

}  // namespace signalsim
