// One Slurm array task's work (`signalsim run-chunk OUT INDEX`): chunk INDEX of OUT/slurm/chunks.json
// run with the local worker pool (one process per run when the submission had --isolate), from the submission's working directory, each finished run's row
// written atomically to RUNDIR/row.csv (run_row_file.hpp) for the submitting side to merge. A run
// that already has a finished row file (the task was requeued) is not run again.
#pragma once

#include <cstddef>
#include <string>

namespace signalsim {

/// Runs the chunk with `jobs` workers at a time and prints one line per finished run (the task's
/// log). Returns 0 when every run of the chunk has its row file (whatever the runs' verdicts), 130
/// when interrupted (scancel, the task's time limit), 2 when a row file could not be written.
/// Throws std::runtime_error for a chunk list it cannot read, an INDEX it does not have, or a
/// working directory this node does not have.
int run_chunk(const std::string& out_dir, std::size_t index, int jobs);

}  // namespace signalsim
