// The route's signal sections for the metrics (see signal_sections.hpp): the decider's sections
// (turn_signal/signal_sections), a roundabout connection split into one section per lanelet.
#include "report/signal_sections.hpp"

#include "turn_signal/signal_sections.hpp"

namespace signalsim {
namespace {

Blinker blinker_of(TurnIndicator command) {
  return command == TurnIndicator::EnableLeft    ? Blinker::Left
         : command == TurnIndicator::EnableRight ? Blinker::Right
                                                 : Blinker::None;
}

std::string id_of(const Lanelet& l) { return l.junction_id.empty() ? l.lane_id : l.junction_id; }

}  // namespace

std::vector<SignalSection> signal_sections(const RouteMap& route, const TurnSignalParameters& params) {
  std::vector<SignalSection> out;
  for (const RouteSignalSection& s : route_signal_sections(route, params.turn_signal_roundabout_on_entry,
                                                           params.turn_signal_roundabout_on_exit)) {
    const Blinker blinker = blinker_of(s.command);
    if (s.kind == SignalSectionKind::Turn) {
      const Lanelet& front = route.at(s.front_index);
      SignalSection turn{"turn", id_of(front), blinker, front.s_start, route.at(s.back_index).s_end(), {}};
      for (std::size_t i = s.front_index; i <= s.back_index; ++i) turn.lanelets.push_back(route.at(i).lane_id);
      out.push_back(std::move(turn));
      continue;
    }
    for (std::size_t i = s.front_index; i <= s.back_index; ++i) {
      const Lanelet& l = route.at(i);
      out.push_back({to_string(s.kind), id_of(l), blinker, l.s_start, l.s_end(), {l.lane_id}});
    }
  }
  return out;
}

}  // namespace signalsim
