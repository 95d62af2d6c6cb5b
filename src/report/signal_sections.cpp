// The route's signal sections: turns and roundabout entries/exits (see signal_sections.hpp).
#include "report/signal_sections.hpp"

namespace signalsim {
namespace {

Blinker blinker_of(TurnDirection d) {
  return d == TurnDirection::Left ? Blinker::Left : d == TurnDirection::Right ? Blinker::Right : Blinker::None;
}

Blinker blinker_of_parameter(const std::string& value) {  // "None" / "Left" / "Right"
  return value == "Left" ? Blinker::Left : value == "Right" ? Blinker::Right : Blinker::None;
}

// True when a lanelet param (e.g. exit_turn_signal_left="[a, b]") lists `lane_id`; brackets,
// commas and spaces all separate (docs/behaviour.md §T5.2).
bool param_lists(const Lanelet& lanelet, const std::string& key, const std::string& lane_id) {
  const auto it = lanelet.params.find(key);
  if (it == lanelet.params.end()) return false;
  std::string token;
  for (const char c : it->second + ' ') {
    if (c == ',' || c == ' ' || c == '[' || c == ']') {
      if (token == lane_id) return true;
      token.clear();
    } else {
      token += c;
    }
  }
  return false;
}

std::string id_of(const Lanelet& l) { return l.junction_id.empty() ? l.lane_id : l.junction_id; }

}  // namespace

std::vector<SignalSection> signal_sections(const RouteMap& route, const TurnSignalParameters& params) {
  std::vector<SignalSection> out;
  const Blinker on_entry = blinker_of_parameter(params.turn_signal_roundabout_on_entry);
  const Blinker on_exit = blinker_of_parameter(params.turn_signal_roundabout_on_exit);
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (l.roundabout_role == RoundaboutRole::Entry || l.roundabout_role == RoundaboutRole::Exit) {
      SignalSection s{l.roundabout_role == RoundaboutRole::Entry ? "roundabout_entry" : "roundabout_exit", id_of(l),
                      on_exit, l.s_start, l.s_end(), {l.lane_id}};
      if (l.roundabout_role == RoundaboutRole::Entry) {
        s.blinker = on_entry;
        // The exit the route takes: the last lanelet of this roundabout after the entry.
        const Lanelet* exit = nullptr;
        for (std::size_t j = i + 1; j < route.size() && route.at(j).roundabout_role != RoundaboutRole::None &&
                                    route.at(j).roundabout_id == l.roundabout_id;
             ++j)
          exit = &route.at(j);
        if (exit && param_lists(l, "exit_turn_signal_left", exit->lane_id)) s.blinker = Blinker::Left;
        else if (exit && param_lists(l, "exit_turn_signal_right", exit->lane_id)) s.blinker = Blinker::Right;
      }
      out.push_back(std::move(s));
      continue;
    }
    if (l.roundabout_role != RoundaboutRole::None) continue;
    const Blinker b = blinker_of(l.turn_direction);
    if (b == Blinker::None) continue;
    SignalSection s{"turn", id_of(l), b, l.s_start, l.s_end(), {l.lane_id}};
    while (i + 1 < route.size() && route.at(i + 1).roundabout_role == RoundaboutRole::None &&
           route.at(i + 1).turn_direction == l.turn_direction) {
      ++i;
      s.s_end = route.at(i).s_end();
      s.lanelets.push_back(route.at(i).lane_id);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace signalsim
