#include "map/lanelet.hpp"

#include <algorithm>

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

double Lanelet::shape_position(double s) const {
  const double along = std::clamp(s - s_start, 0.0, length);
  return length > 0.0 ? along * shape.length() / length : 0.0;
}

Pose Lanelet::pose_at(double s) const { return shape.pose_at(shape_position(s)); }

}  // namespace signalsim
