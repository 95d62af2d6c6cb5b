// results.csv: the table of a batch, one row per finished run. Its columns (fixed ones around the
// runs' metric columns), writing it, reading it back for --resume, and whether a row read back
// still describes a run.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "batch/run_spec.hpp"

namespace signalsim {

/// One finished run: column -> text. Empty cells are not stored.
struct ResultRow {
  std::size_t run = 0;
  std::map<std::string, std::string> cells;
};
using ResultRows = std::map<std::size_t, ResultRow>;  ///< by run index

/// The row's cell in `column`, empty when the row has none.
inline std::string row_cell(const ResultRow& row, const std::string& column) {
  const auto it = row.cells.find(column);
  return it == row.cells.end() ? std::string() : it->second;
}

/// True for a column results.csv fills itself (run, scenario, file, status, ..., wall_time, error):
/// a swept key may not take such a name.
bool is_fixed_result_column(const std::string& name);

/// A swept key's column: the key, or `swept.<key>` when the key is also a run-level metric's column
/// (`max_jerk`: a judge parameter and the ride's metric), so that a key and a metric never share one.
std::string swept_column(const std::string& key);

/// Columns: run, scenario, file, <swept keys>, status, expectations_passed, expectations_total,
/// failed_expectations, law_failed, run_dir, <metric columns of any row, metric_column_less order>, wall_time,
/// error.
std::vector<std::string> result_columns(const std::vector<std::string>& swept, const ResultRows& rows);

/// The whole table as CSV (RFC 4180 quoting), rows by run index.
std::string results_csv(const std::vector<std::string>& swept, const ResultRows& rows);

/// Reads a results.csv written by results_csv. Throws std::runtime_error when it cannot be read.
ResultRows read_results_csv(const std::string& path);

/// True when `row` describes `run` (same scenario file and swept values): --resume may skip it.
bool row_matches(const ResultRow& row, const RunSpec& run);

}  // namespace signalsim
