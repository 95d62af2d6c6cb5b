// Checking a sweep's plot: before any run: the metric's column, the axes, a route that has the
// metric's section or light (see sweep_plot_check.hpp).
#include "batch/sweep_plot_check.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <memory>
#include <optional>

#include "batch/interrupt_guard.hpp"
#include "batch/sweep_check.hpp"
#include "report/metrics.hpp"
#include "scenario/input_error.hpp"
#include "scenario/scenario.hpp"
#include "scenario/take_over.hpp"
#include "step/behavior_stage.hpp"
#include "step/route_planning.hpp"
#include "net/net_index.hpp"

namespace signalsim {
namespace {

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// --- what a plot: may show -------------------------------------------------------------------------
// The results.csv columns that hold numbers (see results.csv in docs/outputs.md and metric_columns.hpp's
// flatten_metrics): the run-level metrics and the outcome counts; per section and per light the
// numeric fields. The other fields hold text or true/false, which a heat map cannot show.
const std::vector<std::string>& numeric_run_columns() {
  static const std::vector<std::string> columns = {
      "max_decel",           "max_jerk",           "p95_decel",          "p95_jerk",       "collisions",
      "blinker_events",      "flickers",           "missed_signals",
      "red_light_violations", "expectations_passed", "expectations_total", "wall_time"};
  return columns;
}
const std::vector<std::string>& section_kinds() {  // SignalSection::kind
  static const std::vector<std::string> kinds = {"turn",      "roundabout_entry", "roundabout_exit", "lane_change",
                                                 "avoidance", "pull_out",         "pull_over"};
  return kinds;
}
const std::vector<std::string>& numeric_section_fields() {
  static const std::vector<std::string> fields = {"lead_distance", "lead_time", "time_on", "flickers"};
  return fields;
}
const std::vector<std::string>& other_section_fields() {
  static const std::vector<std::string> fields = {"id", "blinker", "missed"};
  return fields;
}
// red_light_violation and emergency_stop are true/false: signalsim-plot shows the share of runs where
// they are true (the outcome rates of a perception-fault sweep).
const std::vector<std::string>& numeric_light_fields() {
  static const std::vector<std::string> fields = {"stop_position_error", "red_light_violation", "emergency_stop"};
  return fields;
}
const std::vector<std::string>& other_light_fields() {
  static const std::vector<std::string> fields = {"id", "state_at_line", "decision", "zone"};
  return fields;
}

// "<kind><n>.<field>" (n from 1, no leading zero), as flatten_metrics names section and light cells.
struct MetricColumn {
  std::string kind;
  int number = 0;
  std::string field;
};
std::optional<MetricColumn> parse_metric_column(const std::string& column) {
  const auto dot = column.find('.');
  if (dot == std::string::npos || dot == 0) return std::nullopt;
  const std::string item = column.substr(0, dot);
  std::size_t digits = item.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(item[digits - 1]))) --digits;
  const std::string number = item.substr(digits);
  if (digits == 0 || number.empty() || number[0] == '0' || number.size() > 6) return std::nullopt;
  return MetricColumn{item.substr(0, digits), std::stoi(number), column.substr(dot + 1)};
}

std::string numeric_columns_text() {
  return "numeric columns: " + joined(numeric_run_columns()) + "; <kind><n>." + joined(numeric_section_fields(), "|") +
         " with kind " + joined(section_kinds()) + "; light<n>." + joined(numeric_light_fields(), "|");
}

}  // namespace

std::string plot_metric_problem(const std::string& metric) {
  if (contains(numeric_run_columns(), metric)) return "";
  const std::optional<MetricColumn> column = parse_metric_column(metric);
  if (!column) return "'" + metric + "' is not a results.csv metric column (" + numeric_columns_text() + ")";
  const bool light = column->kind == "light";
  if (!light && !contains(section_kinds(), column->kind))
    return "'" + column->kind + "' in '" + metric + "' is not a section kind or light (" + joined(section_kinds()) +
           ", light)";
  const auto& numeric = light ? numeric_light_fields() : numeric_section_fields();
  if (contains(numeric, column->field)) return "";
  const std::string fields = joined(numeric, ", ");
  if (contains(light ? other_light_fields() : other_section_fields(), column->field))
    return "'" + metric + "' holds text or true/false, not numbers: a heat map cannot show it (numeric fields of " +
           column->kind + "<n>: " + fields + ")";
  return "'" + column->field + "' in '" + metric + "' is not a field of " + column->kind + "<n> (numeric fields: " +
         fields + ")";
}

