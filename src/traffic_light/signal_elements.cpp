#include "traffic_light/signal_elements.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace signalsim {

std::string_view to_string(SignalColor c) {
  switch (c) {
    case SignalColor::Unknown: return "unknown";
    case SignalColor::Red: return "red";
    case SignalColor::Amber: return "amber";
    case SignalColor::Green: return "green";
    case SignalColor::White: return "white";
  }
  return "invalid";
}

std::string_view to_string(SignalShape s) {
  switch (s) {
    case SignalShape::Unknown: return "unknown";
    case SignalShape::Circle: return "circle";
    case SignalShape::LeftArrow: return "left_arrow";
    case SignalShape::RightArrow: return "right_arrow";
    case SignalShape::UpArrow: return "up_arrow";
    case SignalShape::UpLeftArrow: return "up_left_arrow";
    case SignalShape::UpRightArrow: return "up_right_arrow";
    case SignalShape::DownArrow: return "down_arrow";
    case SignalShape::DownLeftArrow: return "down_left_arrow";
    case SignalShape::DownRightArrow: return "down_right_arrow";
    case SignalShape::Cross: return "cross";
  }
  return "invalid";
}

std::string_view to_string(SignalStatus s) {
  switch (s) {
    case SignalStatus::Unknown: return "unknown";
    case SignalStatus::SolidOff: return "solid_off";
    case SignalStatus::SolidOn: return "solid_on";
    case SignalStatus::Flashing: return "flashing";
  }
  return "invalid";
}

std::string_view to_string(LaneTurnDirection d) {
  switch (d) {
    case LaneTurnDirection::Else: return "else";
    case LaneTurnDirection::Straight: return "straight";
    case LaneTurnDirection::Left: return "left";
    case LaneTurnDirection::Right: return "right";
  }
  return "invalid";
}

LaneTurnDirection lane_turn_direction_from_string(std::string_view text) {
  if (text == "left") return LaneTurnDirection::Left;
  if (text == "right") return LaneTurnDirection::Right;
  if (text == "straight") return LaneTurnDirection::Straight;
  return LaneTurnDirection::Else;
}

namespace {

// Tie rule 2 of highest_confidence_per_shape: larger = more cautious = preferred.
int caution_rank(SignalColor c) {
  switch (c) {
    case SignalColor::Red: return 4;
    case SignalColor::Unknown: return 3;
    case SignalColor::Amber: return 2;
    case SignalColor::White: return 1;
    case SignalColor::Green: return 0;
  }
  return 3;  // out-of-range values are treated like Unknown
}

double comparable_confidence(double c) {
  return std::isnan(c) ? -std::numeric_limits<double>::infinity() : c;
}

// True when `a` should be kept over `b` (same shape).
bool preferred(const SignalElement& a, const SignalElement& b) {
  const double ca = comparable_confidence(a.confidence);
  const double cb = comparable_confidence(b.confidence);
  if (ca != cb) return ca > cb;
  const int ra = caution_rank(a.color);
  const int rb = caution_rank(b.color);
  if (ra != rb) return ra > rb;
  return static_cast<int>(a.status) < static_cast<int>(b.status);
}

}  // namespace

std::vector<SignalElement> highest_confidence_per_shape(const std::vector<SignalElement>& detections) {
  std::vector<SignalElement> best;
  highest_confidence_per_shape(detections, best);
  return best;
}

void highest_confidence_per_shape(const std::vector<SignalElement>& detections, std::vector<SignalElement>& best) {
  best.clear();
  for (const SignalElement& e : detections) {
    auto it = std::find_if(best.begin(), best.end(), [&](const SignalElement& b) { return b.shape == e.shape; });
    if (it == best.end()) {
      best.push_back(e);
    } else if (preferred(e, *it)) {
      *it = e;
    }
  }
  std::sort(best.begin(), best.end(), [](const SignalElement& a, const SignalElement& b) {
    return static_cast<int>(a.shape) < static_cast<int>(b.shape);
  });
}

std::optional<SignalShape> matching_arrow_shape(LaneTurnDirection turn_direction) {
  switch (turn_direction) {
    case LaneTurnDirection::Left: return SignalShape::LeftArrow;
    case LaneTurnDirection::Right: return SignalShape::RightArrow;
    case LaneTurnDirection::Straight: return SignalShape::UpArrow;
    case LaneTurnDirection::Else: return std::nullopt;
  }
  return std::nullopt;
}

bool has_green_circle(const std::vector<SignalElement>& elements) {
  return std::any_of(elements.begin(), elements.end(), [](const SignalElement& e) {
    return e.shape == SignalShape::Circle && e.color == SignalColor::Green;
  });
}

bool is_traffic_signal_stop(LaneTurnDirection turn_direction, const std::vector<SignalElement>& elements) {
  // docs/behaviour.md §L1.4 step 1: a green circle lets every lane go.
  if (has_green_circle(elements)) return false;
  // docs/behaviour.md §L1.4 step 2: a lane without turn_direction ignores arrows.
  const std::optional<SignalShape> arrow = matching_arrow_shape(turn_direction);
  if (!arrow) return true;
  // docs/behaviour.md §L1.4 steps 3-5, Decision: the arrow of the lane's direction must be GREEN.
  const bool green_arrow = std::any_of(elements.begin(), elements.end(), [&](const SignalElement& e) {
    return e.shape == *arrow && e.color == SignalColor::Green;
  });
  // docs/behaviour.md §L1.4 step 6.
  return !green_arrow;
}

bool is_traffic_signal_red_stop(LaneTurnDirection turn_direction, const std::vector<SignalElement>& elements) {
  const bool red_circle = std::any_of(elements.begin(), elements.end(), [](const SignalElement& e) {
    return e.shape == SignalShape::Circle && e.color == SignalColor::Red;
  });
  if (!red_circle) return false;
  const std::optional<SignalShape> arrow = matching_arrow_shape(turn_direction);
  if (!arrow) return true;  // not an intersection lanelet: arrows are ignored
  return std::none_of(elements.begin(), elements.end(), [&](const SignalElement& e) {
    return e.shape == *arrow && e.color == SignalColor::Green;
  });
}

bool is_yellow(const std::vector<SignalElement>& elements) {
  // docs/behaviour.md §L1.8: AMBER with SOLID_ON or UNKNOWN status, any shape (as the module's fork).
  return std::any_of(elements.begin(), elements.end(), [](const SignalElement& e) {
    return e.color == SignalColor::Amber &&
           (e.status == SignalStatus::SolidOn || e.status == SignalStatus::Unknown);
  });
}

}  // namespace signalsim
