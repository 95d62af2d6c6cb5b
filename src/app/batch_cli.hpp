// Command-line options shared by `batch`, `sweep` and `check`.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "batch/batch_runner.hpp"
#include "scenario/notes.hpp"
#include "app/cli_numbers.hpp"
#include "app/html_report.hpp"

namespace signalsim::app {

struct BatchCliOptions {
  std::string out_dir;
  int jobs = 0;          // 0: default_jobs()
  double timeout = 0.0;  // 0: the sweep file's, else 300 s
  bool resume = false;
  bool quiet = false;
  bool isolate = false;  // one process per run
  std::string report;    // --report: "failed" or "all"; empty: no report
};

/// --out, --jobs, --isolate, --timeout, --quiet, --report; --resume when `with_resume`.
inline void add_batch_options(CLI::App* sub, BatchCliOptions& o, const std::string& default_out, bool with_resume) {
  sub->add_option("--out", o.out_dir, "Output directory: results.csv and runs/ (default: " + default_out + ")");
  sub->add_option("--jobs,-j", o.jobs, "Worker processes at a time, one SUMO each (default: number of cores)")
      ->check(CLI::Range(1, 4096));
  sub->add_flag("--isolate", o.isolate,
                "One process per run (`signalsim run`), as before persistent workers: slower, nothing shared "
                "between runs");
  sub->add_option("--timeout", o.timeout, "Wall-clock limit per run in seconds (default 300); the run becomes an error row")
      ->check(positive_number());
  if (with_resume)
    sub->add_flag("--resume", o.resume,
                  "Keep the finished rows of OUT/results.csv (passed, failed, no_expectations) and run only the "
                  "others (error rows run again)");
  sub->add_flag("--quiet,-q", o.quiet, "No progress output, no notes")
      ->each([](const std::string&) { set_notes_enabled(false); });  // notes print as scenarios load
  add_report_flag(sub, o.report);
}

inline BatchSettings to_settings(const BatchCliOptions& o, const std::string& default_out, double default_timeout) {
  BatchSettings s;
  s.out_dir = o.out_dir.empty() ? default_out : o.out_dir;
  s.jobs = o.jobs > 0 ? o.jobs : default_jobs();
  s.timeout = o.timeout > 0 ? o.timeout : default_timeout;
  s.resume = o.resume;
  s.isolate = o.isolate;
  s.quiet = o.quiet;
  return s;
}

}  // namespace signalsim::app