void check_plot_axes(const Sweep& s, const SweepPlot& plot) {
  const std::vector<std::string> keys = swept_keys(s);
  const auto check = [&](const char* name, const std::string& column, int line) {
    if (column.empty() || column == "scenario" || contains(keys, column)) return;
    const std::string choices =
        keys.empty() ? std::string("nothing is swept: only scenario") : "swept: " + joined(keys) + "; or scenario";
    throw InputError(s.path, line, std::string("plot.") + name + ": '" + column + "' is not a swept key (" + choices + ")");
  };
  check("x", plot.x, plot.x_line);
  check("y", plot.y, plot.y_line);
  const std::string x = !plot.x.empty() ? plot.x : keys.empty() ? std::string("scenario") : keys.front();
  if (!plot.y.empty() && plot.y == x)
    throw InputError(s.path, plot.y_line,
                     "plot.y: '" + x + "' is the x axis too" +
                         (plot.x.empty() ? " (x defaults to the first swept key; give plot.x)" : "") +
                         ": x and y must differ");
}

void check_sweep_plot(const SweepRuns& runs) {
  for (const SweepPlot& plot : runs.sweep().plots) check_plot_metric(plot, runs);
}

void check_plot_metric(const SweepPlot& plot, const SweepRuns& runs) {
  const Sweep& sweep = runs.sweep();
  const std::optional<MetricColumn> column = parse_metric_column(plot.metric);
  if (!column) return;  // empty (signalsim-plot chooses) or a run-level column every run has
  // Sections and lights per route, from the same code that computes the metrics (an empty record:
  // the route's sections and lights, no values). Maneuver sections belong to each run's scenario
  // and overrides (maneuvers, depart lane, shift threshold), so they are counted per run.
  struct RouteCounts {
    sumo::RoutePlan plan;
    std::map<std::string, int> counts;
  };
  std::map<std::string, std::shared_ptr<const sumo::NetIndex>> nets;
  std::map<std::string, RouteCounts> by_route;
  std::map<std::string, int> most;
  bool planned = false;
  for (std::size_t index = 0; index < runs.size(); ++index) {
    if (index == kCombinationsChecked) return;  // a huge sweep: undecided, not refused
    InterruptGuard::throw_if_interrupted();
    const RunSpec run = runs.at(index);
    try {
      Scenario scenario = load_scenario(run.scenario, ScenarioOverrides{run.set});
      resolve_route_file_ego(scenario);  // a taken-over vehicle's route is in the route files
      std::string key = scenario.net;
      for (const std::string& edge : scenario.ego.route) key += "\n" + edge;
      for (const int lane : required_exit_lanes(scenario)) key += "\n" + std::to_string(lane);
      auto& net = nets[scenario.net];
      if (!net) net = std::make_shared<const sumo::NetIndex>(sumo::NetIndex::load(scenario.net));
      auto [route, fresh] = by_route.try_emplace(key);
      if (fresh) {
        route->second.plan = plan_route(scenario, *net);
        const RunMetrics metrics = compute_metrics(scenario, route->second.plan.map, RunRecord{});
        for (const SectionMetrics& section : metrics.sections) ++route->second.counts[section.section.kind];
        route->second.counts["light"] = static_cast<int>(metrics.lights.size());
      }
      std::map<std::string, int> counts = route->second.counts;
      for (const ManeuverLine& line : maneuver_lines(plan_lateral(scenario, route->second.plan, *net), {},
                                                     scenario.run_params.decider.turn_signal_shift_length_threshold))
        ++counts[line.kind];
      for (const auto& [kind, n] : counts) most[kind] = std::max(most[kind], n);
      planned = true;
      const auto it = counts.find(column->kind);
      if (it != counts.end() && it->second >= column->number) return;
    } catch (const std::exception&) {
      // A route the net cannot drive: the run reports it as its own error.
    }
  }
  if (!planned) return;
  std::vector<std::string> have;
  for (const std::string& kind : section_kinds())  // the kinds some route has
    if (most[kind] > 0) have.push_back(std::to_string(most[kind]) + " " + kind);
  have.push_back(std::to_string(most["light"]) + " light");
  throw InputError(sweep.path, plot.metric_line,
                   "plot.metric: no run's route has a " + column->kind + std::to_string(column->number) +
                       ", so no run can give '" + plot.metric + "' (the most any route has: " + joined(have) +
                       ")");
}

}  // namespace signalsim
