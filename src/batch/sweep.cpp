#include "batch/sweep.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>

#include <yaml-cpp/yaml.h>

#include "batch/sweep_keys.hpp"
#include "sim/behavior_stage.hpp"
#include "scenario/input_error.hpp"
#include "sumo/file_paths.hpp"
#include "report/metrics.hpp"
#include "sim/route_planning.hpp"
#include "scenario/take_over.hpp"
#include "scenario/scenario.hpp"
#include "scenario/yaml_fields.hpp"
#include "sumo/net_index.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// Columns results.csv fills itself: a swept key may not take these names.
const std::vector<std::string>& leading_columns() {
  static const std::vector<std::string> columns = {"run", "scenario", "file"};
  return columns;
}
const std::vector<std::string>& outcome_columns() {
  static const std::vector<std::string> columns = {"status", "expectations_passed", "expectations_total",
                                                   "failed_expectations", "run_dir"};
  return columns;
}
const std::vector<std::string>& trailing_columns() {
  static const std::vector<std::string> columns = {"wall_time", "error"};
  return columns;
}

bool contains(const std::vector<std::string>& list, const std::string& item) {
  return std::find(list.begin(), list.end(), item) != list.end();
}

// A value as the text `--set key=<text>` parses back to the same YAML (flow style for lists).
std::string value_text(const YAML::Node& value, const std::string& file, const std::string& where) {
  if (value.IsScalar()) return value.Scalar();
  if (value.IsSequence()) {
    YAML::Emitter out;
    out << YAML::Flow << value;
    return out.c_str();
  }
  throw InputError(file, yaml_line(value), where + ": expected a value (a number, a text or a list)");
}

SweepAxis read_axis(const std::string& key, const YAML::Node& list, const std::string& file, const std::string& where) {
  const std::string what = where + "." + key;
  if (!list.IsSequence()) throw InputError(file, yaml_line(list), what + ": expected a list of values");
  if (list.size() == 0) throw InputError(file, yaml_line(list), what + ": the list is empty");
  SweepAxis axis;
  axis.key = key;
  for (const YAML::Node& item : list) {
    if (item.IsNull()) throw InputError(file, yaml_line(item), what + ": a value is empty");
    axis.values.push_back(value_text(item, file, what));
    axis.lines.push_back(yaml_line(item) > 0 ? yaml_line(item) : yaml_line(list));
  }
  return axis;
}

void check_key(const std::string& key, const YAML::Node& key_node, const std::string& file, const std::string& where,
               std::set<std::string>& seen) {
  if (key.empty() || key.find('=') != std::string::npos || key.find(' ') != std::string::npos)
    throw InputError(file, yaml_line(key_node), where + ": '" + key + "' is not a key");
  if (contains(leading_columns(), key) || contains(outcome_columns(), key) || contains(trailing_columns(), key))
    throw InputError(file, yaml_line(key_node),
                     where + "." + key + ": '" + key + "' is a results.csv column, not a key to sweep");
  // `params.set.X` and `X` name the same parameter: compare their targets, not their spellings.
  const std::string target = key.rfind("params.set.", 0) == 0 ? key.substr(11) : key;
  if (!seen.insert(target).second)
    throw InputError(file, yaml_line(key_node), where + "." + key + ": the key is swept or set twice");
}

// "key=value" for `--set`: the value as written, quoted when YAML would read it back differently
// (a list given in flow style stays as it is).
std::string set_item(const std::string& key, const std::string& value) {
  YAML::Node node;
  try {
    node = YAML::Load(value);
  } catch (const YAML::Exception&) {
  }
  const bool same = (node.IsScalar() && node.Scalar() == value) || (node.IsSequence() && !value.empty() && value[0] == '[');
  if (same) return key + "=" + value;
  YAML::Emitter out;
  out << YAML::DoubleQuoted << value;
  return key + "=" + out.c_str();
}

std::string joined(const std::vector<std::string>& items, const std::string& separator = ", ") {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : separator) + item;
  return out;
}

