// Reading a sweep file into a Sweep, with every error at its file and line (see sweep_file.hpp).
#include "batch/sweep_file.hpp"
#include "batch/sweep_keys.hpp"

#include <filesystem>
#include <set>

#include <yaml-cpp/yaml.h>

#include "batch/results_table.hpp"
#include "batch/scenario_files.hpp"
#include "batch/sweep_plot_check.hpp"
#include "scenario/input_error.hpp"
#include "scenario/sut_spec.hpp"
#include "scenario/utf8_text.hpp"
#include "scenario/yaml_fields.hpp"
#include "core/file_paths.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

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

bool is_sut_key(const std::string& key) { return key == "decider" || key == "light_judge"; }

// A swept or set decider / light judge: a name signalsim knows (a lib: path relative to the sweep file).
void check_sut_value(const std::string& key, const std::string& value, const std::string& file, int line,
                     const std::string& where) {
  if (!is_sut_key(key)) return;
  SutSpec spec;
  std::string reason = parse_sut_spec(value, fs::path(file).parent_path().string(), spec);
  if (reason.empty() && key == "light_judge" && spec.kind == SutSpec::Kind::AutowareCore)
    reason = "autoware_core is a decider (its path_generator has no traffic-light judge)";
  if (!reason.empty()) throw InputError(file, line, where + "." + key + ": " + reason);
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
    check_sut_value(key, axis.values.back(), file, axis.lines.back(), where);
  }
  return axis;
}

void check_key(const std::string& key, const YAML::Node& key_node, const std::string& file, const std::string& where,
               std::set<std::string>& seen) {
  if (key.empty() || key.find('=') != std::string::npos || key.find(' ') != std::string::npos)
    throw InputError(file, yaml_line(key_node), where + ": '" + key + "' is not a key");
  if (is_fixed_result_column(key))
    throw InputError(file, yaml_line(key_node),
                     where + "." + key + ": '" + key + "' is a results.csv column, not a key to sweep");
  // `params.set.X` and `X` name the same parameter: compare their targets, not their spellings.
  const std::string target = key.rfind("params.set.", 0) == 0 ? key.substr(11) : key;
  if (!seen.insert(target).second)
    throw InputError(file, yaml_line(key_node), where + "." + key + ": the key is swept or set twice");
}

std::vector<std::string> read_scenarios(const YamlFields& top, const std::string& path) {
  if (!top.has("scenarios")) throw InputError(path, 0, "missing required key 'scenarios'");
  const YAML::Node scenarios = top.node("scenarios");
  std::vector<std::string> paths;
  if (scenarios.IsScalar()) {
    paths.push_back(resolve_beside(path, scenarios.Scalar()));
  } else if (scenarios.IsSequence() && scenarios.size() > 0) {
    for (const YAML::Node& item : scenarios) {
      if (!item.IsScalar()) throw InputError(path, yaml_line(item), "scenarios: expected file or directory paths");
      paths.push_back(resolve_beside(path, item.Scalar()));
    }
  } else {
    top.fail("scenarios", "expected a path or a non-empty list of scenario files or directories");
  }
  return scenario_files(paths, path, top.line_of("scenarios"));
}

std::vector<SweepAxis> read_grid(const YamlFields& top, const std::string& path, std::set<std::string>& seen) {
  const YAML::Node grid = top.node("grid");
  if (!grid.IsMap()) top.fail("grid", "expected a mapping of key: [values]");
  if (grid.size() == 0) top.fail("grid", "the mapping is empty: it sweeps nothing (give key: [values], or leave grid out)");
  std::vector<SweepAxis> axes;
  for (const auto& entry : grid) {
    const std::string key = entry.first.Scalar();
    check_key(key, entry.first, path, "grid", seen);
    axes.push_back(read_axis(key, entry.second, path, "grid"));
  }
  return axes;
}

