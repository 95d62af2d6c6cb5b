// Runs many scenario runs in worker processes and keeps results.csv up to date (batch, sweep, check).
//
//   read OUT/results.csv when resuming: rows of finished runs (passed, failed, no_expectations) that
//     match this batch are kept, error rows are dropped (run again); a row that does not match
//     (another sweep) is an error
//   for each remaining run (by index): `signalsim run SCENARIO --out OUT/runs/NNNN-name --quiet
//     --set ...` in one of `jobs` persistent workers, or as a process of its own with `isolate`
//     (worker_pool.hpp, both watched by child_supervisor.hpp), each with the wall-clock timeout
//   a run whose scenario file does not load: its worker exits 2 with the file's line, an error row
//   as each worker ends: a row from its exit code and RUNDIR/summary.json (status passed, failed or
//     no_expectations - a scenario without expectations, nothing checked, not a failure - expectations,
//     "metrics"; computed from the run's files when summary.json has none), or an error row (exit
//     code 2 with its stderr, a signal, a timeout, an unreadable summary);
//     results.csv rewritten (tmp + rename, results_file.hpp: a failed rewrite on a full disk keeps
//     the previous file and is tried again) with every finished row, ordered by run index
//   progress: one updating line on a terminal, one plain line per finished run otherwise
//   Ctrl-C: start nothing more, stop the workers, keep every finished row; exit code 130
// run_batch is start_batch + begin_progress + run_in_worker_pool + finish_batch; another back-end
// (Slurm, batch/slurm/slurm_backend.hpp) calls the same around its own way of running the runs.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "batch/batch_manifest.hpp"
#include "batch/batch_progress.hpp"
#include "batch/results_file.hpp"
#include "batch/results_table.hpp"
#include "batch/run_rows.hpp"
#include "batch/run_spec.hpp"
#include "report/exit_codes.hpp"

namespace signalsim {

struct BatchSettings {
  std::string out_dir;              ///< results.csv and runs/ go here
  int jobs = 1;                     ///< worker processes at a time
  bool isolate = false;             ///< one process per run instead of persistent workers (worker_pool.hpp)
  double timeout = 300.0;           ///< [s] per run, wall clock
  bool resume = false;              ///< keep finished rows of an earlier results.csv
  bool quiet = false;               ///< no progress output
  std::vector<std::string> swept;   ///< swept keys (results.csv columns after "file")
};

struct BatchResult {
  ResultRows rows;                  ///< every finished row (kept and new), by run index
  std::size_t total = 0;            ///< runs in the batch
  std::size_t passed = 0, failed = 0, errors = 0;  ///< over all rows
  std::size_t no_expectations = 0;  ///< rows of scenarios without expectations (not failures)
  std::size_t skipped = 0;          ///< rows kept from an earlier results.csv
  bool interrupted = false;
  std::string results_error;        ///< results.csv could not be written at the end (the rows went to stdout)
  double wall = 0.0;                ///< [s]
  /// 130 interrupted, 4 a run errored (it has no verdict) or results.csv could not be written, 1 a run
  /// failed an expectation, else 0.
  int exit_code() const;
};

/// Default number of worker processes: the number of cores.
int default_jobs();

/// Runs the batch; see the file comment. Throws InputError when --resume meets a results.csv of
/// another batch, std::runtime_error when the output directory cannot be written.
BatchResult run_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings);

/// A batch under way, as start_batch leaves it for a back-end.
struct BatchStart {
  std::unique_ptr<OutputLock> lock;           ///< OUT is this batch's until finish_batch
  std::unique_ptr<ResultsFile> results_file;  ///< OUT/results.csv
  BatchResult result;                         ///< total; the rows kept by --resume (skipped)
  std::vector<std::string> run_dirs;          ///< "runs/NNNN-name" by run index
  std::vector<const RunSpec*> to_run;         ///< runs without a kept row, by index (run dirs removed)
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_write = std::chrono::steady_clock::now();
};

/// Takes OUT's lock, keeps the finished rows of an earlier results.csv (and of run directories'
/// row files, run_row_file.hpp) on --resume, writes OUT/batch.manifest and results.csv with the kept
/// rows, removes the run directories of the runs still to run. Throws like run_batch.
BatchStart start_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings);

/// The batch's run directories by run index: run_dir_name of each run.
std::vector<std::string> run_dir_names(const std::vector<RunSpec>& runs);

/// What every back-end does after start_batch: "resuming: K of N runs already done, M to run"
/// (unless quiet or nothing was kept) and the progress output over the runs still to run.
BatchProgress begin_progress(BatchStart& batch, const BatchSettings& settings);

/// Runs `runs` in worker processes (`signalsim run ... --out OUT/RUN_DIR`), at most settings.jobs at
/// a time with settings.timeout each; hands every finished run's row to `on_row` as it ends, calls
/// `on_tick` about every 200 ms. False when interrupted (SIGINT, SIGTERM): see child_supervisor.hpp.
bool run_in_worker_pool(const std::vector<const RunSpec*>& runs, const std::vector<std::string>& run_dirs,
                        const BatchSettings& settings, const std::function<void(const RunSpec&, ResultRow)>& on_row,
                        const std::function<void()>& on_tick);

/// Rewrites results.csv with every row so far, at most once a second unless `now`; a failed
/// rewrite (a full disk) is reported once and tried again on the next call.
void rewrite_results(BatchStart& batch, const BatchSettings& settings, bool now = false);

/// The last results.csv (the rows go to stdout, after one line on stderr, when it cannot be
/// written), the counts and the wall time. `completed` false: interrupted.
BatchResult finish_batch(BatchStart& batch, const BatchSettings& settings, bool completed);

/// OUT/results.csv
std::string results_path(const std::string& out_dir);

/// One line: "18 runs: 15 passed, 1 failed, 1 without expectations, 1 error in 3.2 s; results:
/// out/x/results.csv".
std::string batch_summary(const BatchResult& result, const std::string& out_dir);

}  // namespace signalsim
