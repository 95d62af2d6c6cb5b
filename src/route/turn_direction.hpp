// SUMO connection `dir` -> Autoware turn_direction (docs/behaviour.md §S3).
#pragma once

#include "map/lanelet.hpp"

namespace signalsim::sumo {

/// l/L left, r/R right, s straight, t the driver's side (left in right-hand nets, right in
/// left-hand ones), T (netconvert's left-hand U-turn) right; anything else None.
TurnDirection turn_direction_of(char dir, bool lefthand);

}  // namespace signalsim::sumo
