// Sweep files: reading and checking one into a Sweep (a grid of runs over scenarios and `--set`
// values). The runs it makes: run_list.hpp; its plot: checks: sweep_plot_check.hpp.
//
// A sweep file (YAML; paths relative to the file):
//
//   name: exit_blinker_by_country          # optional; description: optional
//   scenarios: [../scenarios/close_turns.yaml, ../scenarios]   # files, or directories (their *.yaml)
//   grid:                                  # cartesian product, first key varies slowest
//     country: [jp, de, us]
//     ego.max_speed: [8.33, 11.11, 13.89]
//   zip:                                   # lists of equal length, taken together (one factor);
//     ego.max_speed: [8, 10]               # a list of such mappings gives several factors
//     ego.depart_speed: [8, 10]
//   set: {turn_signal_search_time: 2.5}    # the same for every run
//   timeout: 120                           # s of wall-clock time per run (default 300)
//   out: ../out/exit_blinker               # results directory (the command line's --out wins)
//   plot: {metric: turn1.lead_distance, x: ego.max_speed, y: country}   # for `sweep --plot`
//                                          # (or a list of such mappings: one picture each)
//
// Keys of grid, zip and set are anything `signalsim run --set` accepts: scenario keys (`seed`,
// `country`, `ego.max_speed`, `decider`, ...) or parameter names. A swept `decider` / `light_judge`
// (`decider: [reference, autoware_core, lib:../build/my.so]`) names lib: paths and exec: directories
// relative to the sweep file. Runs are numbered 0.. in the order
// scenarios (outermost) x grid x zip factors (innermost).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace signalsim {

/// One swept key and its values (the YAML text of each value, as `--set` receives it).
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
  std::vector<int> lines;  ///< line of each value in the sweep file
};

struct SweepPlot {
  std::string metric;  ///< a results.csv column; empty: the first *.lead_distance column
  std::string x, y;    ///< swept columns; empty: the first two swept keys (or scenario)
  int metric_line = 0, x_line = 0, y_line = 0;  ///< where each was given (else the line of plot:)
};

struct Sweep {
  std::string path;
  std::string name;
  std::string description;
  std::vector<std::string> scenarios;        ///< scenario files (directories expanded), in order
  int scenarios_line = 0;
  std::vector<SweepAxis> grid;
  int grid_line = 0;
  std::vector<std::vector<SweepAxis>> zips;  ///< each group is one factor
  int zip_line = 0;
  std::vector<std::string> set;              ///< fixed "key=value" overrides
  std::vector<int> set_lines;
  std::optional<double> timeout;             ///< [s] per run
  std::string out;                           ///< resolved against the file; empty when not given
  std::vector<SweepPlot> plots;  ///< plot: one mapping or a list of them, one picture each
  SweepPlot plot;                ///< the first of plots (empty when there is none)
};

/// Reads and checks a sweep file. Throws InputError naming the file and line: malformed YAML, an
/// unknown key, a value of the wrong shape, an empty grid/zip (or an empty list of values), zip lists
/// of different lengths, a key given twice, a reserved column name as key, a missing scenario path,
/// a plot: that cannot be drawn (plot_metric_problem and check_plot_axes, sweep_plot_check.hpp: x
/// and y must be swept keys or `scenario`, and differ).
Sweep load_sweep(const std::string& path);

/// The swept keys, grid first then zip, in file order.
std::vector<std::string> swept_keys(const Sweep& sweep);

/// set_argument, but a `decider` or `light_judge` value names its lib: path and exec: directory
/// relative to the sweep file (sut_override, scenario/sut_spec.hpp).
std::string sweep_set_argument(const Sweep& sweep, const std::string& key, const std::string& value);

/// "key=value" for `--set`: the value as written, double-quoted when YAML would read it back
/// differently (a list given in flow style stays as it is).
std::string set_argument(const std::string& key, const std::string& value);

}  // namespace signalsim
