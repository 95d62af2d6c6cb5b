// The Slurm back-end of `batch` and `sweep` (docs/slurm.md): the same runs, rows and results.csv
// as the local pool, run as one Slurm job array.
//
//   submit: start_batch (lock, --resume, manifest, run directories), the runs still to run cut into
//     chunks (--chunk, kept within the cluster's MaxArraySize), OUT/slurm/chunks.json and task.sh,
//     one `sbatch --array=0-(T-1)%M`; each task runs `signalsim run-chunk OUT INDEX` (run_chunk.hpp)
//   wait (the default): slurm_wait.hpp, then results.csv as the local back-end writes it;
//     --no-wait returns once the job is accepted
//   collect (--collect): waits for the recorded job the same way (Ctrl-C only stops waiting) and
//     merges results.csv: the rows kept at submission, the row files, error rows for lost runs
//   --resume: start_batch keeps every finished row (results.csv and row files); only the others
//     are submitted
//   refused: sbatch/squeue/scancel not on PATH, a rejected submission (sbatch's message), a new
//     submission or a local batch into an OUT whose recorded job still has tasks pending or running
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/batch_runner.hpp"

namespace signalsim {

struct SlurmOptions {
  std::size_t chunk = 0;                ///< runs per array task; 0: 10 per CPU of a task
  int max_parallel = 0;                 ///< array tasks at a time (%M); 0: the cluster decides
  std::string partition;                ///< --partition
  std::string time;                     ///< --time, per task
  std::vector<std::string> sbatch_args; ///< --slurm-arg, each passed to sbatch as it is
  bool wait = true;                     ///< false: --no-wait
};

struct SlurmOutcome {
  BatchResult result;
  bool submitted = false;  ///< a job was submitted (not when every run was already done)
  bool waited = true;      ///< false: --no-wait, nothing merged yet
  std::string job_id;
};

/// Submits the runs still to run (settings.jobs is each task's CPUs) and, unless --no-wait, waits
/// and merges results.csv. Throws like run_batch, and std::runtime_error for a missing Slurm
/// program or a rejected submission.
SlurmOutcome run_batch_on_slurm(const std::vector<RunSpec>& runs, const BatchSettings& settings,
                                const SlurmOptions& slurm);

/// --collect: waits for OUT's recorded job and merges results.csv. Throws InputError when OUT holds
/// another batch's runs, std::runtime_error when OUT has no recorded job.
BatchResult collect_slurm_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings);

/// Throws InputError when OUT/slurm/job.json names a job that still has tasks pending or running
/// (its tasks write into OUT). Does nothing without a record, without squeue on PATH, or when squeue
/// cannot answer.
void refuse_while_slurm_job_runs(const std::string& out_dir);

/// A local batch into OUT: the recorded (ended) Slurm job no longer describes OUT's runs, so that a
/// later --collect does not merge it over the local rows.
void forget_slurm_job(const std::string& out_dir);

}  // namespace signalsim
