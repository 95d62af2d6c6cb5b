// What one run recorded: a row per step and an event per change.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "planning/stop/jerk_limited_stop.hpp"
#include "traffic_light/traffic_light_judge.hpp"

#include "scenario/scenario.hpp"
#include "net/sumo_log.hpp"
#include "report/fleet_record.hpp"
#include "session/sumo_session.hpp"
#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

/// [m/s] SUMO's speed after a step this far below the command: something of SUMO's held the ego.
inline constexpr double kSpeedShortfall = 0.01;

struct TimelineRow {
  double time = 0.0;             ///< [s] simulation time of the observation
  double s_front = 0.0;          ///< route position of the front bumper [m]
  double x = 0.0, y = 0.0;       ///< front bumper, net coordinates [m]
  double speed = 0.0;            ///< [m/s]
  double accel = 0.0;            ///< [m/s^2]
  std::string edge, lane;
  double lateral_offset = 0.0;   ///< [m], left positive; from the planned lane's centre while a lateral plan is driven
  /// The lateral plan's offset at base_link [m, left positive, from the centre of the route lane of
  /// the edge]; empty when no plan is driven (no maneuver, or off the plan's edge).
  std::optional<double> planned_offset;
  Blinker blinker = Blinker::None;            ///< what the decider decided
  RequestSource blinker_source = RequestSource::None;
  int sumo_signals = -1;         ///< mask SUMO showed while executing this decision; -1 = gone
  std::string tl_id;             ///< next light ahead on the route, empty when none
  char tl_state = 0;             ///< its true link state for the ego's connection, 0 when none
  std::string tl_observed;       ///< what perception delivered to the judge this step ("" = nothing)
  JudgeDecision tl_decision = JudgeDecision::None;
  JudgeZone zone = JudgeZone::None;
  std::optional<double> stop_distance;  ///< d: front bumper to the stop point [m] while judged
  double judge_distance = 0.0;   ///< jerk-limited stopping distance [m] (docs/behaviour.md §L2.2) while judged
  double yellow_lamp_line = 0.0; ///< v * yellow_lamp_period [m] while judged
  std::optional<double> stop_s;  ///< route s of the stop point while a stop is requested
  std::optional<StopLevel> stop_level;  ///< constraint set used while braking for a stop
  /// "Why did it slow down?" (docs/outputs.md): the speed signalsim commanded for the step and what
  /// set it (empty when SUMO drove); SUMO's speed after the step (the next row's; empty on the last
  /// row) and, when it fell short of the command by more than kSpeedShortfall, what held it:
  /// "leader" (its id and the gap from the front bumper to its rear) or "sumo" (another of SUMO's
  /// rules: its right of way at a junction, its own lane limit).
  std::optional<double> planned_speed;
  std::string speed_limited_by;
  std::optional<double> sumo_speed;
  std::string sumo_limited_by;
  std::string leader;
  std::optional<double> leader_gap;
  /// V2I (docs/behaviour.md §L1.7, only with v2i.use_remaining_time): the judge's V2I rule held this step,
  /// and the predicted time to red of the ego's link in the predictions in force [s] (empty: none).
  bool v2i_stop = false;
  std::optional<double> v2i_time_to_red;
  /// With a decider under test (docs/decider.md): `blinker` is the SUT's (commanded), these are the
  /// reference decider's, run in shadow on the same inputs.
  std::optional<Blinker> ref_blinker;
  RequestSource ref_blinker_source = RequestSource::None;
  /// With a light judge under test: `tl_decision` is the SUT's for the shown light, this the
  /// reference judge's (None when it did not run), and the SUT's reason.
  std::optional<JudgeDecision> ref_tl_decision;
  std::string tl_reason;
};

/// One stop at a light: where the front came to rest against where it should have.
struct LightStop {
  std::string tl_id;
  double time = 0.0;
  double stop_s = 0.0;           ///< the stop point (stop line - stop_margin)
  double rest_s = 0.0;           ///< front bumper at rest
  double error = 0.0;            ///< rest_s - stop_s [m]; > 0 beyond the stop point
  JudgeDecision decision = JudgeDecision::Stop;
  StopLevel worst_level = StopLevel::Normal;
  bool by_judge = true;          ///< false: SUMO stopped on its own (`--driver sumo`); no decision or level
  /// The vehicle the ego came to rest behind, short of its stop point (a queue before the light):
  /// then `error` says where the queue ended, not how well the ego stopped. Empty when nothing was
  /// between the ego and the stop point.
  std::string queued_behind;
  /// The junction before the light the ego waited at (SUMO's right of way there), when it came to
  /// rest on an earlier lanelet than the light's approach: no stop at the light either.
  std::string waiting_at;
};

/// The front crossed a stop line while the ego's link showed red.
struct RedLightViolation {
  std::string tl_id;
  double time = 0.0;
  double s_front = 0.0;
};

/// One lane change as executed (docs/behaviour.md §T8.2): its blinker, its approval and its lateral motion.
struct LaneChangeRecord {
  std::string edge;
  std::string phase;                       ///< the last phase reached (behavior_stage to_string)
  std::optional<double> blinker_on_time;   ///< [s] the module's blinker timestamp at approval
  std::optional<double> approval_time;     ///< [s]
  std::optional<double> approval_s_base;   ///< [m] base_link at approval
  std::optional<double> prepare_duration;  ///< [s] the module's prepare duration at approval
  std::optional<double> start, end;        ///< [m] base_link s of the lateral motion
  double shift = 0.0;                      ///< [m] lateral, left positive
};

