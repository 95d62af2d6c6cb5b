// The step loop of a run, one step read top to bottom (step_loop.hpp has the algorithm).
#include "sim/step_loop.hpp"

#include <utility>

#include "sim/session_ports.hpp"
#include "step/step_core.hpp"
#include "step/sumo_driven_core.hpp"

namespace signalsim {

RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context) {
  const StartedRun run = start_run(plan_run(scenario, plan), net, context);
  return drive(run, net);
}

RunRecord drive(const StartedRun& run, const sumo::NetIndex& net) {
  CoreSetup setup = core_setup(run, net);  // shifts the light programs
  if (run.config.sumo_drives) {
    SumoDrivenCore core(std::move(setup));
    return run_steps(*run.session, core);
  }
  StepCore core(std::move(setup));
  return run_steps(*run.session, core);
}

RunRecord run_steps(sumo::SumoSession& session, RunCore& core) {
  while (true) {
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
