// Waiting for a submitted Slurm job (slurm_backend.hpp): each run's row is merged as its row file
// appears, the progress line shows the job's pending and running tasks, and once no task of the job
// is pending or running, every run still without a row becomes an error row named by its task's
// Slurm state (CANCELLED, TIMEOUT, NODE_FAIL, ...; a task Slurm no longer knows says so).
//
//   every 0.25 s: look for the row files of the runs of tasks that are not pending; rewrite
//     results.csv at most once a second
//   every 1 s (5 s after the first minute): squeue the job's tasks
//   a task that COMPLETED but whose runs have no row file: wait up to 30 s more (a shared
//     filesystem may show the files late), then its runs are error rows that say so
//   SIGINT/SIGTERM: scancel the job (`cancel_on_interrupt`, the submitting command) or only stop
//     waiting (--collect: the job goes on); the rows found so far are kept
#pragma once

#include "batch/batch_progress.hpp"
#include "batch/batch_runner.hpp"
#include "batch/slurm/slurm_chunks.hpp"

namespace signalsim {

/// Waits as above; every row goes into batch.result.rows (and through progress). False when
/// interrupted. The caller holds an InterruptGuard (interrupt_guard.hpp) around the call: the
/// submission one from before sbatch, so that a Ctrl-C during the submission cancels the job it
/// made (a second guard inside would forget that Ctrl-C).
bool wait_for_slurm_job(BatchStart& batch, const BatchSettings& settings, const ChunkList& list, const SlurmJob& job,
                        BatchProgress& progress, bool cancel_on_interrupt);

/// The error row of a run whose task ended (in `state`, "" when Slurm no longer knows the task)
/// without leaving its row file.
ResultRow lost_run_row(const RunSpec& run, const std::string& out_dir, const std::string& run_dir,
                       const std::string& task, const std::string& state);

}  // namespace signalsim
