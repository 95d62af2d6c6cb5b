// The HTML report (docs/report.md): the --report[=all] flag of batch, sweep, check and compare, the
// facts of the command the report's first screen shows (OUT/command.json), check's verdicts
// (OUT/check.json), and making the pages with `signalsim-plot report` (python/signalsim_plot/report).
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "batch/junit_xml.hpp"

namespace signalsim::app {

inline constexpr const char* kCommandFacts = "command.json";  ///< OUT/command.json
inline constexpr const char* kCheckRecord = "check.json";     ///< OUT/check.json (check only)
inline constexpr const char* kReportPage = "report.html";     ///< OUT/report.html, the first page
inline constexpr const char* kReportDir = "report";           ///< OUT/report/runs/<run>.html


/// What a batch command was asked: the facts of the report's first screen besides those of the runs.
struct CommandFacts {
  std::string command;              ///< batch, sweep, check, compare
  std::vector<std::string> inputs;  ///< the scenario paths as given (sweep: the sweep file)
  std::string sweep_file;
  std::string golden;               ///< check's --golden
  std::vector<std::string> set;     ///< the overrides of every run (--set, --params, --decider, ...)
  struct Plot {
    std::string metric, x, y;       ///< results.csv columns
  };
  std::vector<Plot> plots;          ///< a sweep's plot: entries
  int jobs = 0;
};

/// main(): the command line and the time it started, for OUT/command.json.
void remember_command_line(int argc, char** argv);

/// --report[=all]: `mode` becomes "failed" (pictures of failed and errored runs) or "all".
void add_report_flag(CLI::App* sub, std::string& mode);

/// Writes OUT/command.json: the command line, its inputs, when it started and finished (UTC), the wall
/// time, the machine (host, system, cores) and --jobs. A file that cannot be written is a warning: the
/// runs' own results stand. Removes what an earlier command left for the report (remove_html_report):
/// call it before write_check_record.
void write_command_facts(const std::string& out_dir, const CommandFacts& facts);

/// Removes OUT/report.html, OUT/report/ and OUT/check.json: what an earlier command left for a report
/// (an earlier check's verdicts would otherwise be read as this command's).
void remove_html_report(const std::string& out_dir);

/// OUT/check.json: check's verdict per scenario (name, file, status passed|failed|error|skipped,
/// message, details: the golden diff, system_out: the failed expectations, time).
void write_check_record(const std::string& out_dir, const std::vector<JUnitCase>& cases);

/// `signalsim-plot report OUT [--all] --jobs N --quiet`; prints "report: OUT/report.html" unless
/// `quiet`. Returns the tool's exit code (0: written).
int make_html_report(const std::string& out_dir, bool all_pictures, int jobs, bool quiet);

/// A command's exit code after its --report (mode empty: none asked): `code`, or kExitPicture when the
/// report failed and `code` was 0 (as for --plot).
int finish_with_report(int code, const std::string& mode, const std::string& out_dir, int jobs, bool quiet);

}  // namespace signalsim::app
