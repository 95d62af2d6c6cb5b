#include "sim/session_setup.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <utility>

#include "sut/sut_factory.hpp"
#include "route/approach_lights.hpp"
#include "report/run_files.hpp"
#include "scenario/input_error.hpp"
#include "scenario/take_over.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// SUMO's departLane of a taken-over vehicle, as far as it is known before SUMO starts: a lane index
// ("2"), "first" (SUMO's default: the rightmost lane a passenger car may use), "best" (a lane its
// route continues from: no lane change at the start); nullopt for random, free, allowed, ... (SUMO
// decides at insertion). -1 stands for "best".
constexpr int kBestLane = -1;
std::optional<int> known_departure_lane(const sumo::RouteFileVehicle& v, const sumo::NetIndex& net,
                                        const std::string& first_edge) {
  const std::string& d = v.depart_lane;
  if (d == "best") return kBestLane;
  if (!d.empty() && std::all_of(d.begin(), d.end(), [](unsigned char c) { return std::isdigit(c); }))
    return std::stoi(d);
  if (d.empty() || d == "first") {
    if (const sumo::NetEdge* edge = net.edge(first_edge))
      for (const sumo::NetLane& lane : edge->lanes)
        if (sumo::lane_permits(lane, v.vclass)) return lane.index;
  }
  return std::nullopt;
}

constexpr double kSublaneWidth = 0.1;  // [m] SUMO --lateral-resolution when signalsim needs the sublane model
// SUMO's --lanechange.duration for a run whose lateral motion is lane changes only, in steps: the
// least that is continuous (SUMO: more than one step), so that every other vehicle's lane change
// stays as short as it can (docs/performance.md "Lane changes in traffic").
constexpr double kLaneChangeSteps = 2.0;

// Whether every lateral motion of the plan goes from one lane's centre to another's (the lane
// changes), which SUMO's continuous lane change drives; avoidance, pull out and pull over move the
// ego beside a lane's centre, which needs the sublane model.
bool lane_changes_only(const LateralPlan& lateral) {
  return lateral.depart_offset == 0.0 && lateral.backward == 0.0 &&
         std::all_of(lateral.segments.begin(), lateral.segments.end(),
                     [](const LateralSegment& s) { return s.kind == LateralKind::LaneChange; });
}

// A continuous lane change crosses one lane: a shift over two or more lanes on one edge is one SUMO
// manoeuvre after another, and the ego stops at the centre between them for the rest of that step
// (docs/behaviour.md §S4). That step's lag is at most the plan's lateral motion in a step: its
// steepest slope (1.875 shift / length for a quintic line) at the top speed. Such a shift is left to
// the sublane model when that could exceed kMostLag.
constexpr double kMostLag = 0.1;  // [m] half the default tolerance of lateral_offset_follows_plan
bool lags_between_lanes(const LateralPlan& lateral, double max_speed, double step_length) {
  for (const LateralSegment& segment : lateral.segments) {
    const double lane_width = segment.left_half_width + segment.right_half_width;
    for (const ShiftLine& line : segment.plan.lines()) {
      const double shift = std::abs(line.relative_shift());
      if (shift <= 1.5 * lane_width || line.length() <= 0.0) continue;  // one lane
      if (1.875 * shift / line.length() * max_speed * step_length > kMostLag) return true;
    }
  }
  return false;
}

// The lateral model of a run (docs/behaviour.md §S4): a user's own sublane model or continuous lane
// change if their SUMO options set one, else the continuous lane change for lane changes only (none
// over several lanes fast enough to lag) and the sublane model for every other maneuver.
void choose_lateral_model(sumo::SessionConfig& config, const LateralPlan& lateral,
                          std::optional<double> user_lateral_resolution, std::optional<double> user_lane_change_duration,
                          double step_length, double max_speed) {
  if (user_lateral_resolution) {
    config.lateral_resolution = *user_lateral_resolution;
    if (config.lateral_resolution > 0.0 || !lateral.active()) return;
  }
  if (!lateral.active()) return;
  const bool user_continuous = user_lane_change_duration && *user_lane_change_duration > step_length + 1e-9;
  if (lane_changes_only(lateral) && !lags_between_lanes(lateral, max_speed, step_length) &&
      (!user_lane_change_duration || user_continuous))
    config.lane_change_duration = user_continuous ? *user_lane_change_duration : kLaneChangeSteps * step_length;
  else
    config.lateral_resolution = kSublaneWidth;
}

