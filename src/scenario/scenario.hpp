// A scenario file: the net, the ego and its route, parameters and expectations (YAML).
#pragma once

#include <string>
#include <variant>
#include <vector>

#include <map>
#include <optional>

#include <set>

#include "core/blinker_signals.hpp"  // Blinker
#include "core/vehicle_defaults.hpp"
#include "scenario/key_origins.hpp"
#include "scenario/sut_spec.hpp"
#include "scenario/parameters.hpp"
#include "route/lane_change_room.hpp"
#include "net/sumo_options.hpp"
#include "traffic_light/perception_model.hpp"
#include "traffic_light/v2i_channel.hpp"

namespace signalsim {

std::string_view to_string(Blinker b);  ///< "none", "left", "right", "hazard"

struct EgoSpec {
  /// Take over this vehicle of the route files when it departs (its route, vType and departure are
  /// SUMO's); empty: signalsim adds its own ego (id "ego") on `route`.
  std::string id;
  std::vector<std::string> route;   ///< edge ids; each must connect to the next
  double depart_pos = 0.0;          ///< [m] on the first edge
  double depart_speed = 0.0;        ///< [m/s]
  double max_speed = vehicle_defaults::kMaxSpeed;  ///< [m/s]
  double length = vehicle_defaults::kLength;  ///< [m]
  double width = vehicle_defaults::kWidth;  ///< [m] (SUMO's DEFAULT_VEHTYPE; a taken-over vehicle's from its vType)
  /// Rear-axle centre to front bumper [m]. Default: vehicle_defaults::kBaseLinkShare of the length (3.7 m of 4.5 m).
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;
  double accel = 1.0;               ///< comfortable acceleration [m/s^2] (Autoware normal set)
  double decel = 1.0;               ///< comfortable deceleration [m/s^2] (Autoware normal set)
  double emergency_decel = 9.0;     ///< the most the ego can brake [m/s^2] (SUMO passenger default)
  /// Lane index the ego departs on; -1 = the planned lane of the first edge. Another lane makes
  /// signalsim plan a lane change onto the planned lane on the first edge (see LaneChangeManeuver).
  int depart_lane = -1;
  /// SUMO vehicle class: the lanes the ego may use. signalsim's own ego is a passenger car; a
  /// taken-over vehicle has its vType's (the route files' before the run, SUMO's once it departed).
  std::string vclass = "passenger";
  /// Its vType's decel in SUMO [m/s^2] (SUMO's look-ahead for lane choices; own ego: 4.5).
  double sumo_decel = vehicle_defaults::kSumoDecel;
  /// The keys the scenario (or --set) gave; the others are defaults, or SUMO's for a taken-over ego.
  std::set<std::string> given;
  std::string vehicle_info;                ///< `vehicle_info:` (resolved), empty when none
  std::set<std::string> from_vehicle_info; ///< of `given`: the keys the vehicle_info file set
  std::vector<std::string> vehicle_info_unused;  ///< keys of the vehicle_info file signalsim does not use
  std::map<std::string, int> lines;  ///< the scenario file's line of each given key (0: from --set)
};

/// What SUMO is given beyond the net (docs/sumo.md): a user's .sumocfg, route files and SUMO options.
struct SumoInputs {
  std::string sumocfg;                        ///< the .sumocfg (resolved), empty when none
  std::vector<std::string> route_files;       ///< SUMO -r: the sumocfg's, then `routes:`
  std::vector<std::string> sumo_args;         ///< `sumo_args:` tokens as written (checked at load)
  std::vector<sumo::SumoOption> cfg_options;  ///< the sumocfg's other options, passed on to SUMO
  std::vector<int> cfg_option_lines;          ///< the sumocfg's line of each of cfg_options
  std::string cfg_dir;                        ///< the sumocfg's folder (its relative file names)
  std::string scenario_dir;                   ///< the scenario's folder (relative names in sumo_args)
  double begin = 0.0;                         ///< the sumocfg's begin [s]
  std::optional<double> end;                  ///< the sumocfg's end [s]: the run ends there at the latest
  /// For the summary: the sumocfg values the run used, those the scenario's own keys replaced, and
  /// the options signalsim ignores because it sets them itself (each with the reason).
  std::vector<std::string> cfg_used, cfg_overridden, cfg_ignored;
};

/// `maneuvers: [{lane_change: {at, length}}]`: the timing of the lane change from ego.depart_lane to
/// the first edge's planned lane (the lane with the connection to the next edge). Without it the
/// lane change starts kDefaultLaneChangeLead metres after base_link's depart position and is
/// kDefaultLaneChangeLength long.
/// With `edge` (and `to_lane`) it is a requested lane change on that route edge: the lane plan
/// leaves `edge` on `to_lane` and enters it on another lane (sumo::plan_lanes' required exit).
/// Several lane changes are allowed, at most one per edge.
/// The lateral motion starts after the module's prepare segment (planning/lane_change_execution.hpp):
/// `at` is the earliest start; the blinker comes on max(v * turn_signal_search_time,
/// turn_signal_minimum_search_distance) before it; approval comes `approval_delay` seconds after the
/// blinker (and once the target lane is clear); the lateral motion then starts
/// max(max_prepare_duration - blinker-on time, min_prepare_duration) * v further on.
struct LaneChangeManeuver {
  std::string edge;   ///< empty: the first edge, from ego.depart_lane
  int to_lane = -1;   ///< with `edge`: the lane the ego is on at the end of `edge`
  double at = -1.0;      ///< base_link's earliest start of the lateral motion [m] (route s; on `edge`
                         ///< with `edge`); < 0: default
  double length = 50.0;  ///< [m] of route s over which the ego shifts one lane
  double approval_delay = 0.0;  ///< [s] after the blinker came on (an operator's RTC approval)
  std::string key;  ///< where it is in the file, "maneuvers[2]" (key_error)
};
// The defaults are the lane plan's own (one rule for the plan and the lateral planner).
inline constexpr double kDefaultLaneChangeLead = sumo::kLaneChangeLead;      ///< [m]
inline constexpr double kDefaultLaneChangeLength = sumo::kLaneChangeLength;  ///< [m]

/// `obstacles: [{id, edge, lane, pos, length}]`: a vehicle standing still on a lane for the whole run
/// (SUMO: inserted with a stop at its position), 1.8 m wide like SUMO's default vehicle type.
struct ObstacleSpec {
  std::string id;
  std::string edge;
  int lane = 0;           ///< lane index on `edge`
  double pos = 0.0;       ///< lane position of its front [m]
  double length = 4.5;    ///< [m]
};
inline constexpr double kObstacleWidth = vehicle_defaults::kWidth;  ///< [m] SUMO DEFAULT_VEHTYPE

/// `maneuvers: [{avoid: {obstacle, clearance, side, length, approval_delay}}]`: pass a declared
/// obstacle standing on the ego's planned lane: shift out, hold, shift back
/// (planning/shift_line.hpp plan_avoidance). Approval comes `approval_delay` seconds after the module
/// began to wait (planning/avoidance_execution.hpp); until then the ego waits before the shift.
struct AvoidManeuver {
  std::string obstacle;
  double clearance = 1.0;    ///< lateral gap between the ego's side and the obstacle [m]
  std::string side = "auto"; ///< auto (left), left, right
  double length = 0.0;       ///< > 0: each shift is this long [m]; 0: from jerk/accel limits at max_speed
  double approval_delay = 0.0;  ///< [s] after the module began to wait (an operator's RTC approval)
  std::string key;  ///< where it is in the file, "maneuvers[2]" (key_error)
};

/// `maneuvers: [{pull_out: {offset, length, at, backward, engage_delay}}]`: the ego departs `offset` metres beside its lane's
/// centre (the road side; SUMO departPosLat) and shifts back to the centre over `length` metres from
/// base_link's route s `at` (default: its depart position). Only on the first edge.
struct PullOutManeuver {
  double offset = -0.7;  ///< [m], left positive, from the planned lane's centre
  double length = 30.0;  ///< [m]
  double at = -1.0;      ///< [m] route s of base_link; < 0: the depart position (minus `backward`)
  /// > 0: first back up this far along the lane at kBackwardSpeed (emulated: SUMO moves the ego back
  /// with Vehicle::moveTo; the decider sees a negative speed, not driving forward: hazard lights).
  double backward = 0.0;  ///< [m]
  /// [s] after the run's first step the ego is engaged (Autoware's AUTONOMOUS mode); it stands still
  /// until then (planning/pull_out_departure.hpp).
  double engage_delay = 0.0;
  int line = 0;  ///< the scenario file's line of the maneuver (0: unknown)
  std::string key;  ///< where it is in the file, "maneuvers[2]" (key_error)
};
inline constexpr double kBackwardSpeed = 1.0;  ///< [m/s] emulated backing-up speed

/// `maneuvers: [{pull_over: {edge, pos, offset, length}}]`: the ego's goal is a stop at the road side:
/// it shifts from its lane's centre to `offset` over `length` metres, reaching it with the front
/// bumper at lane position `pos` of `edge`, and stops there (jerk-limited stop).
struct PullOverManeuver {
  std::string edge;
  double pos = 0.0;      ///< lane position of the front bumper at the goal [m]
  double offset = -0.7;  ///< [m], left positive, from the planned lane's centre
  double length = 30.0;  ///< [m]
  std::string key;  ///< where it is in the file, "maneuvers[2]" (key_error)
};

/// Every step on a normal lane while a lateral plan is driven, |lateral_offset - planned_offset|
/// stays within `tolerance`.
struct ExpectLateralFollowsPlan {
  double tolerance = 0.2;
};

/// A blinker direction is on continuously from at least `lead` metres (front bumper) before the
/// route enters `junction` (or the lanelet `lanelet`) until base_link leaves it.
struct ExpectBlinkerThrough {
  std::string junction;
  std::string lanelet;
  Blinker blinker = Blinker::Left;
  double lead = 0.0;
};
/// No blinker while the front bumper is within [from_s, to_s].
struct ExpectNoBlinker {
  double from_s = 0.0;
  double to_s = 0.0;
};
/// A blinker value never occurs.
struct ExpectBlinkerNever {
  Blinker blinker = Blinker::Left;
};
/// The blinker is `blinker` at every step with the front bumper within [from_s, to_s].
struct ExpectBlinkerOn {
  Blinker blinker = Blinker::Left;
  double from_s = 0.0;
  double to_s = 0.0;
};
/// The ego comes to rest for light `light` with its front within `tolerance` of the stop point.
struct ExpectStopsBeforeLight {
  std::string light;
  double tolerance = 0.5;
};
/// The ego crosses the stop line of `light` without a stop decision and without coming to rest.
struct ExpectPassesLight {
  std::string light;
};
/// The judge ordered an emergency stop (dilemma zone) at `light`.
struct ExpectEmergencyStopAtLight {
  std::string light;
};
/// The judge was judging `light` and never classified a dilemma zone there nor ordered an
/// emergency stop (docs/behaviour.md §L2.6).
struct ExpectNeverInDilemmaZone {
  std::string light;
};
/// The judge ordered a stop at `light` because V2I predicted red within the horizon (docs/behaviour.md §L1.7).
struct ExpectV2iStopAtLight {
  std::string light;
};
/// The front never crosses a stop line while the ego's link shows red (r or u).
struct ExpectNeverRunsRed {};
/// `arrives: true`: the ego reaches the end of its route within the run's duration.
struct ExpectArrives {};
using Expectation = std::variant<ExpectBlinkerThrough, ExpectNoBlinker, ExpectBlinkerNever, ExpectBlinkerOn,
                                 ExpectStopsBeforeLight, ExpectPassesLight, ExpectEmergencyStopAtLight,
                                 ExpectNeverRunsRed, ExpectLateralFollowsPlan, ExpectArrives,
                                 ExpectNeverInDilemmaZone, ExpectV2iStopAtLight>;

/// One line describing an expectation, e.g. "blinker_through_junction C left lead 30".
std::string describe(const Expectation& e);

/// `fleet:` fleet mode (docs/fleet.md): the reference decider gives every selected vehicle of SUMO's
/// traffic its blinker, under the scenario's country preset. A vehicle is selected when it matches
/// every filter given (none given: every vehicle but the ego).
struct FleetSpec {
  bool enabled = false;
  std::string vtype;       ///< its vType id equals this ("" any)
  std::string vclass;      ///< its vClass equals this ("" any)
  std::string id_pattern;  ///< an ECMAScript regular expression its whole id matches ("" any)
  /// true (`signals: set`): signalsim sets the selected vehicles' signals; false (`signals:
  /// observe`): it decides and compares with SUMO's own blinker, setting nothing.
  bool set_signals = true;
};

/// Changes to a scenario from the command line or a sweep, applied to the YAML before it is read.
struct ScenarioOverrides {
  /// "key=value": a scenario key path (`seed=3`, `ego.max_speed=10`, `country=de`) or a parameter
  /// name (`turn_signal_search_time=2.5`, applied after params.set). Values are YAML scalars.
  /// "key+=value" appends to a list of the scenario (`params.files+=/abs/candidate.yaml`).
  std::vector<std::string> set;
};

struct Scenario {
  std::string path;                     ///< the scenario file
  std::string name;
  std::string description;
  std::string net;                      ///< absolute or relative to the cwd (resolved from the file)
  std::vector<std::string> additional;  ///< resolved like `net`; the sumocfg's first
  SumoInputs sumo;                      ///< `sumocfg:`, `routes:`, `sumo_args:`
  double step_length = 0.1;             ///< [s]
  double duration = 60.0;               ///< simulated seconds at most
  int seed = 1;
  std::string country;                  ///< preset code ("jp"), empty for none
  EgoSpec ego;
  PerceptionModelParameters perception;  ///< `perception:`; seeded with `seed`; all faults off by default
  /// `perception.v2i:` the V2I channel's faults (docs/behaviour.md §L1.7); seeded with `seed`; none by default
  V2iChannelParameters v2i_channel;
  std::map<std::string, double> light_offsets;  ///< `light_offsets: {tls: seconds}` program shifts
  ParameterSet params;                  ///< defaults, params.files, the country, params.set, overrides
  /// `params` typed, made once when they are read: what the run, the report and generate read (the
  /// decider's and the modules' with the ego's footprint: the functions below).
  RunParameters run_params;
  /// Facts about the input that are not errors (unused keys of parameter files, vehicle_info values
  /// replaced by ego keys); printed once each as "signalsim: note: ..." (scenario/notes).
  std::vector<std::string> notes;
  /// What of the input may not do what its author meant (keys Autoware dropped from its parameter
  /// files, a country preset for the other driving side than the net's); printed once each as
  /// "signalsim: warning: ..." and kept in summary.json `notes`.
  std::vector<std::string> warnings;
  /// params.strict (--strict-params): keys of parameter files checked against Autoware's
  bool strict_params = false;
  std::vector<LaneChangeManeuver> lane_changes;   ///< from `maneuvers` (at most one per edge)
  std::vector<ObstacleSpec> obstacles;
  std::vector<AvoidManeuver> avoids;              ///< from `maneuvers`
  std::optional<PullOutManeuver> pull_out;        ///< from `maneuvers` (at most one)
  std::optional<PullOverManeuver> pull_over;      ///< from `maneuvers` (at most one)
  std::vector<Expectation> expect;
  /// `decider:` / `light_judge:` the implementations under test (docs/decider.md); the reference
  /// (signalsim's own) by default, which then decides alone.
  SutSpec decider;
  SutSpec light_judge;
  double sut_timeout = 5.0;       ///< `sut_timeout:` [s] a SUT's answer to one step at most
  FleetSpec fleet;                ///< `fleet:` (off unless given)
  /// false: no `ego:` (only with `fleet:`): SUMO's traffic alone, fleet mode from the first step
  /// (docs/fleet.md "Without an ego"); `ego` then holds its defaults and nothing reads them.
  bool has_ego = true;
  /// Where each key came from: its line, or the --set item that gave it (key_error below).
  KeyOrigins origins;
};

/// The error `reason` about key `key` of the scenario ("ego.route", "obstacles[1].pos",
/// "light_offsets.C"): at that key's line, or at the --set item that gave it (key_origins.hpp).
inline InputError key_error(const Scenario& scenario, const std::string& key, const std::string& reason) {
  return key_error(scenario.path, scenario.origins, key, reason);
}

/// Reads and checks a scenario file. Throws InputError naming the file, line and key for a missing
/// file, malformed YAML, an unknown or missing key, a wrong type or an out-of-range value.
Scenario load_scenario(const std::string& path, const ScenarioOverrides& overrides = {});

/// The decider's parameters for this scenario: run_params.decider with the ego's base_link_to_front.
TurnSignalParameters turn_signal_parameters(const Scenario& scenario);
/// The behaviour modules' parameters for this scenario: run_params.behavior with the decider's shared
/// values and the ego's footprint (its length, base_link_to_front, SUMO's default width kObstacleWidth).
BehaviorSignalParameters behavior_parameters(const Scenario& scenario);

}  // namespace signalsim
