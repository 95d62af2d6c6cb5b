// The step loop of a run, one step read top to bottom (step_loop.hpp has the algorithm).
#include "sim/step_loop.hpp"

#include <optional>
#include <utility>

#include "sim/fleet_port.hpp"
#include "sim/session_ports.hpp"
#include "step/step_core.hpp"
#include "step/sumo_driven_core.hpp"

namespace signalsim {

RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context) {
  const StartedRun run = start_run(plan_run(scenario, plan), net, context);
  return drive(run, net);
}

std::optional<FleetTracker> fleet_tracker(const StartedRun& run, const sumo::NetIndex& net) {
  if (!run.scenario.fleet.enabled) return std::nullopt;
  return std::optional<FleetTracker>(std::in_place, run.scenario.fleet, run.scenario.run_params.decider,
                                     run.scenario.country, net, run.session->ego_vehicle().id,
                                     run.session->delta_t());
}

RunRecord drive(const StartedRun& run, const sumo::NetIndex& net) {
  CoreSetup setup = core_setup(run, net);  // shifts the light programs
  std::optional<FleetTracker> fleet = fleet_tracker(run, net);
  RunRecord record;
  if (run.config.sumo_drives) {
    SumoDrivenCore core(std::move(setup));
    record = run_steps(*run.session, core, fleet ? &*fleet : nullptr);
  } else {
    StepCore core(std::move(setup));
    record = run_steps(*run.session, core, fleet ? &*fleet : nullptr);
  }
  if (fleet) record.fleet = fleet->finish();
  return record;
}

RunRecord run_steps(sumo::SumoSession& session, RunCore& core, FleetTracker* fleet) {
  std::optional<FleetPort> fleet_port;
  if (fleet) fleet_port.emplace(session, *fleet);
  while (true) {
    if (fleet_port) fleet_port->step();  // the other vehicles' blinkers for the coming step (docs/fleet.md)
    sumo::EgoState ego = session.ego();                             // SUMO's ego at the step's start
    const ObservationDemand want = core.demand(ego);                // located; what else to read
    const StepObservation seen = observe(session, std::move(ego), want);  // exactly that, from SUMO
    const Commands commands = core.step(seen);                      // maneuver, decide, light, plan
    const StepFeedback feedback = apply(session, commands);         // the one writer; SUMO steps
    if (core.record(seen, feedback)) break;                         // row, events, stops; the end
  }
  return core.finish(session.ego_collisions());
}

}  // namespace signalsim
