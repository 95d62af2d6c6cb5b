// Sweep files (a grid of runs over scenarios and `--set` values) and the results table of a batch.
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
// `country`, `ego.max_speed`, ...) or parameter names. Runs are numbered 0.. in the order
// scenarios (outermost) x grid x zip factors (innermost).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/atomic_file.hpp"

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

/// One run of a batch or sweep.
struct RunSpec {
  std::size_t index = 0;
  std::string scenario;                                     ///< the scenario file
  std::string name;                                         ///< the scenario's `name`
  std::vector<std::pair<std::string, std::string>> values;  ///< swept key -> value, sweep order
  std::vector<std::string> set;                             ///< every --set item for the run
  std::string load_error;  ///< a suite's file that does not load: its one-line message (an error row)
};

/// Reads and checks a sweep file. Throws InputError naming the file and line: malformed YAML, an
/// unknown key, a value of the wrong shape, an empty grid/zip (or an empty list of values), zip lists
/// of different lengths, a key given twice, a reserved column name as key, a missing scenario path,
/// a plot: that cannot be drawn (see plot_metric_problem; x and y must be swept keys or `scenario`,
/// and differ).
Sweep load_sweep(const std::string& path);

/// Why `metric` cannot be the plot: metric of a sweep, "" when it can: it must be a results.csv
/// column that holds numbers - a run metric (max_decel, ...), expectations_passed/_total, wall_time,
/// a section's `<kind><n>.<lead_distance|lead_time|time_on|flickers>` (kind turn, roundabout_entry,
/// roundabout_exit; n from 1) or `light<n>.stop_position_error|red_light_violation|emergency_stop`
/// (the true/false ones as the share of runs where true). Text and the other true/false columns
/// (turn1.blinker, turn1.missed) are refused: a heat map of them shows no value.
std::string plot_metric_problem(const std::string& metric);

/// Checks every plot's metric (check_plot_metric) before any run starts.
void check_sweep_plot(const Sweep& sweep, const std::vector<RunSpec>& runs);

/// Checks one plot: metric against the runs before any of them starts: a section or light metric
/// (`roundabout_exit1.lead_distance`, `light2.stop_position_error`) needs a run whose route has that
/// section or light (routes built from the nets as the runs build them; no SUMO). Runs whose route
/// cannot be built are left to fail on their own. Throws InputError at the line of plot.metric.
void check_plot_metric(const Sweep& sweep, const SweepPlot& plot, const std::vector<RunSpec>& runs);

/// Scenario files from paths: a file as given, a directory's *.yaml (sorted by name). Throws
/// InputError for a missing path or an empty directory (`origin`/`line` name where it was given).
std::vector<std::string> scenario_files(const std::vector<std::string>& paths, const std::string& origin = "",
                                        int line = 0);

/// The swept keys, grid first then zip, in file order.
std::vector<std::string> swept_keys(const Sweep& sweep);

/// Every run of the sweep (names left empty); see the file comment for the order. Throws InputError
/// above 1000000 runs.
std::vector<RunSpec> expand_sweep(const Sweep& sweep);

/// Loads every run's scenario with its overrides (no SUMO) and fills in its name. Throws InputError
/// naming the sweep file and the line of the value at fault (the grid/zip when only a combination
/// fails) for an unknown key, a bad value, an unknown country, ...
void check_sweep_runs(const Sweep& sweep, std::vector<RunSpec>& runs);

/// The runs of a suite: one per scenario file with the same overrides. Loads each (no SUMO). A file
/// that does not load (malformed, an unknown key, ...) is a run with `load_error` set and its file
/// stem as name: it becomes an error row and the others run. Throws InputError for a bad --set.
std::vector<RunSpec> suite_runs(const std::vector<std::string>& files, const std::vector<std::string>& set);

// --- results.csv --------------------------------------------------------------------------------

/// One finished run: column -> text. Empty cells are not stored.
struct ResultRow {
  std::size_t run = 0;
  std::map<std::string, std::string> cells;
};
using ResultRows = std::map<std::size_t, ResultRow>;  ///< by run index

/// Columns: run, scenario, file, <swept keys>, status, expectations_passed, expectations_total,
/// failed_expectations, run_dir, <metric columns of any row, metric_column_less order>, wall_time,
/// error.
std::vector<std::string> result_columns(const std::vector<std::string>& swept, const ResultRows& rows);

/// The whole table as CSV (RFC 4180 quoting), rows by run index.
std::string results_csv(const std::vector<std::string>& swept, const ResultRows& rows);

/// Reads a results.csv written by results_csv. Throws std::runtime_error when it cannot be read.
ResultRows read_results_csv(const std::string& path);

/// True when `row` describes `run` (same scenario file and swept values): --resume may skip it.
bool row_matches(const ResultRow& row, const RunSpec& run);

// write_file_atomically (through "<path>.tmp" and a rename): scenario/atomic_file.hpp.

/// CSV helpers (RFC 4180).
std::string csv_field(const std::string& text);
std::vector<std::vector<std::string>> parse_csv(const std::string& text);

}  // namespace signalsim
