// A route's sections: turn groups, roundabout entries and exits, lane changes.
#include "generate/sections.hpp"

#include <algorithm>
#include <map>

namespace signalsim::generate {
namespace {

Side side_of(TurnDirection d) {
  return d == TurnDirection::Left ? Side::Left : d == TurnDirection::Right ? Side::Right : Side::None;
}

Side side_of_setting(const std::string& value) {  // "Left" / "Right" / anything else (docs/behaviour.md §T1.4)
  return value == "Left" ? Side::Left : value == "Right" ? Side::Right : Side::None;
}

// docs/behaviour.md §T5.2 tag format: brackets, commas and spaces all separate.
bool tag_lists(const Lanelet& entry, const std::string& key, const std::vector<std::string>& names) {
  const auto it = entry.params.find(key);
  if (it == entry.params.end()) return false;
  std::string token;
  for (const char c : it->second + ' ') {
    if (c == ',' || c == ' ' || c == '[' || c == ']') {
      if (!token.empty() && std::find(names.begin(), names.end(), token) != names.end()) return true;
      token.clear();
    } else {
      token += c;
    }
  }
  return false;
}

struct Spans {
  std::map<std::string, std::vector<std::pair<std::size_t, std::size_t>>> by_junction;  // [first, last]
  std::map<std::string, int> lane_count;
};

Spans spans_of(const RouteMap& route) {
  Spans out;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    ++out.lane_count[l.lane_id];
    if (l.junction_id.empty()) continue;
    auto& list = out.by_junction[l.junction_id];
    if (!list.empty() && list.back().second + 1 == i) list.back().second = i;
    else list.push_back({i, i});
  }
  return out;
}

SpanTarget target_of(const RouteMap& route, const Spans& spans, std::size_t first, std::size_t last) {
  SpanTarget t;
  const std::string& junction = route.at(first).junction_id;
  if (!junction.empty()) {
    const auto it = spans.by_junction.find(junction);
    if (it != spans.by_junction.end() && it->second.size() == 1 && it->second.front().first == first &&
        it->second.front().second == last)
      t.junction = junction;
  }
  if (t.junction.empty() && first == last && spans.lane_count.at(route.at(first).lane_id) == 1)
    t.lanelet = route.at(first).lane_id;
  return t;
}

Section section_of(const RouteMap& route, const Spans& spans, SectionKind kind, std::size_t first, std::size_t last) {
  Section s;
  s.kind = kind;
  const Lanelet& front = route.at(first);
  s.id = front.junction_id.empty() ? front.lane_id : front.junction_id;
  for (std::size_t i = first; i <= last; ++i) s.lanelets.push_back(route.at(i).lane_id);
  s.start = front.s_start;
  s.end = route.at(last).s_end();
  s.target = target_of(route, spans, first, last);
  s.search_override = front.turn_signal_distance;
  return s;
}

bool same_connection(const Lanelet& a, const Lanelet& b) {
  return a.roundabout_role == b.roundabout_role && a.roundabout_id == b.roundabout_id;
}

}  // namespace

const char* to_string(Side side) {
  switch (side) {
    case Side::Left: return "left";
    case Side::Right: return "right";
    case Side::Either: return "either";
    case Side::None: break;
  }
  return "none";
}

const char* to_string(SectionKind kind) {
  switch (kind) {
    case SectionKind::RoundaboutEntry: return "roundabout_entry";
    case SectionKind::RoundaboutExit: return "roundabout_exit";
    case SectionKind::LaneChange: return "lane_change";
    case SectionKind::Turn: break;
  }
  return "turn";
}

Module module_of(SectionKind kind) {
  switch (kind) {
    case SectionKind::RoundaboutEntry:
    case SectionKind::RoundaboutExit: return Module::Roundabout;
    case SectionKind::LaneChange: return Module::Behavior;
    case SectionKind::Turn: break;
  }
  return Module::Intersection;
}

std::vector<Section> route_sections(const RouteMap& route, const SectionParameters& params,
                                    const std::vector<LaneChangeFact>& lane_changes) {
  std::vector<Section> out;
  const Spans spans = spans_of(route);
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (l.roundabout_role == RoundaboutRole::Entry || l.roundabout_role == RoundaboutRole::Exit) {
      std::size_t last = i;
      while (last + 1 < route.size() && same_connection(route.at(last + 1), l)) ++last;
      if (l.roundabout_role == RoundaboutRole::Entry) {
        Section s = section_of(route, spans, SectionKind::RoundaboutEntry, i, last);
        s.search_distance = params.roundabout_search_distance;
        s.side = side_of_setting(params.on_entry);
        // The exit this route takes: the last lanelet of this roundabout after the entry (§T5.2), named
        // by its connection's lanelets and the normal edge it leads onto (signalsim's SUMO names).
        std::optional<std::size_t> exit;
        for (std::size_t n = last + 1; n < route.size() && route.at(n).roundabout_role != RoundaboutRole::None &&
                                       route.at(n).roundabout_id == l.roundabout_id;
             ++n)
          exit = n;
        if (exit && !l.roundabout_id.empty()) {
          std::vector<std::string> names;
          std::size_t front = *exit;
          if (route.at(*exit).roundabout_role == RoundaboutRole::Exit)
            while (front > 0 && same_connection(route.at(front - 1), route.at(*exit))) --front;
          for (std::size_t k = front; k <= *exit; ++k) names.push_back(route.at(k).lane_id);
          for (std::size_t k = *exit + 1; k < route.size(); ++k)
            if (!route.at(k).is_internal) {
              names.push_back(route.at(k).edge_id);
              break;
            }
          if (tag_lists(l, "exit_turn_signal_left", names)) s.side = Side::Left;
          else if (tag_lists(l, "exit_turn_signal_right", names)) s.side = Side::Right;
        }
        out.push_back(std::move(s));
      } else {
        Section s = section_of(route, spans, SectionKind::RoundaboutExit, i, last);
        s.side = side_of_setting(params.on_exit);
        // docs/behaviour.md §T5.3: the earliest route predecessor of the chain tagged enable_exit_turn_signal.
        std::size_t z = i;
        while (z > 0) {
          const auto& p = route.at(z - 1).params;
          const auto it = p.find("enable_exit_turn_signal");
          if (it == p.end() || it->second != "true") break;
          --z;
        }
        s.exit_desired_start = route.at(z).s_start;
        out.push_back(std::move(s));
      }
      i = last;
      continue;
    }
    if (l.roundabout_role != RoundaboutRole::None) continue;
    const Side side = side_of(l.turn_direction);
    if (side == Side::None) continue;
    std::size_t last = i;  // docs/behaviour.md §T4.2 grouping
    while (last + 1 < route.size() && route.at(last + 1).roundabout_role == RoundaboutRole::None &&
           route.at(last + 1).turn_direction == l.turn_direction)
      ++last;
    Section s = section_of(route, spans, SectionKind::Turn, i, last);
    s.side = side;
    s.search_distance = params.intersection_search_distance;
    out.push_back(std::move(s));
    i = last;
  }
  for (const LaneChangeFact& lc : lane_changes) {
    Section s;
    s.kind = SectionKind::LaneChange;
    s.side = Side::Either;
    s.id = lc.edge;
    s.lanelets = {lc.lane};
    s.start = lc.edge_start;
    s.end = lc.edge_end;
    s.lane_change_at = lc.at;
    out.push_back(std::move(s));
  }
  std::stable_sort(out.begin(), out.end(), [](const Section& a, const Section& b) { return a.start < b.start; });
  return out;
}

}  // namespace signalsim::generate
