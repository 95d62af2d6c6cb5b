// The step loop (DESIGN.md): observe -> window -> decide -> plan -> apply -> record, every step.
//
//   start SUMO, insert the ego on the planned first lane, wait for its departure
//   loop until the ego arrives, `duration` simulated seconds have passed, or the stuck rule ends
//   the run (at rest stuck_rest_time while signalsim commands it to drive, scenario/stuck_watch):
//     observe  ego lane/position/speed from SUMO; s_front from the RouteMap; s_base = s_front - b2f
//     decide   blinker = TurnSignalDecider::decide(route, ego)                  (spec TSD §3)
//     light    the next light: perception, then TrafficLightJudge::step         (spec TLJ §1-§2)
//     plan     speed under the lane limits ahead, lowered by a jerk-limited stop for each stop
//              point (light, pull-over goal, hold point) only once a normal stop must begin
//              (normal, limit, then emergency constraint set)   (planning/stop/stop_speed_planner)
//     apply    blinker bits + speed to SUMO (re-sent every step, spec SUMO §4)
//     step     SUMO advances one step
//     record   the row: observation, decision, and the mask SUMO showed while executing it
#pragma once

#include "scenario/scenario.hpp"
#include "report/timeline.hpp"
#include "sim/session_setup.hpp"
#include "sumo/route_builder.hpp"

namespace signalsim {

/// Runs one scenario on its planned route, on the back-end `context` names (embedded libsumo by
/// default). Throws sumo::SumoError when SUMO fails.
RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context = {});

/// The step loop on a run whose SUMO is started (session_setup.hpp start_run). Throws
/// sumo::SumoError when SUMO fails.
RunRecord drive(const StartedRun& run, const sumo::NetIndex& net);

}  // namespace signalsim
