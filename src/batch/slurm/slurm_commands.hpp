// The Slurm commands the back-end runs (sbatch, squeue, scancel, scontrol), each turned into a value
// or one line of error text. Nothing here knows signalsim's runs (slurm_backend.hpp does).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch/slurm/slurm_queue.hpp"

namespace signalsim {

/// Throws std::runtime_error "--backend slurm: sbatch is not on PATH (...)" for the first of
/// `programs` that is missing.
void require_slurm_programs(const std::vector<std::string>& programs);

/// How long `scontrol ping` may take before the back-end gives up on the controller: sbatch itself
/// retries an unreachable controller for about 18 s before it says so.
constexpr double kSlurmPingTimeout = 5.0;  ///< [s]

/// Throws std::runtime_error "--backend slurm: no Slurm controller answers (<why>)" unless
/// `scontrol ping` reports a controller up within kSlurmPingTimeout (why: scontrol's own line, or
/// "scontrol ping did not answer within 5 s").
void require_slurm_controller();

/// One job array to submit.
struct ArraySubmission {
  std::string script;                   ///< the batch script (its path)
  std::string job_name;                 ///< --job-name
  std::size_t tasks = 0;                ///< --array=0-(tasks-1)
  int max_parallel = 0;                 ///< %M; 0: no limit
  int cpus_per_task = 1;                ///< --cpus-per-task
  std::string output;                   ///< --output pattern (%A job, %a task); output_pattern() makes it
  std::string partition;                ///< --partition; "" the cluster's default
  std::string time;                     ///< --time; "" the partition's default
  std::vector<std::string> extra_args;  ///< --slurm-arg, passed to sbatch as they are, before the script
};

/// `directory/name` as an sbatch --output pattern: a '%' of the directory (a user's --out) doubled,
/// so that only `name`'s %A and %a are replaced. Throws std::runtime_error for a directory with a
/// '\' (sbatch then replaces no pattern at all, and the tasks' logs could not be told apart).
std::string output_pattern(const std::string& directory, const std::string& name);

/// sbatch's argv for the submission (--parsable first).
std::vector<std::string> sbatch_argv(const ArraySubmission& submission);

/// Asks sbatch whether it would take the submission (--test-only, one task, no script), so that a
/// bad --partition, --time or --slurm-arg is refused before anything in OUT changes. Throws like
/// submit_array.
void check_submission(const ArraySubmission& submission);

/// How long a Slurm command may take before it is killed and its call fails with one line: a
/// controller that never answers must not hang the submitting command (nor its Ctrl-C). sbatch gets
/// longer: a submission that timed out may still have made a job (the message says how to look).
constexpr double kSlurmQueryTimeout = 60.0;   ///< squeue, scancel, scontrol
constexpr double kSlurmSubmitTimeout = 300.0; ///< sbatch

/// Submits; returns the job id. Throws std::runtime_error "sbatch refused the job: <its message>",
/// or "sbatch did not answer within 300 s ..." (naming the job to look for with squeue).
std::string submit_array(const ArraySubmission& submission);

/// The states of the job's array tasks (squeue --states=all). `ok` false when squeue failed (error
/// holds its message); a job Slurm no longer knows is ok with no task.
struct QueueReading {
  bool ok = false;
  TaskStates tasks;
  std::string error;
};
QueueReading read_queue(const std::string& job_id);

/// scancel JOB; "" or its error message.
std::string cancel_job(const std::string& job_id);

/// The cluster's MaxArraySize (scontrol show config), `fallback` when it cannot be read.
std::size_t max_array_size(std::size_t fallback = 1001);

}  // namespace signalsim
