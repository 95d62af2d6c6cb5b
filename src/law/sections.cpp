// A route's sections: turn groups, roundabout entries and exits (the decider's own,
// turn_signal/signal_sections), lane changes.
#include "law/sections.hpp"

#include <algorithm>
#include <map>

#include "turn_signal/signal_sections.hpp"

namespace signalsim::law {
namespace {

Side side_of(TurnIndicator command) {
  return command == TurnIndicator::EnableLeft    ? Side::Left
         : command == TurnIndicator::EnableRight ? Side::Right
                                                 : Side::None;
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

// The end of the roundabout passage after entry lanelet `last` (docs/behaviour.md §T5.2: follow the
// route while its lanelets belong to the entry's roundabout); nullopt when the route leaves at once.
std::optional<double> passage_end(const RouteMap& route, std::size_t last) {
  const std::string& id = route.at(last).roundabout_id;
  std::size_t i = last;
  while (i + 1 < route.size() && route.at(i + 1).roundabout_id == id && !id.empty()) ++i;
  if (i == last) return std::nullopt;
  return route.at(i).s_end();
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

Section maneuver_section(const ManeuverFact& m) {
  Section s;
  s.kind = SectionKind::LaneChange;
  s.maneuver = m.kind;
  s.id = m.edge;
  s.lanelets = {m.lane};
  s.start = m.edge_start;
  s.end = m.edge_end;
  s.motion_end = m.motion_end;
  // A lane change's earliest start lies on its edge; the shift generator's modules signal from
  // max(v * search_time, minimum_search_distance) before their motion's start (docs/behaviour.md §T8.1).
  s.lane_change_at = m.kind == "lane_change" ? m.edge_start : m.motion_start;
  const bool sided = m.side == Side::Left || m.side == Side::Right;
  s.side = m.kind == "lane_change" && sided && m.approval_front ? m.side : Side::Either;
  if (s.side != Side::Either) s.approval_front = m.approval_front;
  return s;
}

std::vector<Section> route_sections(const RouteMap& route, const SectionParameters& params,
                                    const std::vector<LaneChangeFact>& lane_changes) {
  std::vector<Section> out;
  const Spans spans = spans_of(route);
  for (const RouteSignalSection& r : route_signal_sections(route, params.on_entry, params.on_exit)) {
    const SectionKind kind = r.kind == SignalSectionKind::RoundaboutEntry  ? SectionKind::RoundaboutEntry
                             : r.kind == SignalSectionKind::RoundaboutExit ? SectionKind::RoundaboutExit
                                                                           : SectionKind::Turn;
    Section s = section_of(route, spans, kind, r.front_index, r.back_index);
    s.side = side_of(r.command);
    if (kind == SectionKind::Turn) s.search_distance = params.intersection_search_distance;
    if (kind == SectionKind::RoundaboutEntry) s.search_distance = params.roundabout_search_distance;
    if (kind == SectionKind::RoundaboutEntry && params.entry_persistence) s.persistent_end = passage_end(route, r.back_index);
    if (kind == SectionKind::RoundaboutExit) s.exit_desired_start = route.at(r.desired_start_index).s_start;
    out.push_back(std::move(s));
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

}  // namespace signalsim::law