// --- what a plot: may show -------------------------------------------------------------------------
// The results.csv columns that hold numbers (see results.csv in README and metrics.hpp's
// flatten_metrics): the run-level metrics and the outcome counts; per section and per light the
// numeric fields. The other fields hold text or true/false, which a heat map cannot show.
const std::vector<std::string>& numeric_run_columns() {
  static const std::vector<std::string> columns = {
      "max_decel",           "max_jerk",           "collisions",         "blinker_events", "flickers", "missed_signals",
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
// red_light_violation and emergency_stop are true/false: tools/plot shows the share of runs where
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

// The plot's x and y: swept keys or `scenario`, and not the same column.
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

std::string describe_values(const RunSpec& run) {
  std::string out = fs::path(run.scenario).filename().string();
  for (const auto& [key, value] : run.values) out += " " + key + "=" + value;
  return out;
}

}  // namespace

std::vector<std::string> scenario_files(const std::vector<std::string>& paths, const std::string& origin, int line) {
  std::vector<std::string> out;
  for (const std::string& path : paths) {
    const std::string where = origin.empty() ? path : origin;
    const int at = origin.empty() ? 0 : line;
    if (fs::is_directory(path)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::directory_iterator(path)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".yaml" || ext == ".yml")) found.push_back(entry.path().string());
      }
      if (found.empty()) throw InputError(where, at, "directory '" + path + "' holds no scenario (*.yaml)");
      std::sort(found.begin(), found.end());
      out.insert(out.end(), found.begin(), found.end());
    } else if (fs::is_regular_file(path)) {
      out.push_back(path);
    } else {
      throw InputError(where, at, "scenario path '" + path + "' not found");
    }
  }
  return out;
}

