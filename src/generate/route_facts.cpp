// Lights, yielding links and lane changes of one planned route, read from the net.
#include "generate/route_facts.hpp"

namespace signalsim::generate {
namespace {

bool yields(char state) {
  return state == 'm' || state == '=' || state == 's' || state == 'w' || state == 'Z' || state == 'o' || state == 'O';
}

// The connection taken from lanelet i to lanelet i + 1 (the next must be internal, or follow an
// internal one), if the net has it.
const sumo::NetConnection* link_between(const RouteMap& route, std::size_t i, const sumo::NetIndex& net) {
  const Lanelet& here = route.at(i);
  const Lanelet& next = route.at(i + 1);
  if (next.is_internal) {
    if (!here.is_internal) return net.connection_via(next.lane_id);
    for (const sumo::NetConnection& c : net.connections_from_lane(here.lane_id))
      if (c.via == next.lane_id) return &c;
    return nullptr;
  }
  if (!here.is_internal) return nullptr;
  for (const sumo::NetConnection& c : net.connections_from_lane(here.lane_id))
    if (c.to_edge == next.edge_id) return &c;
  return nullptr;
}

// The program SUMO runs for a light: the last one the net defines for its id (a newly loaded
// program becomes the default, MSTLLogicControl::add).
const sumo::NetTlLogic* running_program(const sumo::NetIndex& net, const std::string& tls) {
  const sumo::NetTlLogic* last = nullptr;
  for (const sumo::NetTlLogic& logic : net.tl_logics())
    if (logic.id == tls) last = &logic;
  return last;
}

bool ever_passable(const sumo::NetTlLogic& logic, int link_index) {
  for (const sumo::NetPhase& p : logic.phases) {
    if (link_index < 0 || static_cast<std::size_t>(link_index) >= p.state.size()) continue;
    const char c = p.state[static_cast<std::size_t>(link_index)];
    if (c == 'G' || c == 'g' || c == 's' || c == 'o' || c == 'O') return true;
  }
  return false;
}

void check_link(const sumo::NetIndex& net, const std::string& tls, int link_index, PlannedRouteFacts& f) {
  const sumo::NetTlLogic* logic = running_program(net, tls);
  if (logic == nullptr || !ever_passable(*logic, link_index))
    f.never_green.push_back(tls + " link " + std::to_string(link_index));
}

}  // namespace

PlannedRouteFacts route_facts(const sumo::RoutePlan& plan, const LateralPlan& lateral, const sumo::NetIndex& net) {
  PlannedRouteFacts f;
  const RouteMap& route = plan.map;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (!l.is_internal && l.traffic_light) {
      f.lights.push_back({l.traffic_light->tls_id, l.stop_line_s()});
      double cycle = 0.0;
      if (const sumo::NetTlLogic* logic = running_program(net, l.traffic_light->tls_id))
        for (const sumo::NetPhase& p : logic->phases) cycle += p.duration;
      f.light_cycles.push_back(cycle);
      check_link(net, l.traffic_light->tls_id, l.traffic_light->link_index, f);
      f.stops.push_back({l.stop_line_s(), true, "light " + l.traffic_light->tls_id});
      continue;
    }
    if (i + 1 >= route.size()) continue;
    const sumo::NetConnection* c = link_between(route, i, net);
    if (c == nullptr) continue;
    const std::string junction = route.at(i + 1).is_internal ? route.at(i + 1).junction_id : l.junction_id;
    if (!c->tl.empty() && l.is_internal) {
      f.stops.push_back({l.s_end(), true, "light " + c->tl + " inside junction " + junction});
      check_link(net, c->tl, c->link_index, f);
    }
    else if (c->tl.empty() && yields(c->state))
      f.stops.push_back({l.s_end(), false,
                         "the yield at junction " + junction + " (link state " + std::string(1, c->state) + ")"});
  }
  for (const LateralSegment& seg : lateral.segments) {
    if (seg.kind != LateralKind::LaneChange) continue;
    const Lanelet& l = route.at(seg.route_index);
    f.lane_changes.push_back({seg.edge, seg.reference_lane, seg.lane_change.earliest_start, l.s_start, l.s_end()});
  }
  return f;
}

}  // namespace signalsim::generate
