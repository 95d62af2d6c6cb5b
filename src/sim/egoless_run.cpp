// The step loop of a run without an ego (egoless_run.hpp): fleet mode's pass, then SUMO's step.
#include "sim/egoless_run.hpp"

#include "fleet/fleet_tracker.hpp"
#include "sim/fleet_port.hpp"
#include "sim/step_loop.hpp"

namespace signalsim {

RunRecord run_egoless(const Scenario& scenario, const sumo::NetIndex& net, const RunContext& context) {
  StartedRun run;
  run.out_dir = context.out_dir;
  run.scenario = scenario;
  run.config = session_config(scenario, sumo::RoutePlan{}, LateralPlan{}, context);
  run.config.no_ego = true;
  run.session = sumo::open_session(run.config);
  sumo::SumoSession& session = *run.session;
  shift_light_programs(run);
  std::optional<FleetTracker> tracker = fleet_tracker(run, net);  // the scenario has fleet: (egoless_run.hpp)
  FleetPort port(session, *tracker);
  // The last step starts before the end, as the ego's run (half a step of tolerance for rounding).
  const double end = scenario.sumo.begin + scenario.duration - 0.5 * scenario.step_length;
  RunRecord record;
  EgolessRun& ran = record.egoless.emplace();
  ran.ended = "duration";
  while (session.time() < end) {
    if (session.expected_vehicles() == 0) {
      ran.ended = "no_vehicles";
      break;
    }
    port.step();  // the vehicles' blinkers for the coming step (docs/fleet.md)
    session.step();
    ++ran.steps;
  }
  ran.end_time = session.time();
  record.sumo = run_sumo_info(run);
  record.fleet = tracker->finish();
  return record;
}

}  // namespace signalsim
