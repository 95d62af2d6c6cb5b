// Runs a batch's runs in worker processes and keeps results.csv up to date (batch_runner.hpp).
#include "batch/batch_runner.hpp"

#include <csignal>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "batch/batch_manifest.hpp"
#include "batch/child_process.hpp"
#include "batch/results_file.hpp"
#include "batch/run_outputs.hpp"
#include "batch/run_row_file.hpp"
#include "batch/run_rows.hpp"
#include "core/number_text.hpp"
#include "batch/worker_pool.hpp"
#include "scenario/input_error.hpp"
#include "report/atomic_file.hpp"
#include "report/run_files.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

void count(BatchResult& result) {
  result.passed = result.failed = result.no_expectations = result.errors = 0;
  for (const auto& [index, row] : result.rows) {
    const auto it = row.cells.find("status");
    const std::string status = it == row.cells.end() ? "" : it->second;
    if (status == "passed") ++result.passed;
    else if (status == "failed") ++result.failed;
    else if (status == "no_expectations") ++result.no_expectations;
    else ++result.errors;
  }
}

// Whether a finished run's files are still there: its summary.json in its run folder.
bool run_files_kept(const std::string& out_dir, const std::string& run_dir) {
  std::error_code ec;
  return fs::is_regular_file(fs::path(out_dir) / run_dir / run_files::kSummary, ec);
}

}  // namespace

int BatchResult::exit_code() const {
  if (interrupted) return kExitInterrupted;
  if (errors > 0 || !results_error.empty()) return kExitRunErrors;
  return failed > 0 ? kExitFailed : 0;
}

int default_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

std::string results_path(const std::string& out_dir) { return (fs::path(out_dir) / run_files::kResults).string(); }

BatchStart start_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings) {
  BatchStart batch;
  BatchResult& result = batch.result;
  result.total = runs.size();
  fs::create_directories(fs::path(settings.out_dir) / run_files::kRunsDir);
  batch.lock = std::make_unique<OutputLock>(settings.out_dir);
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout (| head) must not kill the batch
  const std::string csv = results_path(settings.out_dir);
  const std::string manifest_file = manifest_path(settings.out_dir);
  const std::string manifest = batch_manifest(runs);
  batch.run_dirs = run_dir_names(runs);

  if (settings.resume && fs::exists(csv)) {
    const std::string changed =
        fs::exists(manifest_file) ? manifest_difference(read_text_file(manifest_file), manifest) : "it has no batch.manifest";
    if (!changed.empty())
      throw InputError(settings.out_dir, 0,
                       "--resume: the results there were made with other settings (scenarios, their "
                       "contents or --set values changed: " + changed + "); use another --out");
    for (auto& [index, row] : read_results_csv(csv)) {
      if (index >= runs.size() || !row_matches(row, runs[index]))
        throw InputError(csv, static_cast<int>(index) + 2,
                         "--resume: run " + std::to_string(index) +
                             " was not this run of this batch (other scenarios or values); use another --out");
      const auto status = row.cells.find("status");
      // Error rows are run again, and so is a finished run whose files are gone (its folder deleted).
      if (status != row.cells.end() && is_finished_status(status->second) && run_files_kept(settings.out_dir, batch.run_dirs[index]))
        result.rows[index] = std::move(row);
    }
    // A run finished by a back-end that leaves a row file in its run directory (Slurm) but whose
    // row never reached results.csv (the merge did not happen: --no-wait, Ctrl-C) is done too.
    for (const RunSpec& run : runs) {
      if (result.rows.count(run.index)) continue;
      auto row = read_row_file(settings.out_dir, batch.run_dirs[run.index]);
      if (row && row->run == run.index && row_matches(*row, run) && is_finished_status(row->cells["status"]))
        result.rows[run.index] = std::move(*row);
    }
    result.skipped = result.rows.size();
  }
  write_file_atomically(manifest_file, manifest);
  batch.results_file = std::make_unique<ResultsFile>(csv);
  if (!batch.results_file->write(results_csv(settings.swept, result.rows)))
    throw std::runtime_error(batch.results_file->error());

  for (const RunSpec& run : runs) {
    if (result.rows.count(run.index)) continue;
    fs::remove_all(fs::path(settings.out_dir) / batch.run_dirs[run.index]);  // a stale or half-written run
    batch.to_run.push_back(&run);
  }
  batch.last_write = Clock::now();
  return batch;
}

std::vector<std::string> run_dir_names(const std::vector<RunSpec>& runs) {
  std::vector<std::string> names(runs.size());
  for (const RunSpec& run : runs) names[run.index] = run_dir_name(run, runs.size());
  return names;
}