// A user's SUMO options that cannot run the sublane model the plan needs: a lateral-resolution of 0,
// or a positive lanechange.duration (SUMO refuses it beside a lateral-resolution: MSFrame::checkOptions).
void refuse_user_lateral_options(const std::string& path, const sumo::SessionConfig& config,
                                 std::optional<double> user_lateral_resolution,
                                 std::optional<double> user_lane_change_duration) {
  if (config.lateral_resolution <= 0.0 || (user_lateral_resolution && *user_lateral_resolution > 0.0)) return;
  const char* needs = "the scenario drives lateral motion that needs SUMO's sublane model (avoidance, pull out, "
                      "pull over, a shift over several lanes too fast for the continuous lane change, or lane "
                      "changes with a lanechange.duration of a step or less), but its SUMO options set ";
  if (user_lateral_resolution)
    throw InputError(path, 0, needs + ("lateral-resolution " + std::to_string(*user_lateral_resolution)));
  if (user_lane_change_duration && *user_lane_change_duration > 0.0)
    throw InputError(path, 0, needs + ("lanechange.duration " + std::to_string(*user_lane_change_duration)) +
                                  ", which SUMO does not run beside the sublane model");
}

// Waiting for a taken-over vehicle: until the sumocfg's end, else a day.
double take_over_deadline(const Scenario& s) { return s.sumo.end ? *s.sumo.end : s.sumo.begin + 86400.0; }

}  // namespace

sumo::SessionConfig session_config(const Scenario& scenario, const sumo::RoutePlan& plan, const LateralPlan& lateral,
                                   const RunContext& context) {
  const bool connect = context.backend.kind == sumo::BackendKind::Connect;
  // A traci SUT is another client of the SUMO signalsim connects to (docs/decider.md "Another TraCI client").
  for (const auto& [key, spec] : {std::pair{"decider", &scenario.decider}, std::pair{"light_judge", &scenario.light_judge}})
    if (!connect && spec->kind == SutSpec::Kind::Traci)
      throw InputError(scenario.path, 0, std::string(key) + " traci is another TraCI client of the SUMO the run "
                                         "shares with it: it needs --connect HOST:PORT");
  if (connect && !scenario.light_offsets.empty())
    throw InputError(scenario.path, 0, "light_offsets change the lights of every client of the SUMO at " +
                                           context.backend.host + ":" + std::to_string(context.backend.port) +
                                           "; --connect controls only the ego");
  if (connect && !scenario.sumo.sumo_args.empty())
    throw InputError(scenario.path, 0, "sumo_args cannot reach a SUMO someone else started (--connect): give the "
                                       "options to that sumo");
  if (connect && !scenario.obstacles.empty())
    throw InputError(scenario.path, 0, "obstacles would be vehicles in the simulation of every client of the SUMO at " +
                                           context.backend.host + ":" + std::to_string(context.backend.port) +
                                           "; --connect controls only the ego");
  sumo::SessionConfig config;
  config.backend = context.backend;
  config.net = scenario.net;
  config.route_files = scenario.sumo.route_files;
  config.additional = scenario.additional;
  const bool gui = context.backend.kind == sumo::BackendKind::Gui;
  std::optional<double> user_lateral_resolution;  // a user's own sublane model, for their traffic too
  std::optional<double> user_lane_change_duration;  // and their own continuous lane change
  try {
    // sumo_args win over the sumocfg's options of the same name (SUMO refuses an option twice).
    const std::vector<sumo::SumoOption> own = sumo::parse_sumo_tokens(scenario.sumo.sumo_args);
    std::vector<sumo::SumoOption> cfg = scenario.sumo.cfg_options;
    std::erase_if(cfg, [&](const sumo::SumoOption& c) {
      return std::any_of(own.begin(), own.end(), [&](const sumo::SumoOption& o) { return o.name == c.name; });
    });
    for (const std::vector<sumo::SumoOption>* options : {&std::as_const(cfg), &own})
      for (const sumo::SumoOption& o : *options)
        if (o.name == "lateral-resolution") user_lateral_resolution = std::atof(o.value.c_str());
        else if (o.name == "lanechange.duration") user_lane_change_duration = std::atof(o.value.c_str());
    config.extra_args = sumo::sumo_tokens(cfg, scenario.sumo.sumocfg, context.out_dir, scenario.sumo.cfg_dir, gui);
    const auto tokens = sumo::sumo_tokens(own, "sumo_args", context.out_dir, scenario.sumo.scenario_dir, gui);
    config.extra_args.insert(config.extra_args.end(), tokens.begin(), tokens.end());
  } catch (const sumo::SumoOptionError& e) {
    throw InputError(scenario.path, 0, e.what());
  }
  if (!context.out_dir.empty()) config.log_file = (fs::path(context.out_dir) / run_files::kSumoLog).string();
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
  // signalsim drives lateral motion with offsets re-commanded every step (docs/behaviour.md §S4).
  choose_lateral_model(config, lateral, user_lateral_resolution, user_lane_change_duration, scenario.step_length,
                       scenario.ego.max_speed);
  refuse_user_lateral_options(scenario.path, config, user_lateral_resolution, user_lane_change_duration);
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
  if (planned.taken_over && !planned.scenario.ego.route.empty()) {
    const auto lane = known_departure_lane(*planned.taken_over, net, planned.scenario.ego.route.front());
    planned.departure_known = lane.has_value();
    if (lane && *lane >= 0) planned.scenario.ego.depart_lane = *lane;  // plan from where it will be
  }
  try {
    planned.plan = plan_route(planned.scenario, net);
  } catch (const InputError& e) {
    // A taken-over vehicle's route is its route file's: the fault is named there.
    if (!planned.taken_over || e.file() != planned.scenario.path) throw;
    const sumo::RouteFileVehicle& v = *planned.taken_over;
    throw InputError(v.file, v.line, "<" + v.kind + "> '" + v.id + "' (ego.id of " + planned.scenario.path +
                                         "): " + e.reason());
  }
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
  run.out_dir = context.out_dir;
  run.scenario = std::move(planned.scenario);
  const std::optional<sumo::RouteFileVehicle>& definition = planned.taken_over;
  sumo::RoutePlan& plan = planned.plan;
  run.lateral = plan_lateral(run.scenario, plan, net);
  sumo::SessionConfig& config = run.config;
  config = session_config(run.scenario, plan, run.lateral, context);
  // A departure lane SUMO chooses at insertion (random, free, ...) may need a lane change at once:
  // signalsim drives it with the continuous lane change, which must be on from the start.
  if (definition && !planned.departure_known && config.lateral_resolution <= 0.0 && config.lane_change_duration <= 0.0)
    config.lane_change_duration = kLaneChangeSteps * run.scenario.step_length;
  if (context.backend.kind == sumo::BackendKind::Connect &&
      (!run.scenario.sumo.route_files.empty() || !run.scenario.additional.empty() ||
       !run.scenario.sumo.cfg_options.empty()))
    run.notes.push_back("--connect: the scenario's route files, additional files and sumocfg options are the "
                        "server's business; signalsim did not load them (the server reports its own in "
                        "sumo.server_options)");
  // An exec: SUT's process starts up (a Python interpreter: tens of ms) while SUMO loads.
  run.suts = make_systems_under_test(run.scenario);
  if (run.suts.decider) run.suts.decider->launch(run.out_dir);
  if (run.suts.light_judge) run.suts.light_judge->launch(run.out_dir);
  run.session = sumo::open_session(config);
  if (definition) {
    const sumo::EgoVehicle& vehicle = run.session->ego_vehicle();
    if (vehicle.route != run.scenario.ego.route)
      throw InputError(definition->file, definition->line,
                       "vehicle '" + vehicle.id + "' drives [" + edges_text(vehicle.route) + "] in SUMO, not the route [" +
                           edges_text(run.scenario.ego.route) + "] of its route file (did the SUMO at the other end "
                           "load other route files?)");
    // SUMO's values for the vehicle; its lanes planned from the lane it departed on.
    run.scenario = with_taken_over_ego(run.scenario, vehicle, *definition);
    plan = plan_route(run.scenario, net);
    run.lateral = plan_lateral(run.scenario, plan, net);
    if (run.lateral.active() && config.lateral_resolution <= 0.0 && config.lane_change_duration <= 0.0 &&
        !context.sumo_drives)
      throw InputError(definition->file, definition->line,
                       "vehicle '" + vehicle.id + "' departed on lane " + std::to_string(vehicle.depart_lane) +
                           " and its route needs a lane change, which signalsim drives with SUMO's continuous lane "
                           "change; SUMO runs without it (the route file's departLane did not say that a change is "
                           "needed)");
  }
  run.plan = std::move(plan);
  return run;
}

