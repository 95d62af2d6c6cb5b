#include "map/lanelet.hpp"


namespace signalsim {

std::string_view to_string(TurnDirection d) {
  switch (d) {
    case TurnDirection::Straight: return "straight";
    case TurnDirection::Left: return "left";
    case TurnDirection::Right: return "right";
    case TurnDirection::None: break;
  }
  return "none";
}

std::string_view to_string(RoundaboutRole r) {
  switch (r) {
    case RoundaboutRole::Entry: return "entry";
    case RoundaboutRole::Internal: return "internal";
    case RoundaboutRole::Exit: return "exit";
    case RoundaboutRole::None: break;
  }
  return "none";
}

}  // namespace signalsim
