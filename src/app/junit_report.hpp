// The JUnit cases of `check --junit` and `batch --junit` (docs/batch.md "JUnit"): what a CI server
// shows of each run besides its verdict. One home for
//   classname   the scenario file's folder relative to the working directory, dots for slashes, then
//               the net's file stem: `scenarios.cross` (a CI server groups by it)
//   file        the scenario file relative to the working directory (absolute when outside it)
//   properties  seed, country, net, each parameter file the values came from, decider, light_judge
//   attachments of a failed or errored run: its pictures (signalsim-plot's plots/*.png, drawn here
//               when missing, and gui.png), as paths like `file`'s
//   system-out  each failed expectation and law verdict with its detail
// and the checks and writing of the --junit file itself.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "batch/junit_xml.hpp"
#include "batch/results_table.hpp"
#include "batch/run_spec.hpp"

namespace signalsim::app {

/// `path` relative to the working directory when it lies inside it, else absolute.
std::string path_for_ci(const std::string& path);

/// The failed expectations and law verdicts of a run's summary with their details, one a line, for
/// the console and JUnit's <system-out>.
std::string failures_of(const nlohmann::ordered_json& summary);

/// A case with the run's name (the scenario file's stem), classname, file and, once the run wrote
/// `summary` (null: it did not), its properties. The outcome is the caller's.
JUnitCase junit_case(const RunSpec& run, const nlohmann::ordered_json& summary);

/// The run's summary.json in `run_dir`, or null when there is none readable (a run that did not start).
nlohmann::ordered_json summary_or_null(const std::string& run_dir);

/// For a failed or errored case: draws the run's pictures (signalsim-plot, unless `run_dir`/plots
/// already holds them, or the run wrote no timeline.csv; a failure to draw is reported and the case keeps
/// what there is) and attaches
/// every PNG of `run_dir`/plots and `run_dir`/gui.png. Nothing for other cases or a run without a summary.
void attach_pictures(JUnitCase& c, const std::string& run_dir);

/// `batch --junit`: a case per run from its results.csv row: passed, failed (the failed expectations
/// and law verdicts), skipped (no expectations), error (the row's error; no row: did not finish).
std::vector<JUnitCase> batch_junit_cases(const std::vector<RunSpec>& runs, const ResultRows& rows,
                                         const std::string& out_dir);

/// A folder a command writes into after its runs (--update's golden folder, --junit's): created and
/// written to now, so that one that cannot be is bad input before the runs rather than after them.
/// Throws InputError naming `flag`.
void check_writable_folder(const std::string& dir, const std::string& flag);

/// --junit FILE: not a folder, and its folder can be created and written into (bad input before
/// any run; throws InputError naming --junit).
void check_junit_destination(const std::string& file);

/// Writes the JUnit file (its folder created), whole or not at all.
void write_junit(const std::string& file, const std::string& suite, const std::vector<JUnitCase>& cases, double wall);

}  // namespace signalsim::app
