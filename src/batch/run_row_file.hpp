// A run's finished row kept in its own run directory, RUNDIR/row.csv: a back-end that runs the runs
// elsewhere (a Slurm task, batch/slurm/slurm_backend.hpp) writes it as each run ends, atomically, and the
// submitting side merges results.csv from these files. The file is a results.csv of one row (the
// same cells, the same text), so the merged table equals the local back-end's byte for byte.
// A run without the file did not finish.
#pragma once

#include <optional>
#include <string>

#include "batch/results_table.hpp"

namespace signalsim {

/// OUT/RUN_DIR/row.csv
std::string row_file_path(const std::string& out_dir, const std::string& run_dir);

/// Writes the row (tmp + rename). Throws std::runtime_error naming the file when it cannot.
void write_row_file(const std::string& out_dir, const std::string& run_dir, const ResultRow& row);

/// The row, or nothing when the file is missing or is not a one-row results table (a torn copy
/// cannot happen: the file is renamed into place whole).
std::optional<ResultRow> read_row_file(const std::string& out_dir, const std::string& run_dir);

}  // namespace signalsim
