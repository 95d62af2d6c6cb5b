#include "route/approach_lights.hpp"

#include "route/turn_direction.hpp"

namespace signalsim::sumo {
namespace {

enum class Lamp { Off, Green, Amber, Red, Unknown };

Lamp lamp_of(char state) {
  switch (state) {
    case 'G':
    case 'g': return Lamp::Green;
    case 'y':
    case 'Y': return Lamp::Amber;
    case 'r':
    case 'u':  // red-yellow (before green): still red
    case 's':  // as a circle: stop first
      return Lamp::Red;
    case 'o':
    case 'O': return Lamp::Off;
    default: return Lamp::Unknown;
  }
}

char state_at(const std::string& state, int index) {
  return index >= 0 && static_cast<std::size_t>(index) < state.size() ? state[static_cast<std::size_t>(index)] : '?';
}

SignalColor color_of(Lamp lamp) {
  switch (lamp) {
    case Lamp::Green: return SignalColor::Green;
    case Lamp::Amber: return SignalColor::Amber;
    case Lamp::Red: return SignalColor::Red;
    default: return SignalColor::Unknown;
  }
}

// The circle (see signal_elements in the header): never greener than the ego's own link.
Lamp circle_of(const std::string& state, const ApproachLight& light) {
  const Lamp own = lamp_of(state_at(state, light.link_index));
  if (own != Lamp::Green) return own;
  for (const ApproachLink& link : light.links)
    if (link.direction == TurnDirection::Straight && link.from_lane == light.lane_index)
      return lamp_of(state_at(state, link.link_index));
  return own;
}

bool is_turn(TurnDirection d) { return d == TurnDirection::Left || d == TurnDirection::Right; }

// The turn links that make arrows: every turn link of the approach (one signal head for it, as an
// Autoware map has one traffic light per approach), but of the ego's own direction only its own link.
// A right turn of the same lane to another edge, or of another lane, that is green while the ego's
// link is red is a signal for other vehicles: it must not let the ego go (found by `signalsim
// generate` on SUMO's pasubio net, where it made the judge pass a red link).
bool arrow_source(const ApproachLink& link, const ApproachLight& light) {
  if (!is_turn(link.direction)) return false;
  return link.direction != light.direction || link.link_index == light.link_index;
}

}  // namespace

bool shows_arrow(const std::vector<std::string>& phase_states, const ApproachLight& light) {
  for (const std::string& state : phase_states) {
    if (circle_of(state, light) == Lamp::Green) continue;
    for (const ApproachLink& link : light.links) {
      const char link_state = state_at(state, link.link_index);
      if (arrow_source(link, light) && (link_state == 's' || lamp_of(link_state) == Lamp::Green)) return true;
    }
  }
  return false;
}

std::vector<ApproachLight> approach_lights(const NetIndex& net, const RouteMap& route) {
  std::vector<ApproachLight> out;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& lanelet = route.at(i);
    if (!lanelet.traffic_light || lanelet.is_internal) continue;
    ApproachLight light;
    light.route_index = i;
    light.tls_id = lanelet.traffic_light->tls_id;
    light.link_index = lanelet.traffic_light->link_index;
    if (const NetLane* lane = net.lane(lanelet.lane_id)) light.lane_index = lane->index;
    light.direction = i + 1 < route.size() ? route.at(i + 1).turn_direction : TurnDirection::None;
    light.s_stop_line = lanelet.stop_line_s();
    if (const NetEdge* edge = net.edge(lanelet.edge_id)) {
      for (const NetLane& lane : edge->lanes)
        for (const NetConnection& c : net.connections_from_lane(lane.id))
          if (c.tl == light.tls_id && c.link_index >= 0)
            light.links.push_back({turn_direction_of(c.dir, net.lefthand()), c.link_index, c.from_lane});
    }
    std::vector<std::string> states;
    for (const NetTlLogic& logic : net.tl_logics())
      if (logic.id == light.tls_id)
        for (const NetPhase& phase : logic.phases) states.push_back(phase.state);
    light.has_arrow = shows_arrow(states, light);
    out.push_back(std::move(light));
  }
  return out;
}

std::optional<std::vector<SignalElement>> signal_elements(const std::string& state, const ApproachLight& light) {
  if (lamp_of(state_at(state, light.link_index)) == Lamp::Off) return std::nullopt;
  const Lamp circle = circle_of(state, light);
  std::vector<SignalElement> elements;
  elements.push_back({color_of(circle), SignalShape::Circle, SignalStatus::SolidOn, 1.0});
  bool left = false, right = false;  // one arrow per direction
  for (const ApproachLink& link : light.links) {
    if (!arrow_source(link, light)) continue;
    const char link_state = state_at(state, link.link_index);
    // 's' is red as a circle but a green arrow for its turn (docs/behaviour.md §S3).
    const Lamp lamp = link_state == 's' ? Lamp::Green : lamp_of(link_state);
    if (lamp == circle || (lamp != Lamp::Green && lamp != Lamp::Amber)) continue;
    bool& done = link.direction == TurnDirection::Left ? left : right;
    if (done) continue;
    done = true;
    elements.push_back({color_of(lamp),
                        link.direction == TurnDirection::Left ? SignalShape::LeftArrow : SignalShape::RightArrow,
                        SignalStatus::SolidOn, 1.0});
  }
  return elements;
}

LaneTurnDirection judge_turn_direction(TurnDirection direction) {
  switch (direction) {
    case TurnDirection::Left: return LaneTurnDirection::Left;
    case TurnDirection::Right: return LaneTurnDirection::Right;
    case TurnDirection::Straight: return LaneTurnDirection::Straight;
    case TurnDirection::None: break;
  }
  return LaneTurnDirection::Else;
}

std::string describe_elements(const std::vector<SignalElement>& elements) {
  std::string out;
  for (const SignalElement& e : elements) {
    if (!out.empty()) out += '+';
    out += std::string(to_string(e.color));
    if (e.shape != SignalShape::Circle) out += "_" + std::string(to_string(e.shape));
  }
  return out.empty() ? "nothing" : out;
}

}  // namespace signalsim::sumo
