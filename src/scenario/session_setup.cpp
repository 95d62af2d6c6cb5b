#include "scenario/session_setup.hpp"

#include <filesystem>

#include "scenario/input_error.hpp"
#include "scenario/take_over.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// A taken-over vehicle's departure lane is SUMO's: unless departLane="best" (the lane its route
// continues from, as planned), it may need a lane change from the start, which needs the sublane model.
bool may_depart_off_plan(const sumo::RouteFileVehicle& v) { return v.depart_lane != "best"; }

// Waiting for a taken-over vehicle: until the sumocfg's end, else a day.
double take_over_deadline(const Scenario& s) { return s.sumo.end ? *s.sumo.end : s.sumo.begin + 86400.0; }

}  // namespace

sumo::SessionConfig session_config(const Scenario& scenario, const sumo::RoutePlan& plan, const LateralPlan& lateral,
                                   const RunContext& context) {
  const bool connect = context.backend.kind == sumo::BackendKind::Connect;
  if (connect && !scenario.light_offsets.empty())
    throw InputError(scenario.path, 0, "light_offsets change the lights of every client of the SUMO at " +
                                           context.backend.host + ":" + std::to_string(context.backend.port) +
                                           "; --connect controls only the ego");
  if (connect && !scenario.sumo.sumo_args.empty())
    throw InputError(scenario.path, 0, "sumo_args cannot reach a SUMO someone else started (--connect): give the "
                                       "options to that sumo");
  sumo::SessionConfig config;
  config.backend = context.backend;
  config.net = scenario.net;
  config.route_files = scenario.sumo.route_files;
  config.additional = scenario.additional;
  const bool gui = context.backend.kind == sumo::BackendKind::Gui;
  try {
    config.extra_args =
        sumo::sumo_tokens(scenario.sumo.cfg_options, scenario.sumo.sumocfg, context.out_dir, scenario.sumo.cfg_dir, gui);
    const auto own = sumo::sumo_tokens(sumo::parse_sumo_tokens(scenario.sumo.sumo_args), "sumo_args", context.out_dir,
                                       scenario.sumo.scenario_dir, gui);
    config.extra_args.insert(config.extra_args.end(), own.begin(), own.end());
  } catch (const sumo::SumoOptionError& e) {
    throw InputError(scenario.path, 0, e.what());
  }
  if (!context.out_dir.empty()) config.log_file = (fs::path(context.out_dir) / kSumoLogFile).string();
  config.step_length = scenario.step_length;
  config.begin = scenario.sumo.begin;
  config.seed = scenario.seed;
  config.take_over = scenario.ego.id;
  config.take_over_until = take_over_deadline(scenario);
  config.route = scenario.ego.route;
  config.depart_lane = plan.entry_lane_per_edge.empty() ? 0 : plan.entry_lane_per_edge.front();
  if (scenario.ego.depart_lane >= 0) config.depart_lane = scenario.ego.depart_lane;
  config.depart_pos = scenario.ego.depart_pos;
  config.depart_speed = scenario.ego.depart_speed;
  config.max_speed = scenario.ego.max_speed;
  config.length = scenario.ego.length;
  config.width = scenario.ego.width;
  config.accel = scenario.ego.accel;
  config.emergency_decel = scenario.ego.emergency_decel;
  // SUMO never changes lanes on its own: signalsim drives every lane change (plan_lateral).
  config.keep_planned_lanes = true;
  // signalsim drives lateral motion with sublane offsets re-commanded every step (spec SUMO §4).
  if (lateral.active()) config.lateral_resolution = 0.1;
  config.depart_pos_lat = lateral.depart_offset;
  for (const ObstacleSpec& o : scenario.obstacles) config.standing.push_back({o.id, o.edge, o.lane, o.pos, o.length});
  // SUMO driving: its own lane changes; maneuvers (a pull out's depart offset included) are signalsim's.
  if (context.sumo_drives) {
    config.sumo_drives = true;
    config.keep_planned_lanes = false;
    config.depart_pos_lat = 0.0;
  }
  return config;
}

PlannedRun plan_run(const Scenario& scenario, const sumo::NetIndex& net) {
  PlannedRun planned;
  planned.scenario = scenario;
  planned.taken_over = resolve_route_file_ego(planned.scenario);  // a taken-over vehicle's route
  planned.plan = plan_route(planned.scenario, net);
  return planned;
}

PlannedRun plan_run(const Scenario& scenario, sumo::RoutePlan plan) {
  PlannedRun planned;
  planned.scenario = scenario;
  planned.taken_over = resolve_route_file_ego(planned.scenario);
  planned.plan = std::move(plan);
  return planned;
}

StartedRun start_run(PlannedRun planned, const sumo::NetIndex& net, const RunContext& context) {
  StartedRun run;
  run.scenario = std::move(planned.scenario);
  const std::optional<sumo::RouteFileVehicle>& definition = planned.taken_over;
  sumo::RoutePlan& plan = planned.plan;
  run.lateral = plan_lateral(run.scenario, plan, net);
  sumo::SessionConfig& config = run.config;
  config = session_config(run.scenario, plan, run.lateral, context);
  if (definition && may_depart_off_plan(*definition)) config.lateral_resolution = 0.1;
  run.session = sumo::open_session(config);
  if (definition) {
    // SUMO's values for the vehicle; its lanes re-planned if it departed on another lane.
    run.scenario = with_taken_over_ego(run.scenario, run.session->ego_vehicle(), *definition);
    run.lateral = plan_lateral(run.scenario, plan, net);
    if (run.lateral.active() && config.lateral_resolution <= 0.0 && !context.sumo_drives)
      throw InputError(run.scenario.path, 0, "vehicle '" + run.scenario.ego.id + "' departed on lane " +
                                                 std::to_string(run.scenario.ego.depart_lane) +
                                                 ", from which its route needs a lane change right away, but SUMO "
                                                 "runs without the sublane model (its departLane is \"best\")");
  }
  run.plan = std::move(plan);
  return run;
}

}  // namespace signalsim
