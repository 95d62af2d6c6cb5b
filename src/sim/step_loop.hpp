// The step loop (docs/architecture.md "The step as a system", docs/run.md): SUMO's ports around a
// run's core, every step.
//
//   start SUMO, insert the ego on the planned first lane, wait for its departure (session_setup)
//   shift the light programs by the scenario's light_offsets (session_setup core_setup)
//   loop until the core says the run is over:
//     ego       SUMO's ego at the step's start
//     demand    the core locates the ego on the route and says what else the step reads
//     observe   exactly that, from SUMO, at the same moment (sim/session_ports)
//     step      the core's stages on the observation, no SUMO: maneuver, decide, light, plan
//               (step/step_core.hpp) -> Commands
//     apply     the one writer: SUMO's modes, blinker bits, speed, lateral offset, back-up; SUMO
//               advances one step and says whether the ego is still there and its signal mask
//     record    the core's row, events, stops; the end: arrived, stuck or out of time
// Fleet mode (docs/fleet.md): before each step the other vehicles' blinkers (sim/fleet_port).
// A SUMO-driven run (RunContext::sumo_drives) runs the same loop with the SUMO-driven core
// (step/sumo_driven_core.hpp), which commands nothing.
#pragma once

#include <optional>

#include "fleet/fleet_tracker.hpp"
#include "net/net_index.hpp"
#include "report/timeline.hpp"
#include "route/route_builder.hpp"
#include "scenario/scenario.hpp"
#include "session/sumo_session.hpp"
#include "sim/session_setup.hpp"
#include "step/run_core.hpp"

namespace signalsim {

/// Runs one scenario on its planned route, on the back-end `context` names (embedded libsumo by
/// default). Throws sumo::SumoError when SUMO fails.
RunRecord run_scenario(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net,
                       const RunContext& context = {});

/// The step loop on a run whose SUMO is started (session_setup.hpp start_run), with the core its
/// configuration asks for (signalsim drives, or SUMO does). Throws sumo::SumoError when SUMO fails.
RunRecord drive(const StartedRun& run, const sumo::NetIndex& net);

/// Fleet mode's tracker for a started run whose scenario asks for it (docs/fleet.md), else nothing;
/// the ego (none in an egoless run: an empty id) is never among its vehicles.
std::optional<FleetTracker> fleet_tracker(const StartedRun& run, const sumo::NetIndex& net);

/// The step loop of `core` on `session` until the core says the run is over; with `fleet`, fleet
/// mode's pass over the other vehicles before each step (docs/fleet.md). Throws sumo::SumoError when
/// SUMO fails.
RunRecord run_steps(sumo::SumoSession& session, RunCore& core, FleetTracker* fleet = nullptr);

}  // namespace signalsim