BatchProgress begin_progress(BatchStart& batch, const BatchSettings& settings) {
  BatchResult& result = batch.result;
  if (!settings.quiet && result.skipped > 0)
    std::printf("resuming: %zu of %zu runs already done, %zu to run\n", result.skipped, result.total,
                batch.to_run.size());
  return BatchProgress(batch.to_run.size(), settings.quiet);
}

bool run_in_worker_pool(const std::vector<const RunSpec*>& runs, const std::vector<std::string>& run_dirs,
                        const BatchSettings& settings, const std::function<void(const RunSpec&, ResultRow)>& on_row,
                        const std::function<void()>& on_tick) {
  std::vector<ProcessJob> jobs;
  std::vector<const RunSpec*> by_job;
  const std::string self = self_executable();
  for (const RunSpec* run : runs) {
    ProcessJob job;
    job.id = by_job.size();
    job.timeout = settings.timeout;
    job.argv = {self, "run", run->scenario, "--out", (fs::path(settings.out_dir) / run_dirs[run->index]).string(),
                "--quiet"};
    for (const std::string& item : run->set) {
      job.argv.push_back("--set");
      job.argv.push_back(item);
    }
    jobs.push_back(std::move(job));
    by_job.push_back(run);
  }
  return run_jobs(
      jobs, settings.jobs, settings.isolate,
      [&](const ProcessJob& job, const ProcessResult& process) {
        const RunSpec& run = *by_job[job.id];
        on_row(run, make_row(run, settings.out_dir, run_dirs[run.index], settings.timeout, process));
      },
      on_tick);
}

void rewrite_results(BatchStart& batch, const BatchSettings& settings, bool now) {
  // Each run's own summary.json is already on disk; results.csv is rewritten at most once a second
  // (and at the end), so a batch of many thousands of runs stays linear.
  // A rewrite that fails (a full disk) stops nothing: the previous complete file stays, the batch
  // goes on and tries again with the next finished run.
  ResultsFile& file = *batch.results_file;
  if (!now && Clock::now() - batch.last_write < std::chrono::seconds(1) && file.error().empty()) return;
  const bool had_error = !file.error().empty();
  if (!file.write(results_csv(settings.swept, batch.result.rows)) && !had_error)
    std::fprintf(stderr, "signalsim: %s; the batch goes on and writes it again later\n", file.error().c_str());
  batch.last_write = Clock::now();
}

BatchResult finish_batch(BatchStart& batch, const BatchSettings& settings, bool completed) {
  BatchResult& result = batch.result;
  result.interrupted = !completed;
  const std::string table = results_csv(settings.swept, result.rows);
  if (!batch.results_file->write(table)) {
    // The finished rows must not be lost: the table goes to stdout instead, after one line that says so.
    result.results_error = batch.results_file->error();
    std::fprintf(stderr, "signalsim: %s; the finished rows follow on stdout\n", result.results_error.c_str());
    std::fwrite(table.data(), 1, table.size(), stdout);
    std::fflush(stdout);
  }
  count(result);
  result.wall = std::chrono::duration<double>(Clock::now() - batch.start).count();
  return result;
}

BatchResult run_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings) {
  BatchStart batch = start_batch(runs, settings);
  BatchProgress progress = begin_progress(batch, settings);
  const bool completed = run_in_worker_pool(
      batch.to_run, batch.run_dirs, settings,
      [&](const RunSpec& run, ResultRow row) {
        progress.finished(run, row);
        batch.result.rows[run.index] = std::move(row);
        rewrite_results(batch, settings);
      },
      [&] { progress.tick(); });
  progress.end();
  return finish_batch(batch, settings, completed);
}

std::string batch_summary(const BatchResult& result, const std::string& out_dir) {
  std::string out = std::to_string(result.total) + " run" + (result.total == 1 ? "" : "s") + ": " +
                    std::to_string(result.passed) + " passed, " + std::to_string(result.failed) + " failed, " +
                    std::to_string(result.no_expectations) + " without expectations, " +
                    std::to_string(result.errors) + " error" + (result.errors == 1 ? "" : "s");
  if (result.rows.size() < result.total) out += ", " + std::to_string(result.total - result.rows.size()) + " not run";
  if (result.skipped) out += " (" + std::to_string(result.skipped) + " from the earlier results.csv)";
  out += format_text(" in %.1f s; results: ", result.wall) + results_path(out_dir);
  if (result.interrupted) out += "\ninterrupted: finished runs are kept; run again with --resume to complete";
  return out;
}

}  // namespace signalsim
