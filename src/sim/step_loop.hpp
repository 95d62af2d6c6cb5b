// The step loop (docs/architecture.md, docs/run.md): observe -> maneuver -> decide ->
// light -> plan -> apply -> record, every step.
//
//   start SUMO, insert the ego on the planned first lane, wait for its departure (session_setup)
//   shift the light programs by the scenario's light_offsets
//   loop until the ego arrives, `duration` simulated seconds have passed, or the stuck rule ends
//   the run (at rest stuck_rest_time while signalsim commands it to drive, sim/stuck_watch):
//     observe   ego lane/position/speed from SUMO; s_front from the RouteMap; s_base = s_front - b2f;
//               whether SUMO left the lane plan (sim/plan_watch); the offset from the planned lane
//     maneuver  the behaviour modules' request and the lane changes' phases (sim/behavior_stage)
//     decide    window and blinker = TurnSignalDecider::decide(route, ego, behaviour)    (docs/behaviour.md §T3)
//     light     every light in the window: perception, then TrafficLightJudge::step    (docs/behaviour.md §L1-§L2)
//     plan      speed under the lane limits ahead, lowered by a jerk-limited stop for each stop
//               point (light, pull-over goal, hold point) only once a normal stop must begin
//               (normal, limit, then emergency constraint set)   (planning/stop/stop_speed_planner)
//     apply     SUMO's speed mode, blinker bits + speed (re-sent every step, docs/behaviour.md §S4), the
//               lateral offset, a back-up; SUMO advances one step
//     record    the row: observation, decision, and the mask SUMO showed while executing it;
//               events on change; stops and red crossings (sim/step_record, sim/light_outcomes)
//     end       arrived, stuck or out of time: the record says which
// Each stage is a member function of StepLoop (sim/step_stages.hpp), which also holds what lives
// from one step to the next.
#pragma once

#include "scenario/scenario.hpp"
#include "report/timeline.hpp"
#include "sim/session_setup.hpp"
#include "route/route_builder.hpp"

namespace signalsim {

/// Runs one scenario on its planned route, on the back-end `context` names (embedded libsumo by
/// default). Throws sumo::SumoError when SUMO fails.
RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context = {});

/// The step loop on a run whose SUMO is started (session_setup.hpp start_run). Throws
/// sumo::SumoError when SUMO fails.
RunRecord drive(const StartedRun& run, const sumo::NetIndex& net);

}  // namespace signalsim