/// One lateral motion of a maneuver the metrics measure like a turn (metrics.hpp).
struct ManeuverLine {
  std::string kind;                 ///< "lane_change", "avoidance", "pull_out", "pull_over"
  std::string id;                   ///< the edge it is driven on
  double s_start = 0.0;             ///< [m] base_link s where the lateral motion starts
  double s_end = 0.0;               ///< [m] where it ends
  Blinker blinker = Blinker::None;  ///< the direction of the motion (left: moving left)
};

struct TimelineEvent {
  double time = 0.0;
  double s_front = 0.0;
  std::string kind;              ///< "blinker", "light" or "lane_change" (phases, source = edge)
  std::string from, to;
  std::string source;
};

struct ExpectationResult {
  std::string description;
  bool passed = false;
  std::string detail;            ///< why it failed, or what held
};

/// Which SUMO ran, the ego as it departed there, and what SUMO said (summary.json `sumo`, `ego`).
struct RunSumoInfo {
  sumo::BackendKind backend = sumo::BackendKind::Embedded;
  std::string endpoint;             ///< connect: host:port
  sumo::EgoVehicle ego;             ///< as SUMO had it at departure
  std::vector<std::string> args;    ///< the options passed through (sumo_args, the sumocfg's)
  std::string out_dir;              ///< the run's output directory, where relative outputs landed
  std::string log;                  ///< SUMO's log file, empty when none
  std::vector<std::pair<std::string, std::string>> server_options;  ///< connect: the server's own
  std::vector<std::string> notes;   ///< what of the scenario the back-end did not apply, and why
  sumo::SumoLogCounts log_counts;   ///< counted after SUMO closed
};

/// SUMO's leader of the ego (the stuck rule's reason): the vehicle ahead and the gap to it.
struct LeaderInfo {
  std::string id;
  double gap = 0.0;  ///< [m] ego front bumper to the leader's rear bumper
};

/// Why a run ended before the ego arrived (step/stuck_watch).
struct NotArrived {
  std::string reason;              ///< "stuck" (the stuck rule ended the run), "duration", or
                                   ///< "off_plan" (it ended off the lane plan: step/plan_watch)
  double time = 0.0;               ///< [s] the last row's time
  double s_front = 0.0;            ///< [m] where the front was
  std::string edge, lane;
  double at_rest_for = 0.0;        ///< [s] at rest until the end (0: moving)
  std::string held_by;             ///< what of signalsim held the ego at rest ("" when nothing did)
  std::optional<LeaderInfo> leader;        ///< SUMO's leader of the ego, if any within the look-up range
  std::string junction;            ///< the junction the ego waits in or at when no leader explains it
  std::string detail;              ///< one sentence with all of the above
};

/// Who drove the ego: signalsim's decider, judge and planners, or SUMO on its own (`run --driver sumo`).
enum class Driver { Signalsim, Sumo };
std::string_view to_string(Driver driver);

/// Consecutive steps the ego spent on a lane the lane plan does not list there: another lane of a
/// route edge (SUMO changed lanes, or took another connection) or an internal lane of another
/// connection (step/plan_watch.hpp for a signalsim-driven run).
struct OffPlanStretch {
  std::string lane;          ///< the lane the ego was on
  std::string planned_lane;  ///< the route's lanelet at that position
  double s_from = 0.0;       ///< [m] route s of the front at the first step
  double s_to = 0.0;         ///< [m] at the last step
  int steps = 0;
};

/// One light judged at one step (every light within the judges' window, not only the one the row
/// shows): the metrics give each light on the route its own state at the line and decision.
struct LightObservation {
  std::size_t row = 0;          ///< index into RunRecord::rows
  std::size_t route_index = 0;  ///< the light's approach lanelet
  char state = 0;               ///< true state of the ego's link
  JudgeDecision decision = JudgeDecision::None;  ///< None when the judge did not run
  JudgeZone zone = JudgeZone::None;
};

/// A run without an ego (docs/fleet.md "Without an ego"): how long SUMO's traffic ran.
struct EgolessRun {
  long long steps = 0;      ///< SUMO steps run
  double end_time = 0.0;    ///< [s] SUMO time after the last step
  std::string ended;        ///< "duration" (begin + duration reached) or "no_vehicles" (none left to run)
};

struct RunRecord {
  Driver driver = Driver::Signalsim;
  std::vector<TimelineRow> rows;
  std::vector<TimelineEvent> events;
  std::vector<LightStop> stops;
  std::vector<RedLightViolation> red_violations;
  std::vector<LaneChangeRecord> lane_changes;
  std::vector<ManeuverLine> maneuver_lines;  ///< route order (behavior_stage maneuver_lines)
  bool arrived = false;          ///< the ego reached the end of its route
  std::optional<NotArrived> not_arrived;  ///< why not, when it did not
  int off_route_steps = 0;       ///< steps on a lane not on the planned route (route position held)
  std::vector<OffPlanStretch> off_plan;  ///< stretches off the planned lanes
  std::vector<LightObservation> light_log;  ///< signalsim-driven runs: every light judged, per step
  int collisions = 0;
  double base_link_to_front = 0.0;
  bool v2i = false;  ///< v2i.use_remaining_time: timeline.csv gets its v2i_time_to_red column
  /// The implementations under test (docs/decider.md), as named; "" when the reference decided.
  std::string decider_sut, light_judge_sut;
  RunSumoInfo sumo;
  /// Fleet mode's record (docs/fleet.md); empty when it is off.
  std::optional<FleetRecord> fleet;
  /// Set only for a run without an ego (its rows and events are then empty).
  std::optional<EgolessRun> egoless;
};

}  // namespace signalsim
