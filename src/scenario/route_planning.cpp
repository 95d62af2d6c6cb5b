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
  for (const auto& [tls, offset] : scenario.light_offsets)
    if (!net.tl_logic(tls))
      throw InputError(scenario.path, 0, "light_offsets: '" + tls + "' is not a traffic light of the net");
  return plan;
}

}  // namespace signalsim