Sweep load_sweep(const std::string& path) {
  YAML::Node root = load_yaml_file(path, "sweep file");
  if (!root || root.IsNull()) throw InputError(path, 0, "the sweep file is empty");
  YamlFields top(root, path, "", sweep_keys());
  Sweep s;
  s.path = path;
  s.name = top.text_or("name", fs::path(path).stem().string());
  s.description = top.text_or("description", "");

  if (!top.has("scenarios")) throw InputError(path, 0, "missing required key 'scenarios'");
  const YAML::Node scenarios = top.node("scenarios");
  s.scenarios_line = top.line_of("scenarios");
  std::vector<std::string> paths;
  if (scenarios.IsScalar()) {
    paths.push_back(sumo::resolve_beside(path, scenarios.Scalar()));
  } else if (scenarios.IsSequence() && scenarios.size() > 0) {
    for (const YAML::Node& item : scenarios) {
      if (!item.IsScalar()) throw InputError(path, yaml_line(item), "scenarios: expected file or directory paths");
      paths.push_back(sumo::resolve_beside(path, item.Scalar()));
    }
  } else {
    top.fail("scenarios", "expected a path or a non-empty list of scenario files or directories");
  }
  s.scenarios = scenario_files(paths, path, s.scenarios_line);

  std::set<std::string> seen;
  if (top.has("grid")) {
    const YAML::Node grid = top.node("grid");
    s.grid_line = top.line_of("grid");
    if (!grid.IsMap()) top.fail("grid", "expected a mapping of key: [values]");
    if (grid.size() == 0)
      top.fail("grid", "the mapping is empty: it sweeps nothing (give key: [values], or leave grid out)");
    for (const auto& entry : grid) {
      const std::string key = entry.first.Scalar();
      check_key(key, entry.first, path, "grid", seen);
      s.grid.push_back(read_axis(key, entry.second, path, "grid"));
    }
  }
  if (top.has("zip")) {
    const YAML::Node zip = top.node("zip");
    s.zip_line = top.line_of("zip");
    std::vector<YAML::Node> groups;
    if (zip.IsMap()) groups.push_back(zip);
    else if (zip.IsSequence())
      for (const YAML::Node& g : zip) groups.push_back(g);
    else top.fail("zip", "expected a mapping of key: [values] (or a list of such mappings)");
    if (groups.empty())
      top.fail("zip", "the list is empty: it sweeps nothing (give mappings of key: [values], or leave zip out)");
    for (const YAML::Node& group : groups) {
      if (!group.IsMap()) throw InputError(path, yaml_line(group), "zip: expected a mapping of key: [values]");
      if (group.size() == 0)
        throw InputError(path, yaml_line(group),
                         "zip: the mapping is empty: it sweeps nothing (give key: [values], or leave it out)");
      std::vector<SweepAxis> axes;
      for (const auto& entry : group) {
        const std::string key = entry.first.Scalar();
        check_key(key, entry.first, path, "zip", seen);
        axes.push_back(read_axis(key, entry.second, path, "zip"));
        if (axes.back().values.size() != axes.front().values.size())
          throw InputError(path, yaml_line(entry.first),
                           "zip." + key + ": " + std::to_string(axes.back().values.size()) + " values, but zip." +
                               axes.front().key + " has " + std::to_string(axes.front().values.size()) +
                               " (zipped lists go together and need the same length)");
      }
      s.zips.push_back(std::move(axes));
    }
  }
  if (top.has("set")) {
    const YAML::Node set = top.node("set");
    if (!set.IsMap()) top.fail("set", "expected a mapping of key: value");
    for (const auto& entry : set) {
      const std::string key = entry.first.Scalar();
      check_key(key, entry.first, path, "set", seen);
      if (entry.second.IsNull()) throw InputError(path, yaml_line(entry.first), "set." + key + ": the value is empty");
      s.set.push_back(set_item(key, value_text(entry.second, path, "set." + key)));
      s.set_lines.push_back(yaml_line(entry.first));
    }
  }
  if (top.has("timeout")) s.timeout = top.required_number("timeout");
  if (top.has("out")) s.out = sumo::resolve_beside(path, top.text("out"));
  if (top.has("plot")) {
    // One mapping, or a list of them (one picture each).
    const YAML::Node node = top.node("plot");
    std::vector<YAML::Node> items;
    if (node.IsSequence()) {
      if (node.size() == 0) top.fail("plot", "an empty list draws nothing");
      for (const YAML::Node& item : node) items.push_back(item);
    } else {
      items.push_back(node);
    }
    for (const YAML::Node& item : items) {
      YamlFields fields(item, path, "plot", sweep_plot_keys());
      SweepPlot plot;
      plot.metric_line = fields.line_of("metric");  // the line of plot: when a key is not given
      plot.x_line = fields.line_of("x");
      plot.y_line = fields.line_of("y");
      plot.metric = fields.text_or("metric", "");
      plot.x = fields.text_or("x", "");
      plot.y = fields.text_or("y", "");
      fields.finish();
      // Checked here, not by tools/plot after every run finished.
      if (!plot.metric.empty())
        if (const std::string problem = plot_metric_problem(plot.metric); !problem.empty())
          throw InputError(path, plot.metric_line, "plot.metric: " + problem);
      check_plot_axes(s, plot);
      s.plots.push_back(plot);
    }
    s.plot = s.plots.front();
  }
  top.finish();
  return s;
}

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

void check_sweep_plot(const Sweep& sweep, const std::vector<RunSpec>& runs) {
  for (const SweepPlot& plot : sweep.plots) check_plot_metric(sweep, plot, runs);
}

void check_plot_metric(const Sweep& sweep, const SweepPlot& plot, const std::vector<RunSpec>& runs) {
  const std::optional<MetricColumn> column = parse_metric_column(plot.metric);
  if (!column) return;  // empty (tools/plot chooses) or a run-level column every run has
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
  for (const RunSpec& run : runs) {
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
                                                     scenario.params.number("turn_signal_shift_length_threshold")))
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

std::vector<std::string> swept_keys(const Sweep& sweep) {
  std::vector<std::string> keys;
  for (const SweepAxis& a : sweep.grid) keys.push_back(a.key);
  for (const auto& group : sweep.zips)
    for (const SweepAxis& a : group) keys.push_back(a.key);
  return keys;
}

