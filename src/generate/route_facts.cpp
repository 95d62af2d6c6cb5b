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

}  // namespace

PlannedRouteFacts route_facts(const sumo::RoutePlan& plan, const LateralPlan& lateral, const sumo::NetIndex& net) {
  PlannedRouteFacts f;
  const RouteMap& route = plan.map;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (!l.is_internal && l.traffic_light) {
      f.lights.push_back({l.traffic_light->tls_id, l.stop_line_s()});
      double cycle = 0.0;
      if (const sumo::NetTlLogic* logic = net.tl_logic(l.traffic_light->tls_id))
        for (const sumo::NetPhase& p : logic->phases) cycle += p.duration;
      f.light_cycles.push_back(cycle);
      f.stops.push_back({l.stop_line_s(), true, "light " + l.traffic_light->tls_id});
      continue;
    }
    if (i + 1 >= route.size()) continue;
    const sumo::NetConnection* c = link_between(route, i, net);
    if (c == nullptr) continue;
    const std::string junction = route.at(i + 1).is_internal ? route.at(i + 1).junction_id : l.junction_id;
    if (!c->tl.empty() && l.is_internal)
      f.stops.push_back({l.s_end(), true, "light " + c->tl + " inside junction " + junction});
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
