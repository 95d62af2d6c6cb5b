#include "scenario/route_planning.hpp"

#include "scenario/input_error.hpp"
#include "turn_signal/exit_signal_marking.hpp"

namespace signalsim {

sumo::RoutePlan prepare_route(sumo::RoutePlan plan, const ParameterSet& params) {
  if (params.boolean("turn_signal_roundabout_exit_signal_from_previous_exit"))
    plan.map = mark_exit_signal_lanes(std::move(plan.map));
  return plan;
}

sumo::RoutePlan plan_route(const Scenario& scenario, const sumo::NetIndex& net) {
  try {
    return prepare_route(sumo::build_route(net, scenario.ego.route), scenario.params);
  } catch (const sumo::RouteError& e) {
    throw InputError(scenario.path, 0, std::string("ego.route: ") + e.what());
  }
}

}  // namespace signalsim
