// A run's row of results.csv: from a worker's end (exit code, stderr, RUNDIR/summary.json), or from a
// scenario file that did not load. Also the run directory's name and the run's one-line description.
#pragma once

#include <cstddef>
#include <string>

#include "batch/child_supervisor.hpp"
#include "batch/results_table.hpp"
#include "batch/run_spec.hpp"

namespace signalsim {

/// True for the statuses of a run that finished (passed, failed, no_expectations): --resume keeps
/// such rows; anything else ("error") is run again.
bool is_finished_status(const std::string& status);

/// "runs/0007-close_turns": by index (4 digits, more for 10000+ runs), so names never collide.
std::string run_dir_name(const RunSpec& run, std::size_t total);

/// "run 7 close_turns country=jp": for progress lines.
std::string describe_run(const RunSpec& run);

/// A worker's stderr as one line: "signalsim: " prefixes dropped, lines joined with " / ", at most
/// about 600 characters.
std::string stderr_one_line(const std::string& text);

/// The row of a run whose worker ended: status, expectations and metrics from OUT/RUN_DIR/summary.json
/// after exit code 0 or 1; otherwise an error row (timeout, signal, exit code 2 with its stderr).
ResultRow make_row(const RunSpec& run, const std::string& out_dir, const std::string& run_dir, double timeout,
                   const ProcessResult& result);

}  // namespace signalsim
