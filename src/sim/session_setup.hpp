// From a scenario to a running SUMO: the back-end and output directory of the run (RunContext), SUMO's
// configuration for the scenario (session_config), and start_run, which plans the route, starts SUMO,
// inserts or takes over the ego and, for a taken-over vehicle, fills in what SUMO says it is:
// plan_run (no SUMO) then start_run.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "step/route_planning.hpp"
#include "scenario/scenario.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"
#include "net/route_files.hpp"
#include "report/run_files.hpp"
#include "session/sumo_session.hpp"
#include "step/step_core.hpp"

namespace signalsim {

/// How a run reaches SUMO, beyond the scenario.
struct RunContext {
  sumo::BackendOptions backend;  ///< embedded (default), gui or connect
  /// The run's output directory: SUMO's messages go to OUT/sumo.log and relative output paths of
  /// sumo_args (and of the sumocfg's outputs) land here. Empty: no log, paths as written.
  std::string out_dir;
  /// SUMO drives the ego (`run --driver sumo`): same insertion, vType, traffic and lights, but SUMO's
  /// own speed, lane changes and blinkers (sumo::SessionConfig::sumo_drives); drive() then runs the
  /// SUMO-driven core (step/sumo_driven_core.hpp), which commands nothing.
  bool sumo_drives = false;
};

/// SUMO's configuration for `scenario` on its planned route with its lateral plan. Throws InputError
/// for a scenario the back-end cannot run (light_offsets or sumo_args with --connect: they would
/// change the simulation of the other clients, or could not be applied).
sumo::SessionConfig session_config(const Scenario& scenario, const sumo::RoutePlan& plan, const LateralPlan& lateral,
                                   const RunContext& context);

/// A run planned before SUMO starts: the scenario with a taken-over vehicle's route from the route
/// files, and its route plan.
struct PlannedRun {
  Scenario scenario;
  sumo::RoutePlan plan;
  std::optional<sumo::RouteFileVehicle> taken_over;  ///< the route-file definition of `ego.id`
  /// Taken over: its departure lane is known before SUMO starts (departLane a lane index, "first" or
  /// "best"); otherwise SUMO chooses it at insertion.
  bool departure_known = true;
};

/// Reads the route files (for `ego.id`: the vehicle's route; otherwise: no file may use the id "ego")
/// and plans the route. Throws InputError (an unknown ego id, a route file that already uses the id
/// "ego", a route that contradicts the vehicle's), sumo::NetError for a malformed route file.
PlannedRun plan_run(const Scenario& scenario, const sumo::NetIndex& net);
/// The same with a route plan made elsewhere (the ego's route must be the scenario's).
PlannedRun plan_run(const Scenario& scenario, sumo::RoutePlan plan);

/// A run whose SUMO is started and whose ego has departed.
struct StartedRun {
  Scenario scenario;       ///< as run: a taken-over vehicle's type and departure filled in
  sumo::RoutePlan plan;    ///< the route as driven
  LateralPlan lateral;
  sumo::SessionConfig config;  ///< what SUMO was started with
  std::vector<std::string> notes;  ///< what of the scenario the back-end did not apply, and why
  std::string out_dir;             ///< the run's output directory (RunContext)
  SystemsUnderTest suts;           ///< the scenario's SUTs, launched before SUMO started
  std::unique_ptr<sumo::SumoSession> session;
};

/// Launches the scenario's systems under test, then starts SUMO on the context's back-end and inserts
/// the ego, or waits for the vehicle to take over and fills in what SUMO says it is. Throws InputError
/// (a key that contradicts the vehicle's vType; a SUT's library or command that cannot be used),
/// SutError (an exec: process that could not be started), sumo::SumoError (SUMO's; the libsumo module
/// not loadable); an exec: process already launched is killed and reaped as the run unwinds.
StartedRun start_run(PlannedRun planned, const sumo::NetIndex& net, const RunContext& context);

/// The record's `sumo` fields of a started run (summary.json `sumo`, `ego`): the back-end, its
/// endpoint with --connect, the ego as SUMO had it at departure, the options passed through, the
/// output directory and log, the server's options and the back-end's notes. Never throws.
RunSumoInfo run_sumo_info(const StartedRun& run);

/// Shifts SUMO's light programs by the scenario's light_offsets (once, after SUMO started).
void shift_light_programs(const StartedRun& run);

/// What a run's core is built from (step_core.hpp CoreSetup): the route's lights with arrow bulbs from
/// SUMO's loaded programs, the record's SUMO fields and SUMO's time now. Shifts the light programs by
/// the scenario's light_offsets (call once, before the first step). Throws sumo::SumoError.
CoreSetup core_setup(const StartedRun& run, const sumo::NetIndex& net);

}  // namespace signalsim
