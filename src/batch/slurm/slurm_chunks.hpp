// What a Slurm submission leaves in OUT/slurm/ for its tasks and for a later --collect:
//   chunks.json   the runs to run, cut into chunks of consecutive runs, one chunk per array task
//                 (each run: index, scenario file, name, swept values, --set items, run directory),
//                 the working directory of the submission, the timeout per run and --isolate
//   task.sh       the batch script: `signalsim run-chunk OUT $SLURM_ARRAY_TASK_ID`
//   job.json      the submitted job's id and its number of tasks (written once sbatch accepted it)
//   logs/         each task's output (task-<job>_<task>.log)
// and how many runs go into one chunk.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "batch/run_spec.hpp"

namespace signalsim {

/// One run of a chunk: what `signalsim run-chunk` needs to run it and make its row.
struct ChunkRun {
  RunSpec spec;
  std::string run_dir;  ///< "runs/NNNN-name"
};

struct ChunkList {
  std::string directory;  ///< the submission's working directory (scenario paths are relative to it)
  double timeout = 300.0;
  bool isolate = false;  ///< --isolate: one process per run in the tasks' pools too
  std::vector<std::vector<ChunkRun>> chunks;  ///< by array task index
};

/// OUT/slurm
std::string slurm_dir(const std::string& out_dir);

/// Runs per chunk: `requested` (0: 10 per CPU of a task), raised so that the chunks fit in the
/// cluster's MaxArraySize; `note` says so when it had to be raised.
std::size_t chunk_size(std::size_t runs, std::size_t requested, int cpus_per_task, std::size_t max_array,
                       std::string& note);

/// `runs` cut into consecutive chunks of `size`.
std::vector<std::vector<ChunkRun>> make_chunks(const std::vector<ChunkRun>& runs, std::size_t size);

/// Writes OUT/slurm/chunks.json atomically. Throws std::runtime_error.
void write_chunk_list(const std::string& out_dir, const ChunkList& list);

/// Reads OUT/slurm/chunks.json. Throws std::runtime_error naming the file.
ChunkList read_chunk_list(const std::string& out_dir);

/// Writes OUT/slurm/task.sh (run by the program at `program`) and returns its path.
std::string write_task_script(const std::string& out_dir, const std::string& program);

/// The job a submission made.
struct SlurmJob {
  std::string id;
  std::size_t tasks = 0;
};

/// OUT/slurm/job.json: written after sbatch accepted the job, removed before a new submission.
void write_job_record(const std::string& out_dir, const SlurmJob& job);
void remove_job_record(const std::string& out_dir);
/// The recorded job, or nothing when there is none. Throws std::runtime_error when it is unreadable.
std::optional<SlurmJob> read_job_record(const std::string& out_dir);

}  // namespace signalsim
