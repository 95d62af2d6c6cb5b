// Putting a run's metrics together: the ride, the sections, the lights; and their JSON (see metrics.hpp).
#include "report/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "report/outputs.hpp"
#include "core/number_text.hpp"

namespace signalsim {
namespace {

// Nearest-rank percentile: the smallest value with at least p % of the values at or below it; 0 of none.
double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p / 100.0 * static_cast<double>(values.size())));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

}  // namespace

std::vector<SignalSection> run_signal_sections(const Scenario& scenario, const RouteMap& route, const RunRecord& record) {
  std::vector<SignalSection> sections = signal_sections(route, scenario.run_params.decider);
  for (const ManeuverLine& line : record.maneuver_lines)
    sections.push_back({line.kind, line.id, line.blinker, line.s_start + record.base_link_to_front, line.s_end, {}});
  std::stable_sort(sections.begin(), sections.end(),
                   [](const SignalSection& a, const SignalSection& b) { return a.s_start < b.s_start; });
  return sections;
}

RunMetrics compute_metrics(const Scenario& scenario, const RouteMap& route, const RunRecord& record) {
  RunMetrics m;
  const auto& rows = record.rows;
  // The acceleration as timeline.csv has it, so that metrics recomputed from the files (batch's
  // fallback) are the run's own: the jerk divides its rounding by the step.
  const auto written = [](double v) { return as_written(v, 3); };
  // The ride while moving: a row whose step had the ego moving at its start or its end (not a
  // rest); the jerk between two consecutive such rows.
  const auto moving = [&](std::size_t i) { return rows[i].speed > kRideRestSpeed || written(rows[i].accel) != 0.0; };
  double min_accel = 0.0, max_jerk = 0.0;
  std::vector<double> decels, jerks;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    min_accel = std::min(min_accel, written(rows[i].accel));
    if (moving(i)) decels.push_back(std::max(0.0, -written(rows[i].accel)));
    if (i == 0 || !(rows[i].time > rows[i - 1].time)) continue;
    const double jerk = std::abs(written(rows[i].accel) - written(rows[i - 1].accel)) / (rows[i].time - rows[i - 1].time);
    max_jerk = std::max(max_jerk, jerk);
    if (moving(i) && moving(i - 1)) jerks.push_back(jerk);
  }
  m.max_decel = rounded(-min_accel, 3);
  m.max_jerk = rounded(max_jerk, 3);
  m.p95_decel = rounded(percentile(std::move(decels), 95.0), 3);
  m.p95_jerk = rounded(percentile(std::move(jerks), 95.0), 3);
  m.collisions = record.collisions;
  m.blinker_events = static_cast<int>(std::count_if(record.events.begin(), record.events.end(),
                                                    [](const TimelineEvent& e) { return e.kind == "blinker"; }));
  m.flickers = count_flickers(rows, scenario.step_length);

  m.sections = measure_sections(run_signal_sections(scenario, route, record), record, scenario.step_length);
  for (const SectionMetrics& s : m.sections) m.missed_signals += s.missed.value_or(false);
  m.lights = measure_lights(route, record);
  for (const LightMetrics& l : m.lights) m.red_light_violations += l.red_light_violation.value_or(false);
  return m;
}

nlohmann::ordered_json to_json(const RunMetrics& m) {
  nlohmann::ordered_json out;
  out["max_decel"] = m.max_decel;
  out["max_jerk"] = m.max_jerk;
  out["p95_decel"] = m.p95_decel;
  out["p95_jerk"] = m.p95_jerk;
  out["collisions"] = m.collisions;
  out["blinker_events"] = m.blinker_events;
  out["flickers"] = m.flickers;
  out["missed_signals"] = m.missed_signals;
  out["red_light_violations"] = m.red_light_violations;
  nlohmann::ordered_json sections = nlohmann::ordered_json::array();
  for (const SectionMetrics& s : m.sections) {
    nlohmann::ordered_json j;
    j["kind"] = s.section.kind;
    j["id"] = s.section.id;
    j["blinker"] = to_string(s.section.blinker);
    j["s_start"] = rounded(s.section.s_start, 3);
    j["s_end"] = rounded(s.section.s_end, 3);
    j["lanelets"] = s.section.lanelets;
    j["reached"] = s.reached;
    j["blinker_at_start"] = s.blinker_at_start ? nlohmann::ordered_json(to_string(*s.blinker_at_start)) : nullptr;
    j["lead_distance"] = optional_json(s.lead_distance);
    j["lead_time"] = optional_json(s.lead_time);
    j["time_on"] = optional_json(s.time_on);
    j["flickers"] = s.flickers;
    j["missed"] = optional_json(s.missed);
    sections.push_back(std::move(j));
  }
  out["sections"] = std::move(sections);
  nlohmann::ordered_json lights = nlohmann::ordered_json::array();
  for (const LightMetrics& l : m.lights) {
    nlohmann::ordered_json j;
    j["id"] = l.id;
    j["link_index"] = l.link_index;
    j["stop_line_s"] = l.stop_line_s;
    j["reached"] = l.reached;
    j["state_at_line"] = l.state_at_line;
    j["red_light_violation"] = optional_json(l.red_light_violation);
    j["stop_position_error"] = optional_json(l.stop_position_error);
    j["decision"] = optional_json(l.decision);
    j["zone"] = optional_json(l.zone);
    j["emergency_stop"] = optional_json(l.emergency_stop);
    lights.push_back(std::move(j));
  }
  out["lights"] = std::move(lights);
  return out;
}

nlohmann::ordered_json metrics_json(const Scenario& scenario, const RouteMap& route, const RunRecord& record) {
  return to_json(compute_metrics(scenario, route, record));
}

}  // namespace signalsim