std::vector<RunSpec> expand_sweep(const Sweep& sweep) {
  // Factors: each grid axis, then each zip group; an option is a list of (key, value).
  using Option = std::vector<std::pair<std::string, std::string>>;
  std::vector<std::vector<Option>> factors;
  for (const SweepAxis& a : sweep.grid) {
    std::vector<Option> options;
    for (const std::string& v : a.values) options.push_back({{a.key, v}});
    factors.push_back(std::move(options));
  }
  for (const auto& group : sweep.zips) {
    std::vector<Option> options(group.front().values.size());
    for (std::size_t i = 0; i < options.size(); ++i)
      for (const SweepAxis& a : group) options[i].emplace_back(a.key, a.values[i]);
    factors.push_back(std::move(options));
  }
  double count = static_cast<double>(sweep.scenarios.size());
  for (const auto& options : factors) count *= static_cast<double>(options.size());
  if (count > 1e6)
    throw InputError(sweep.path, sweep.grid_line, "the sweep has " + std::to_string(static_cast<long long>(count)) +
                                                      " runs, more than 1000000");
  std::vector<RunSpec> runs;
  for (const std::string& scenario : sweep.scenarios) {
    std::vector<std::size_t> at(factors.size(), 0);
    while (true) {
      RunSpec run;
      run.index = runs.size();
      run.scenario = scenario;
      run.set = sweep.set;
      for (std::size_t f = 0; f < factors.size(); ++f)
        for (const auto& [key, value] : factors[f][at[f]]) {
          run.values.emplace_back(key, value);
          run.set.push_back(set_item(key, value));
        }
      runs.push_back(std::move(run));
      // Odometer: the last factor turns fastest; done when the first one wraps around.
      std::size_t f = factors.size();
      bool wrapped = true;
      while (f > 0) {
        --f;
        if (++at[f] < factors[f].size()) {
          wrapped = false;
          break;
        }
        at[f] = 0;
      }
      if (wrapped) break;
    }
  }
  return runs;
}

void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs) {
  auto loads = [](const std::string& file, const std::vector<std::string>& set, std::string* error) {
    try {
      (void)load_scenario(file, ScenarioOverrides{set});
      return true;
    } catch (const InputError& e) {
      if (error) *error = e.what();
      return false;
    }
  };
  auto line_of_value = [&](const std::string& key, const std::string& value) {
    for (const SweepAxis& a : sweep.grid)
      if (a.key == key)
        for (std::size_t i = 0; i < a.values.size(); ++i)
          if (a.values[i] == value) return std::make_pair(std::string("grid"), a.lines[i]);
    for (const auto& group : sweep.zips)
      for (const SweepAxis& a : group)
        if (a.key == key)
          for (std::size_t i = 0; i < a.values.size(); ++i)
            if (a.values[i] == value) return std::make_pair(std::string("zip"), a.lines[i]);
    return std::make_pair(std::string("grid"), sweep.grid_line);
  };
  std::set<std::string> good_scenarios;  // scenario files that load with the fixed set alone
  std::set<std::string> good_values;     // "key=value" that load alone (with the fixed set)
  for (RunSpec& run : runs) {
    try {
      run.name = load_scenario(run.scenario, ScenarioOverrides{run.set}).name;
      continue;
    } catch (const InputError& e) {
      // Find what is at fault: the scenario with the fixed set, one value alone, or the combination.
      std::string error = e.what();
      if (!good_scenarios.count(run.scenario)) {
        if (!loads(run.scenario, sweep.set, &error)) {
          const int line = sweep.set.empty() ? sweep.scenarios_line : sweep.set_lines.front();
          throw InputError(sweep.path, line, (sweep.set.empty() ? "scenarios: " : "set: ") + error);
        }
        good_scenarios.insert(run.scenario);
      }
      for (const auto& [key, value] : run.values) {
        const std::string item = key + "=" + value;
        if (good_values.count(run.scenario + "\n" + item)) continue;
        std::vector<std::string> set = sweep.set;
        set.push_back(set_item(key, value));
        if (!loads(run.scenario, set, &error)) {
          const auto [where, line] = line_of_value(key, value);
          throw InputError(sweep.path, line, where + "." + key + ": value " + value + ": " + error);
        }
        good_values.insert(run.scenario + "\n" + item);
      }
      throw InputError(sweep.path, sweep.zips.empty() ? sweep.grid_line : sweep.zip_line,
                       "run " + std::to_string(run.index) + " (" + describe_values(run) + "): " + e.what());
    }
  }
}

