// The step loop of a signalsim-driven run, one step read top to bottom (step_loop.hpp has the
// algorithm; the stages and what persists between steps are in step_stages.hpp).
#include "sim/step_loop.hpp"

#include "step/step_core.hpp"

namespace signalsim {

RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context) {
  const StartedRun run = start_run(plan_run(scenario, plan), net, context);
  return drive(run, net);
}

RunRecord drive(const StartedRun& run, const sumo::NetIndex& net) {
  StepLoop loop(run, net);  // the stages, their state, the record; shifts the light programs
  while (true) {
    const StepObservation now = loop.observe();                        // ego on the route, from SUMO
    const StepManeuver maneuver = loop.maneuver(now);                  // behaviour modules, lane changes
    const BlinkerChoice blinker = loop.decide(now, maneuver);          // window + turn-signal decider
    const StepLights lights = loop.light(now);                         // perception + judge, each light
    const SpeedPlan plan = loop.plan_speed(now, maneuver, lights);     // limits, stops
    const bool alive = loop.apply(now, blinker, lights, plan);         // commands to SUMO, SUMO steps
    loop.record_step(now, maneuver, blinker, lights, plan, alive);     // row, events, stops
    if (loop.ended(alive, plan)) break;                                // arrived, stuck or duration
  }
  return loop.finish();
}

}  // namespace signalsim
