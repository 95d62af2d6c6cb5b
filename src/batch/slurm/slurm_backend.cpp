// Submitting a batch as a Slurm job array, waiting for it, collecting it (slurm_backend.hpp).
#include "batch/slurm/slurm_backend.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "batch/child_process.hpp"
#include "batch/interrupt_guard.hpp"
#include "batch/run_outputs.hpp"
#include "batch/run_rows.hpp"
#include "batch/slurm/program_output.hpp"
#include "batch/slurm/slurm_chunks.hpp"
#include "batch/slurm/slurm_commands.hpp"
#include "batch/slurm/slurm_wait.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

std::string plural(std::size_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

void refuse_while_slurm_job_runs(const std::string& out_dir) {
  const auto job = read_job_record(out_dir);
  if (!job || find_on_path("squeue").empty()) return;
  // A controller that does not answer runs no task of it (and a Slurm submission fails anyway).
  const QueueReading reading = read_queue(job->id);
  for (const auto& [task, state] : reading.tasks)
    if (is_active_task_state(state))
      throw InputError(out_dir, 0,
                       "Slurm job " + job->id + " still has " + describe_task_states(reading.tasks) +
                           " writing there: wait for it (--collect), or cancel it (scancel " + job->id + ") first");
}

void forget_slurm_job(const std::string& out_dir) {
  std::error_code ignored;
  if (fs::exists(slurm_dir(out_dir), ignored)) remove_job_record(out_dir);
}

SlurmOutcome run_batch_on_slurm(const std::vector<RunSpec>& runs, const BatchSettings& settings,
                                const SlurmOptions& slurm) {
  require_slurm_programs({"sbatch", "squeue", "scancel", "scontrol"});
  require_slurm_controller();  // in seconds, before sbatch or squeue would wait on a controller that is down
  refuse_while_slurm_job_runs(settings.out_dir);
  // The tasks get absolute paths: they may start in another directory, on another node.
  const std::string out = fs::absolute(settings.out_dir).lexically_normal().string();
  ArraySubmission submission;
  submission.job_name = "signalsim-" + fs::path(out).filename().string();
  submission.max_parallel = slurm.max_parallel;
  submission.cpus_per_task = settings.jobs;
  submission.output = output_pattern((fs::path(slurm_dir(out)) / "logs").string(), "task-%A_%a.log");
  submission.partition = slurm.partition;
  submission.time = slurm.time;
  submission.extra_args = slurm.sbatch_args;
  check_submission(submission);  // a bad --partition is refused before OUT changes
  release_notes();  // the scenarios' notes, held by the command until the job can be submitted
  const InterruptGuard signals;  // from here, Ctrl-C ends in the wait below, which cancels the job

  SlurmOutcome outcome;
  BatchStart batch = start_batch(runs, settings);
  BatchProgress progress = begin_progress(batch, settings);
  if (batch.to_run.empty()) {
    progress.end();
    outcome.result = finish_batch(batch, settings, true);
    return outcome;
  }
  rewrite_results(batch, settings, true);  // a --collect later finds the error rows of files that did not load

  std::vector<ChunkRun> to_run;
  for (const RunSpec* run : batch.to_run) to_run.push_back({*run, batch.run_dirs[run->index]});
  std::string note;
  const std::size_t size = chunk_size(to_run.size(), slurm.chunk, settings.jobs, max_array_size(), note);
  if (!note.empty() && !settings.quiet) std::printf("note: %s\n", note.c_str());
  ChunkList list;
  list.directory = fs::current_path().string();
  list.timeout = settings.timeout;
  list.isolate = settings.isolate;
  list.chunks = make_chunks(to_run, size);

  remove_job_record(out);  // the chunk list is about to describe another job
  write_chunk_list(out, list);
  fs::create_directories(fs::path(slurm_dir(out)) / "logs");
  submission.script = write_task_script(out, self_executable());
  submission.tasks = list.chunks.size();
  if (InterruptGuard::interrupted()) {  // Ctrl-C before anything was submitted
    progress.end();
    outcome.result = finish_batch(batch, settings, false);
    return outcome;
  }
  const SlurmJob job{submit_array(submission), list.chunks.size()};
  write_job_record(out, job);
  outcome.submitted = true;
  outcome.job_id = job.id;
  if (!settings.quiet)
    std::printf("submitted Slurm job %s: %s in %s of up to %zu, %s each%s\n", job.id.c_str(),
                plural(to_run.size(), "run").c_str(), plural(job.tasks, "array task").c_str(), size,
                plural(static_cast<std::size_t>(settings.jobs), "CPU").c_str(),
                slurm.max_parallel > 0 ? (", at most " + std::to_string(slurm.max_parallel) + " at a time").c_str() : "");
  std::fflush(stdout);

  if (!slurm.wait && !InterruptGuard::interrupted()) {
    outcome.waited = false;
    progress.end();
    outcome.result = finish_batch(batch, settings, true);
    return outcome;
  }
  const bool completed = wait_for_slurm_job(batch, settings, list, job, progress, true);
  progress.end();
  outcome.result = finish_batch(batch, settings, completed);
  return outcome;
}

BatchResult collect_slurm_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings) {
  require_slurm_programs({"squeue"});
  const auto job = read_job_record(settings.out_dir);
  if (!job)
    throw std::runtime_error(settings.out_dir + ": --collect: no Slurm job was submitted there (slurm/job.json is " +
                             "missing); submit with --backend slurm");
  const std::string manifest_file = manifest_path(settings.out_dir);
  const std::string changed = fs::exists(manifest_file)
                                  ? manifest_difference(read_text_file(manifest_file), batch_manifest(runs))
                                  : "it has no batch.manifest";
  if (!changed.empty())
    throw InputError(settings.out_dir, 0,
                     "--collect: the runs there were made with other settings (scenarios, their contents or "
                     "--set values changed: " + changed + "); collect with the command that submitted them");
  const ChunkList list = read_chunk_list(settings.out_dir);

  BatchStart batch;
  batch.lock = std::make_unique<OutputLock>(settings.out_dir);
  batch.result.total = runs.size();
  batch.run_dirs = run_dir_names(runs);
  std::vector<bool> submitted(runs.size(), false);
  for (const auto& chunk : list.chunks)
    for (const ChunkRun& run : chunk) {
      if (run.spec.index >= runs.size() || run.spec.scenario != runs[run.spec.index].scenario ||
          run.spec.values != runs[run.spec.index].values)
        throw InputError(slurm_dir(settings.out_dir) + "/chunks.json", 0,
                         "run " + std::to_string(run.spec.index) + " is not a run of this batch; use the command "
                         "that submitted it");
      submitted[run.spec.index] = true;
    }
  // The rows that were final at submission (kept by --resume, files that did not load); rows of
  // submitted runs come from their row files (a second --collect recomputes them).
  const std::string csv = results_path(settings.out_dir);
  if (fs::exists(csv))
    for (auto& [index, row] : read_results_csv(csv))
      if (index < runs.size() && !submitted[index] && row_matches(row, runs[index])) {
        if (is_finished_status(row.cells["status"])) ++batch.result.skipped;
        batch.result.rows[index] = std::move(row);
      }
  batch.results_file = std::make_unique<ResultsFile>(csv);
  std::size_t to_collect = 0;
  for (const auto& chunk : list.chunks) to_collect += chunk.size();
  if (!settings.quiet)
    std::printf("collecting Slurm job %s: %s in %s\n", job->id.c_str(), plural(to_collect, "run").c_str(),
                plural(job->tasks, "array task").c_str());
  BatchProgress progress(to_collect, settings.quiet);
  const InterruptGuard signals;  // Ctrl-C only stops waiting
  const bool completed = wait_for_slurm_job(batch, settings, list, *job, progress, false);
  progress.end();
  return finish_batch(batch, settings, completed);
}

}  // namespace signalsim