std::vector<RunSpec> suite_runs(const std::vector<std::string>& files, const std::vector<std::string>& set) {
  std::vector<RunSpec> runs;
  for (const std::string& file : files) {
    RunSpec run;
    run.index = runs.size();
    run.scenario = file;
    run.set = set;
    try {
      run.name = load_scenario(file, ScenarioOverrides{set}).name;
    } catch (const InputError& e) {
      if (e.file() == "--set") throw;  // the command's own input: every run would fail alike
      run.name = fs::path(file).stem().string();
      run.load_error = e.what();
    } catch (const std::exception& e) {  // a sumocfg the scenario names that does not read, ...
      run.name = fs::path(file).stem().string();
      run.load_error = e.what();
    }
    runs.push_back(std::move(run));
  }
  return runs;
}

// --- results.csv --------------------------------------------------------------------------------

std::vector<std::string> result_columns(const std::vector<std::string>& swept, const ResultRows& rows) {
  std::vector<std::string> columns = leading_columns();
  columns.insert(columns.end(), swept.begin(), swept.end());
  columns.insert(columns.end(), outcome_columns().begin(), outcome_columns().end());
  std::set<std::string> fixed(columns.begin(), columns.end());
  fixed.insert(trailing_columns().begin(), trailing_columns().end());
  std::set<std::string> metric_set;
  for (const auto& [index, row] : rows)
    for (const auto& [column, text] : row.cells)
      if (!fixed.count(column)) metric_set.insert(column);
  std::vector<std::string> metrics(metric_set.begin(), metric_set.end());
  std::stable_sort(metrics.begin(), metrics.end(), metric_column_less);
  columns.insert(columns.end(), metrics.begin(), metrics.end());
  columns.insert(columns.end(), trailing_columns().begin(), trailing_columns().end());
  return columns;
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string results_csv(const std::vector<std::string>& swept, const ResultRows& rows) {
  const std::vector<std::string> columns = result_columns(swept, rows);
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + csv_field(columns[i]);
  out += '\n';
  for (const auto& [index, row] : rows) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i) out += ',';
      if (columns[i] == "run") {
        out += std::to_string(index);
        continue;
      }
      const auto it = row.cells.find(columns[i]);
      if (it != row.cells.end()) out += csv_field(it->second);
    }
    out += '\n';
  }
  return out;
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text) {
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> record;
  std::string field;
  bool quoted = false, any = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += text[++i];
      else if (c == '"') quoted = false;
      else field += c;
      continue;
    }
    if (c == '"') {
      quoted = any = true;
    } else if (c == ',') {
      record.push_back(std::move(field));
      field.clear();
      any = true;
    } else if (c == '\n' || c == '\r') {
      if (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      record.push_back(std::move(field));
      field.clear();
      records.push_back(std::move(record));
      record.clear();
      any = false;
    } else {
      field += c;
      any = true;
    }
  }
  if (any || !field.empty() || !record.empty()) {
    record.push_back(std::move(field));
    records.push_back(std::move(record));
  }
  return records;
}

ResultRows read_results_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const auto records = parse_csv(buffer.str());
  if (records.empty() || records.front().empty() || records.front().front() != "run")
    throw std::runtime_error(path + ": not a results.csv (its first column is not 'run')");
  const auto& header = records.front();
  ResultRows rows;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const auto& record = records[r];
    if (record.size() == 1 && record[0].empty()) continue;
    if (record.size() != header.size())
      throw std::runtime_error(path + ":" + std::to_string(r + 1) + ": " + std::to_string(record.size()) +
                               " fields, the header has " + std::to_string(header.size()));
    ResultRow row;
    try {
      std::size_t used = 0;
      row.run = std::stoul(record[0], &used);
      if (used != record[0].size()) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(r + 1) + ": run '" + record[0] + "' is not a number");
    }
    for (std::size_t i = 1; i < header.size(); ++i)
      if (!record[i].empty()) row.cells[header[i]] = record[i];
    rows[row.run] = std::move(row);
  }
  return rows;
}

bool row_matches(const ResultRow& row, const RunSpec& run) {
  const auto cell = [&](const std::string& column) {
    const auto it = row.cells.find(column);
    return it == row.cells.end() ? std::string() : it->second;
  };
  if (row.run != run.index || cell("file") != run.scenario) return false;
  for (const auto& [key, value] : run.values)
    if (cell(key) != value) return false;
  return true;
}

}  // namespace signalsim
