// RUNDIR/row.csv: one run's row of results.csv (run_row_file.hpp).
#include "batch/run_row_file.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "report/atomic_file.hpp"

namespace signalsim {

std::string row_file_path(const std::string& out_dir, const std::string& run_dir) {
  return (std::filesystem::path(out_dir) / run_dir / "row.csv").string();
}

void write_row_file(const std::string& out_dir, const std::string& run_dir, const ResultRow& row) {
  ResultRows rows;
  rows[row.run] = row;
  write_file_atomically(row_file_path(out_dir, run_dir), results_csv({}, rows));
}

std::optional<ResultRow> read_row_file(const std::string& out_dir, const std::string& run_dir) {
  const std::string path = row_file_path(out_dir, run_dir);
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;  // the common case while waiting: not yet
  try {
    ResultRows rows = read_results_csv(path);
    if (rows.size() != 1 || !rows.begin()->second.cells.count("status")) return std::nullopt;
    return std::move(rows.begin()->second);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

}  // namespace signalsim
