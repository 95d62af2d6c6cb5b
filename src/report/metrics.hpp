// Metrics every run reports: how well the blinker served each turn, roundabout entry/exit and
// maneuver on the route, what happened at each light, and the ride (deceleration, jerk, collisions).
// This file puts them together into RunMetrics and summary.json's "metrics" object; each part
// has its own file:
//
//   sections  signal_sections.hpp: the route's turns and roundabout entries/exits; the run adds its
//             maneuvers' lateral motions (RunRecord::maneuver_lines: lane_change, avoidance,
//             pull_out, pull_over, from the front bumper where base_link starts the motion until
//             base_link ends it; the expected blinker is the direction of the motion), all sorted
//             by start.
//             section_metrics.hpp: lead distance / time, time on, missed, flickers of each.
//   lights    light_metrics.hpp: state at the line, red-light violation, the judge's decision and
//             zone, emergency stop, stop position error of each signalised approach.
//   run       max deceleration, max jerk (from the timeline's accel), their 95th percentiles while
//             moving, collisions, blinker events, flickers, missed signals, red-light violations.
//   columns   metric_columns.hpp: the metrics as results.csv cells and their order.
//
// Computed from what the run recorded (RunRecord) and the route (RouteMap), never from SUMO.
// Values are rounded to 1 mm / 1 ms so the JSON is byte-stable. A metric that does not apply
// (a section never reached, no lead when no blinker served the section) is null.
#pragma once

#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "map/route_map.hpp"
#include "report/light_metrics.hpp"
#include "report/section_metrics.hpp"
#include "report/signal_sections.hpp"
#include "report/timeline.hpp"
#include "scenario/scenario.hpp"

namespace signalsim {

/// A value of summary.json that may be absent: the value, or null.
template <typename T>
nlohmann::ordered_json optional_json(const std::optional<T>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

/// [m/s] Below this speed with no acceleration, a row is at rest (the percentiles leave it out).
inline constexpr double kRideRestSpeed = 0.01;

struct RunMetrics {
  double max_decel = 0.0;          ///< [m/s^2] largest deceleration (>= 0)
  double max_jerk = 0.0;           ///< [m/s^3] largest |d accel / dt| between consecutive steps
  double p95_decel = 0.0;          ///< [m/s^2] 95th percentile (nearest rank) of the deceleration while moving
  double p95_jerk = 0.0;           ///< [m/s^3] 95th percentile of |d accel / dt| between rows while moving
  int collisions = 0;
  int blinker_events = 0;
  int flickers = 0;                ///< over the whole run
  int missed_signals = 0;          ///< sections reached whose blinker was missed
  int red_light_violations = 0;
  std::vector<SectionMetrics> sections;
  std::vector<LightMetrics> lights;
};

/// The sections a run is measured on: the route's (signal_sections) and its maneuvers' lateral
/// motions (front bumper at base_link's start), sorted by start.
std::vector<SignalSection> run_signal_sections(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

RunMetrics compute_metrics(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

/// The "metrics" object of summary.json.
nlohmann::ordered_json to_json(const RunMetrics& metrics);
nlohmann::ordered_json metrics_json(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

}  // namespace signalsim
