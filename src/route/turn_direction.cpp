#include "route/turn_direction.hpp"

namespace signalsim::sumo {

TurnDirection turn_direction_of(char dir, bool lefthand) {
  switch (dir) {
    case 'l':
    case 'L': return TurnDirection::Left;
    case 'r':
    case 'R': return TurnDirection::Right;
    case 's': return TurnDirection::Straight;
    // A U-turn goes round to the driver's side: left in right-hand traffic, right in left-hand traffic.
    case 't': return lefthand ? TurnDirection::Right : TurnDirection::Left;
    // SUMO 1.15's netconvert writes U-turns of left-hand nets as 'T' (LinkDirection::TURN_LEFTHAND),
    // a clockwise turn: right.
    case 'T': return TurnDirection::Right;
    default: return TurnDirection::None;  // 'i' (invalid) and anything unknown
  }
}

}  // namespace signalsim::sumo
