#include "scenario/route_planning.hpp"

#include <sstream>

#include "scenario/input_error.hpp"
#include "turn_signal/exit_signal_marking.hpp"

namespace signalsim {

sumo::RoutePlan prepare_route(sumo::RoutePlan plan, const ParameterSet& params) {
  if (params.boolean("turn_signal_roundabout_exit_signal_from_previous_exit"))
    plan.map = mark_exit_signal_lanes(std::move(plan.map));
  return plan;
}

LateralPlan plan_lateral(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net) {
  LateralPlan lateral;
  const Lanelet& first = plan.map.at(0);
  lateral.edge = first.edge_id;
  lateral.reference_lane = first.lane_id;
  const sumo::NetEdge* edge = net.edge(first.edge_id);
  const int planned = plan.lane_per_edge.empty() ? 0 : plan.lane_per_edge.front();
  const int depart = scenario.ego.depart_lane < 0 ? planned : scenario.ego.depart_lane;
  if (edge == nullptr) return lateral;
  if (depart >= static_cast<int>(edge->lanes.size()) || !edge->lanes[static_cast<std::size_t>(depart)].allows_passenger) {
    std::ostringstream out;
    out << "ego.depart_lane: edge '" << edge->id << "' has no lane " << depart << " the ego may drive ("
        << edge->lanes.size() << " lanes)";
    throw InputError(scenario.path, 0, out.str());
  }
  if (depart == planned) {
    if (scenario.lane_change)
      throw InputError(scenario.path, 0,
                       "maneuvers: lane_change: the ego departs on the planned lane " + first.lane_id +
                           " of the first edge; set ego.depart_lane to another lane");
    return lateral;
  }
  // The depart lane's centre seen from the planned lane's centre (left positive).
  const auto width = [&](int i) { return edge->lanes[static_cast<std::size_t>(i)].width; };
  const int step = depart > planned ? 1 : -1;
  double offset = 0.5 * width(planned) + 0.5 * width(depart);
  for (int i = planned + step; i != depart; i += step) offset += width(i);
  offset *= step;
  lateral.boundary = step * 0.5 * width(planned);
  const double b2f = scenario.ego.base_link_to_front;
  const double depart_base = scenario.ego.depart_pos - b2f;
  LaneChangeManeuver m;
  m.at = depart_base + kDefaultLaneChangeLead;
  m.length = kDefaultLaneChangeLength;
  if (scenario.lane_change) m = *scenario.lane_change;
  if (m.at < depart_base) {
    std::ostringstream out;
    out << "maneuvers: lane_change.at " << m.at << " m is behind base_link's depart position " << depart_base << " m";
    throw InputError(scenario.path, 0, out.str());
  }
  // No lateral command on internal lanes: the shift ends while the front is still on the edge.
  if (m.at + m.length + b2f > first.length) {
    std::ostringstream out;
    out << "maneuvers: the lane change on '" << edge->id << "' (base_link " << m.at << " + " << m.length
        << " m) must end while the front bumper is still on the edge (" << first.length << " m)";
    throw InputError(scenario.path, 0, out.str());
  }
  lateral.plan = ShiftPlan({ShiftLine{m.at, m.at + m.length, offset, 0.0}});
  return lateral;
}

sumo::RoutePlan plan_route(const Scenario& scenario, const sumo::NetIndex& net) {
  sumo::RoutePlan plan;
  try {
    plan = prepare_route(sumo::build_route(net, scenario.ego.route), scenario.params);
  } catch (const sumo::RouteError& e) {
    throw InputError(scenario.path, 0, std::string("ego.route: ") + e.what());
  }
  // What SUMO would otherwise clamp or reject only after it started.
  const Lanelet& first = plan.map.at(0);
  if (scenario.ego.depart_pos > first.length) {
    std::ostringstream out;
    out << "ego.depart_pos: " << scenario.ego.depart_pos << " m is beyond the end of edge '" << first.edge_id
        << "' (" << first.length << " m)";
    throw InputError(scenario.path, 0, out.str());
  }
  plan_lateral(scenario, plan, net);  // checks the depart lane and the maneuvers
  for (const auto& [tls, offset] : scenario.light_offsets)
    if (!net.tl_logic(tls))
      throw InputError(scenario.path, 0, "light_offsets: '" + tls + "' is not a traffic light of the net");
  return plan;
}

}  // namespace signalsim
