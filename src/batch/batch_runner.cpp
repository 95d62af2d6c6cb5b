// Runs a batch's runs in worker processes and keeps results.csv up to date (batch_runner.hpp).
#include "batch/batch_runner.hpp"

#include <csignal>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <thread>

#include "batch/batch_manifest.hpp"
#include "batch/batch_progress.hpp"
#include "batch/process_pool.hpp"
#include "batch/results_file.hpp"
#include "batch/run_outputs.hpp"
#include "batch/run_rows.hpp"
#include "batch/text_format.hpp"
#include "batch/worker_pool.hpp"
#include "scenario/input_error.hpp"
#include "report/atomic_file.hpp"

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

std::string results_path(const std::string& out_dir) { return (fs::path(out_dir) / "results.csv").string(); }

BatchResult run_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings) {
  const auto start = Clock::now();
  BatchResult result;
  result.total = runs.size();
  fs::create_directories(fs::path(settings.out_dir) / "runs");
  const OutputLock lock(settings.out_dir);
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout (| head) must not kill the batch
  const std::string csv = results_path(settings.out_dir);
  const std::string manifest_file = manifest_path(settings.out_dir);
  const std::string manifest = batch_manifest(runs);

  if (settings.resume && fs::exists(csv)) {
    if (!fs::exists(manifest_file) || read_text_file(manifest_file) != manifest)
      throw InputError(settings.out_dir, 0,
                       "--resume: the results there were made with other settings (scenarios, their "
                       "contents or --set values changed); use another --out");
    for (auto& [index, row] : read_results_csv(csv)) {
      if (index >= runs.size() || !row_matches(row, runs[index]))
        throw InputError(csv, static_cast<int>(index) + 2,
                         "--resume: run " + std::to_string(index) +
                             " was not this run of this batch (other scenarios or values); use another --out");
      const auto status = row.cells.find("status");
      if (status != row.cells.end() && is_finished_status(status->second))
        result.rows[index] = std::move(row);  // error rows are run again
    }
    result.skipped = result.rows.size();
  }
  write_file_atomically(manifest_file, manifest);
  ResultsFile results_file(csv);
  if (!results_file.write(results_csv(settings.swept, result.rows))) throw std::runtime_error(results_file.error());

  std::vector<ProcessJob> jobs;
  std::vector<const RunSpec*> not_loaded;
  std::vector<std::string> run_dirs(runs.size());
  const std::string self = self_executable();
  for (const RunSpec& run : runs) {
    run_dirs[run.index] = run_dir_name(run, runs.size());
    if (result.rows.count(run.index)) continue;
    const fs::path dir = fs::path(settings.out_dir) / run_dirs[run.index];
    fs::remove_all(dir);  // a stale or half-written run of an earlier batch
    if (!run.load_error.empty()) {
      not_loaded.push_back(&run);  // an error row with the file's message; no worker
      continue;
    }
    ProcessJob job;
    job.id = run.index;
    job.timeout = settings.timeout;
    job.argv = {self, "run", run.scenario, "--out", dir.string(), "--quiet"};
    for (const std::string& item : run.set) {
      job.argv.push_back("--set");
      job.argv.push_back(item);
    }
    jobs.push_back(std::move(job));
  }
  if (!settings.quiet && result.skipped > 0)
    std::printf("resuming: %zu of %zu runs already done, %zu to run\n", result.skipped, runs.size(), jobs.size());

  BatchProgress progress(jobs.size() + not_loaded.size(), settings.quiet);
  for (const RunSpec* run : not_loaded) {
    ResultRow row = load_error_row(*run);
    progress.finished(*run, row);
    result.rows[run->index] = std::move(row);
  }
  auto last_write = Clock::now();
  const bool completed = run_jobs(
      jobs, settings.jobs, settings.isolate,
      [&](const ProcessJob& job, const ProcessResult& process) {
        const RunSpec& run = runs[job.id];
        ResultRow row = make_row(run, settings.out_dir, run_dirs[job.id], settings.timeout, process);
        progress.finished(run, row);
        result.rows[job.id] = std::move(row);
        // Each run's own summary.json is already on disk; results.csv is rewritten at most once a
        // second (and at the end), so a batch of many thousands of runs stays linear.
        // A rewrite that fails (a full disk) stops nothing: the previous complete file stays, the
        // batch goes on and tries again with the next finished run.
        if (Clock::now() - last_write >= std::chrono::seconds(1) || !results_file.error().empty()) {
          const bool had_error = !results_file.error().empty();
          if (!results_file.write(results_csv(settings.swept, result.rows)) && !had_error)
            std::fprintf(stderr, "signalsim: %s; the batch goes on and writes it again later\n",
                         results_file.error().c_str());
          last_write = Clock::now();
        }
      },
      [&] { progress.tick(); });
  progress.end();
  result.interrupted = !completed;
  const std::string table = results_csv(settings.swept, result.rows);
  if (!results_file.write(table)) {
    // The finished rows must not be lost: the table goes to stdout instead, after one line that says so.
    result.results_error = results_file.error();
    std::fprintf(stderr, "signalsim: %s; the finished rows follow on stdout\n", result.results_error.c_str());
    std::fwrite(table.data(), 1, table.size(), stdout);
    std::fflush(stdout);
  }
  count(result);
  result.wall = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
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
