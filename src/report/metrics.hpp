// Metrics every run reports: how well the blinker served each turn, roundabout entry/exit and
// maneuver on the route, what happened at each light, and the ride (deceleration, jerk, collisions).
//
// Computed from what the run recorded (RunRecord) and the route (RouteMap), never from SUMO:
//
//   sections  the route's signal sections, in route order:
//               turn              consecutive turn lanelets with the same left/right direction
//                                 (a left turn's two chained internal lanes are one section),
//                                 outside roundabouts; the expected blinker is the direction
//               roundabout_entry  an entry lanelet; expected blinker turn_signal_roundabout_on_entry,
//                                 or left/right when the entry's exit_turn_signal_left/right lists
//                                 the exit lanelet the route takes (spec TSD §5.2)
//               roundabout_exit   an exit lanelet; expected blinker turn_signal_roundabout_on_exit
//               lane_change,      a maneuver's lateral motion (RunRecord::maneuver_lines): from the
//               avoidance,        front bumper where base_link starts it until base_link ends it; the
//               pull_out,         expected blinker is the direction of the motion. A lane change's
//               pull_over         lead_time is its blinker's lead over the lateral motion (the
//                                 prepare time, spec TSD §8.2). Sorted with the others by start.
//   for each  the serving stretch of the expected blinker: the one on at the last step before the
//               front reached s_start, else at the step it reached it, else the first one that began
//               later while base_link was still in the section (a late blinker)
//                 lead_distance = s_start - s_front where the stretch began (< 0: late)
//                 lead_time     = time the front reached s_start - time it began (< 0: late)
//                 time_on       = how long the stretch lasted (0 when there is none)
//               missed = the blinker was not on when the front reached s_start (within that step)
//             flickers = blinker states shorter than 1 s (changes on both sides) that began between
//               the previous section's end and this one's end (front bumper, plus base_link_to_front)
//   lights    every signalised approach on the route (stop line = approach lane end - stopOffset),
//             from the rows between the previous light's stop line and this one's:
//               state_at_line        the ego link's state as the front crossed the stop line
//               red_light_violation  crossed at r/u (or the run recorded a violation there)
//               decision             the judge's most restrictive decision on the approach
//                                    (emergency_stop > stop > pass); null when it never engaged
//               zone                 the pass judge's zone when that decision was first taken, else the
//                                    last zone it gave (e.g. pass_through_yellow)
//               emergency_stop       the decision was emergency_stop
//               stop_position_error  the recorded stop at this light: rest position - stop point
//   run       max deceleration, max jerk (from the timeline's accel), collisions, blinker events,
//             flickers, missed signals, red-light violations.
//
// Values are rounded to 1 mm / 1 ms so the JSON is byte-stable. A metric that does not apply
// (a section never reached, no lead when no blinker served the section) is null.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "map/route_map.hpp"
#include "scenario/scenario.hpp"
#include "report/timeline.hpp"

namespace signalsim {

/// A stretch of the route that asks for a blinker.
struct SignalSection {
  std::string kind;                   ///< "turn", "roundabout_entry", "roundabout_exit", or a maneuver kind
  std::string id;                     ///< junction id (turns, roundabouts), else the first lane id
  Blinker blinker = Blinker::None;    ///< the blinker the section asks for (None: it asks for none)
  double s_start = 0.0;               ///< route s where the section starts [m]
  double s_end = 0.0;                 ///< route s where it ends [m]
  std::vector<std::string> lanelets;  ///< lane ids, in route order
};

/// The route's signal sections in route order. `params` gives the roundabout on_entry/on_exit.
std::vector<SignalSection> signal_sections(const RouteMap& route, const ParameterSet& params);

struct SectionMetrics {
  SignalSection section;
  bool reached = false;                  ///< the front got to the section start
  std::optional<double> lead_distance;   ///< [m] blinker on before the start (front bumper); < 0 late
  std::optional<double> lead_time;       ///< [s]; < 0 late
  std::optional<double> time_on;         ///< [s] length of the blinker stretch serving the section
  int flickers = 0;                      ///< blinker states shorter than 1 s near the section
  std::optional<bool> missed;            ///< the blinker was not on when the front reached the start
};

struct LightMetrics {
  std::string id;                          ///< tls id
  int link_index = -1;                     ///< the ego's link
  double stop_line_s = 0.0;                ///< route s of the stop line [m]
  bool reached = false;                    ///< the front crossed the stop line
  std::string state_at_line;               ///< link state (r, y, g, G, ...) as the front crossed; "" unknown
  std::optional<bool> red_light_violation; ///< crossed while the link showed r or u
  std::optional<double> stop_position_error;  ///< [m] rest position minus stop point; > 0 beyond it
  std::optional<std::string> decision;     ///< most restrictive judge decision: pass, stop, emergency_stop
  std::optional<std::string> zone;         ///< stoppable, optional_zone, dilemma_zone, pass_through_yellow, slow
  std::optional<bool> emergency_stop;      ///< the judge ordered an emergency stop here
};

struct RunMetrics {
  double max_decel = 0.0;          ///< [m/s^2] largest deceleration (>= 0)
  double max_jerk = 0.0;           ///< [m/s^3] largest |d accel / dt| between consecutive steps
  int collisions = 0;
  int blinker_events = 0;
  int flickers = 0;                ///< over the whole run
  int missed_signals = 0;          ///< sections reached whose blinker was missed
  int red_light_violations = 0;
  std::vector<SectionMetrics> sections;
  std::vector<LightMetrics> lights;
};

/// Shorter than this a blinker state counts as a flicker [s].
inline constexpr double kFlickerSeconds = 1.0;

RunMetrics compute_metrics(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

/// The "metrics" object of summary.json.
nlohmann::ordered_json to_json(const RunMetrics& metrics);
nlohmann::ordered_json metrics_json(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

/// One results.csv cell per scalar: run-level keys as they are ("max_decel"), section fields as
/// "<kind><n>.<field>" (n counts sections of that kind from 1: "turn1.lead_distance",
/// "roundabout_exit1.missed"), light fields as "light<n>.<field>". Nulls are left out; numbers use
/// the JSON text, booleans true/false.
std::vector<std::pair<std::string, std::string>> flatten_metrics(const nlohmann::ordered_json& metrics);

/// A fixed order of flattened metric columns, independent of which runs have which: run-level
/// keys first, then turns, roundabout entries, exits, other sections, lights; by number, then field.
bool metric_column_less(const std::string& a, const std::string& b);

}  // namespace signalsim