RunSumoInfo run_sumo_info(const StartedRun& run) {
  const sumo::SumoSession& session = *run.session;
  RunSumoInfo info;
  info.backend = session.backend();
  if (run.config.backend.kind == sumo::BackendKind::Connect)
    info.endpoint = run.config.backend.host + ":" + std::to_string(run.config.backend.port);
  info.ego = session.ego_vehicle();
  info.args = run.config.extra_args;
  info.out_dir = run.out_dir;
  info.log = run.config.log_file;
  info.server_options = session.server_options();
  info.notes = run.notes;
  return info;
}

void shift_light_programs(const StartedRun& run) {
  for (const auto& [tls, offset] : run.scenario.light_offsets) run.session->shift_light_program(tls, offset);
}

// The route's lights with arrow bulbs from every program SUMO loaded (additional files may replace the
// net's program); then the scenario's light offsets shift the programs.
CoreSetup core_setup(const StartedRun& run, const sumo::NetIndex& net) {
  sumo::SumoSession& session = *run.session;
  std::vector<sumo::ApproachLight> lights = sumo::approach_lights(net, run.plan.map);
  for (sumo::ApproachLight& a : lights) a.has_arrow = sumo::shows_arrow(session.program_states(a.tls_id), a);
  shift_light_programs(run);
  return CoreSetup{run.scenario,      run.plan.map,    run.lateral, std::move(lights), run_sumo_info(run),
                   session.time(),    run.suts};
}

}  // namespace signalsim