std::vector<std::vector<SweepAxis>> read_zips(const YamlFields& top, const std::string& path,
                                              std::set<std::string>& seen) {
  const YAML::Node zip = top.node("zip");
  std::vector<YAML::Node> groups;
  if (zip.IsMap()) groups.push_back(zip);
  else if (zip.IsSequence())
    for (const YAML::Node& g : zip) groups.push_back(g);
  else top.fail("zip", "expected a mapping of key: [values] (or a list of such mappings)");
  if (groups.empty())
    top.fail("zip", "the list is empty: it sweeps nothing (give mappings of key: [values], or leave zip out)");
  std::vector<std::vector<SweepAxis>> zips;
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
    zips.push_back(std::move(axes));
  }
  return zips;
}

void read_set(const YamlFields& top, const std::string& path, std::set<std::string>& seen, Sweep& s) {
  const YAML::Node set = top.node("set");
  if (!set.IsMap()) top.fail("set", "expected a mapping of key: value");
  for (const auto& entry : set) {
    const std::string key = entry.first.Scalar();
    check_key(key, entry.first, path, "set", seen);
    if (entry.second.IsNull()) throw InputError(path, yaml_line(entry.first), "set." + key + ": the value is empty");
    const std::string value = value_text(entry.second, path, "set." + key);
    check_sut_value(key, value, path, yaml_line(entry.second), "set");
    s.set.push_back(sweep_set_argument(s, key, value));
    s.set_lines.push_back(yaml_line(entry.first));
  }
}

// plot: one mapping, or a list of them (one picture each). Checked here, not by signalsim-plot after
// every run finished; needs the swept keys read already.
std::vector<SweepPlot> read_plots(const YamlFields& top, const std::string& path, const Sweep& s) {
  const YAML::Node node = top.node("plot");
  std::vector<YAML::Node> items;
  if (node.IsSequence()) {
    if (node.size() == 0) top.fail("plot", "an empty list draws nothing");
    for (const YAML::Node& item : node) items.push_back(item);
  } else {
    items.push_back(node);
  }
  std::vector<SweepPlot> plots;
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
    if (!plot.metric.empty())
      if (const std::string problem = plot_metric_problem(plot.metric); !problem.empty())
        throw InputError(path, plot.metric_line, "plot.metric: " + problem);
    check_plot_axes(s, plot);
    plots.push_back(plot);
  }
  return plots;
}

}  // namespace

Sweep load_sweep(const std::string& path) {
  YAML::Node root = load_yaml_file(path, "sweep file");
  if (!root || root.IsNull()) throw InputError(path, 0, "the sweep file is empty");
  YamlFields top(root, path, "", sweep_keys());
  Sweep s;
  s.path = path;  // first: read_set's sweep_set_argument resolves beside it
  s.name = top.text_or("name", fs::path(path).stem().string());
  if (const std::string problem = name_problem(s.name, true); !problem.empty()) {
    if (top.has("name")) top.fail("name", problem);
    throw InputError(path, 0, "the file's name gives the sweep's name: " + problem);
  }
  s.description = top.text_or("description", "");
  s.scenarios = read_scenarios(top, path);
  s.scenarios_line = top.line_of("scenarios");

  std::set<std::string> seen;  // keys of grid, zip and set, by the parameter they name
  if (top.has("grid")) {
    s.grid_line = top.line_of("grid");
    s.grid = read_grid(top, path, seen);
  }
  if (top.has("zip")) {
    s.zip_line = top.line_of("zip");
    s.zips = read_zips(top, path, seen);
  }
  if (top.has("set")) read_set(top, path, seen, s);
  if (top.has("timeout")) s.timeout = top.required_number("timeout");
  if (top.has("out")) s.out = resolve_beside(path, top.text("out"));
  if (top.has("plot")) {
    s.plots = read_plots(top, path, s);
    s.plot = s.plots.front();
  }
  top.finish();
  return s;
}

std::vector<std::string> swept_keys(const Sweep& sweep) {
  std::vector<std::string> keys;
  for (const SweepAxis& a : sweep.grid) keys.push_back(a.key);
  for (const auto& group : sweep.zips)
    for (const SweepAxis& a : group) keys.push_back(a.key);
  return keys;
}

std::string sweep_set_argument(const Sweep& sweep, const std::string& key, const std::string& value) {
  if (is_sut_key(key)) return sut_override(key, value, fs::path(sweep.path).parent_path().string());
  return set_argument(key, value);
}

std::string set_argument(const std::string& key, const std::string& value) {
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

}  // namespace signalsim
