// The route's signal sections and the roundabout exit-tag rule (see signal_sections.hpp).
#include "turn_signal/signal_sections.hpp"

#include <algorithm>

namespace signalsim {
namespace {

bool same_connection(const Lanelet& a, const Lanelet& b) {
  return a.roundabout_role == b.roundabout_role && a.roundabout_id == b.roundabout_id;
}

// A lanelet of the roundabout `roundabout_id` (any role): docs/behaviour.md §T5 isRoundaboutLanelet.
bool in_roundabout(const Lanelet& l, const std::string& roundabout_id) {
  return l.roundabout_role != RoundaboutRole::None && l.roundabout_id == roundabout_id;
}

}  // namespace

TurnIndicator command_of(TurnDirection d) {
  if (d == TurnDirection::Left) return TurnIndicator::EnableLeft;
  if (d == TurnDirection::Right) return TurnIndicator::EnableRight;
  return TurnIndicator::Disable;
}

TurnIndicator roundabout_command(std::string_view setting) {
  if (setting == "Left") return TurnIndicator::EnableLeft;
  if (setting == "Right") return TurnIndicator::EnableRight;
  return TurnIndicator::Disable;
}

RoundaboutConnection roundabout_connection_at(const RouteMap& route, std::size_t index) {
  RoundaboutConnection c{index, index, route.at(index).roundabout_role};
  const Lanelet& seed = route.at(index);
  while (c.front_index > 0 && same_connection(route.at(c.front_index - 1), seed)) --c.front_index;
  while (c.back_index + 1 < route.size() && same_connection(route.at(c.back_index + 1), seed)) ++c.back_index;
  return c;
}

std::optional<std::size_t> roundabout_exit_used(const RouteMap& route, const RoundaboutConnection& entry) {
  const std::string& ring = route.at(entry.front_index).roundabout_id;
  if (ring.empty()) return std::nullopt;  // "E has >= 1 roundabout"
  std::optional<std::size_t> exit;
  for (std::size_t n = entry.back_index + 1; n < route.size(); ++n) {
    if (!in_roundabout(route.at(n), ring)) break;  // left E's (first) roundabout
    exit = n;
  }
  return exit;
}

std::vector<std::string> split_exit_tag(std::string_view value) {
  std::vector<std::string> items;
  std::string current;
  for (char ch : value) {
    if (ch == ',' || ch == ' ' || ch == '[' || ch == ']') {
      if (!current.empty()) items.push_back(std::move(current));
      current.clear();
    } else {
      current.push_back(ch);
    }
  }
  if (!current.empty()) items.push_back(std::move(current));
  return items;
}

std::vector<std::string> exit_names(const RouteMap& route, std::size_t exit) {
  const Lanelet& x = route.at(exit);
  if (x.roundabout_role != RoundaboutRole::Exit) return {x.lane_id};
  std::vector<std::string> names;
  const RoundaboutConnection connection = roundabout_connection_at(route, exit);
  for (std::size_t i = connection.front_index; i <= exit; ++i) names.push_back(route.at(i).lane_id);
  // signalsim's SUMO-friendly addition: the normal edge the exit leads onto.
  for (std::size_t i = exit + 1; i < route.size(); ++i) {
    if (!route.at(i).is_internal) {
      names.push_back(route.at(i).edge_id);
      break;
    }
  }
  return names;
}

bool exit_tag_lists(const Lanelet& entry, const std::string& tag_key, const std::vector<std::string>& names) {
  const auto it = entry.params.find(tag_key);
  if (it == entry.params.end()) return false;
  for (const std::string& item : split_exit_tag(it->second))
    if (std::find(names.begin(), names.end(), item) != names.end()) return true;
  return false;
}

std::optional<TurnIndicator> exit_tag_command(const RouteMap& route, const RoundaboutConnection& entry) {
  const std::optional<std::size_t> exit = roundabout_exit_used(route, entry);
  if (!exit) return std::nullopt;
  const std::vector<std::string> names = exit_names(route, *exit);
  const Lanelet& e = route.at(entry.front_index);
  if (exit_tag_lists(e, "exit_turn_signal_left", names)) return TurnIndicator::EnableLeft;
  if (exit_tag_lists(e, "exit_turn_signal_right", names)) return TurnIndicator::EnableRight;
  return std::nullopt;
}

std::optional<std::size_t> exit_signal_chain_start(const RouteMap& route, std::size_t exit_front_index) {
  // The route is a line: the only route predecessor of lanelet i is i - 1.
  std::optional<std::size_t> start;
  std::size_t z = exit_front_index;
  while (z > 0) {
    const auto& params = route.at(z - 1).params;
    const auto it = params.find("enable_exit_turn_signal");
    if (it == params.end() || it->second != "true") break;
    start = --z;
  }
  return start;
}

const char* to_string(SignalSectionKind kind) {
  switch (kind) {
    case SignalSectionKind::RoundaboutEntry: return "roundabout_entry";
    case SignalSectionKind::RoundaboutExit: return "roundabout_exit";
    case SignalSectionKind::Turn: break;
  }
  return "turn";
}

std::vector<RouteSignalSection> route_signal_sections(const RouteMap& route, std::string_view on_entry,
                                                      std::string_view on_exit) {
  std::vector<RouteSignalSection> out;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (l.roundabout_role == RoundaboutRole::Entry || l.roundabout_role == RoundaboutRole::Exit) {
      const RoundaboutConnection c = roundabout_connection_at(route, i);
      RouteSignalSection s{SignalSectionKind::RoundaboutExit, c.front_index, c.back_index,
                           roundabout_command(on_exit), c.front_index};
      if (c.role == RoundaboutRole::Entry) {
        s.kind = SignalSectionKind::RoundaboutEntry;
        s.command = exit_tag_command(route, c).value_or(roundabout_command(on_entry));
      } else {
        s.desired_start_index = exit_signal_chain_start(route, c.front_index).value_or(c.front_index);
      }
      out.push_back(s);
      i = c.back_index;
      continue;
    }
    if (l.roundabout_role != RoundaboutRole::None) continue;
    const TurnIndicator command = command_of(l.turn_direction);
    if (command == TurnIndicator::Disable) continue;
    std::size_t last = i;  // docs/behaviour.md §T4.2 grouping
    while (last + 1 < route.size() && route.at(last + 1).roundabout_role == RoundaboutRole::None &&
           route.at(last + 1).turn_direction == l.turn_direction)
      ++last;
    out.push_back({SignalSectionKind::Turn, i, last, command, i});
    i = last;
  }
  return out;
}

}  // namespace signalsim
