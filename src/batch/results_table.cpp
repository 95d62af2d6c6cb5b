// results.csv: its columns, writing it, reading it back, matching a row to a run (see results_table.hpp).
#include "batch/results_table.hpp"

#include <algorithm>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/csv.hpp"
#include "report/metric_columns.hpp"

namespace signalsim {
namespace {

// The columns results.csv fills itself, before the swept keys, after them, and after the metrics.
const std::vector<std::string>& leading_columns() {
  static const std::vector<std::string> columns = {"run", "scenario", "file"};
  return columns;
}
const std::vector<std::string>& outcome_columns() {
  static const std::vector<std::string> columns = {"status", "expectations_passed", "expectations_total",
                                                   "failed_expectations", "law_failed", "run_dir"};
  return columns;
}
const std::vector<std::string>& trailing_columns() {
  static const std::vector<std::string> columns = {"wall_time", "error"};
  return columns;
}

}  // namespace

bool is_fixed_result_column(const std::string& name) {
  for (const auto* columns : {&leading_columns(), &outcome_columns(), &trailing_columns()})
    if (std::find(columns->begin(), columns->end(), name) != columns->end()) return true;
  return false;
}

std::string swept_column(const std::string& key) { return is_run_metric_column(key) ? "swept." + key : key; }

std::vector<std::string> result_columns(const std::vector<std::string>& swept, const ResultRows& rows) {
  std::vector<std::string> columns = leading_columns();
  for (const std::string& key : swept) columns.push_back(swept_column(key));
  columns.insert(columns.end(), outcome_columns().begin(), outcome_columns().end());
  std::set<std::string> fixed(columns.begin(), columns.end());
  fixed.insert(trailing_columns().begin(), trailing_columns().end());
  std::set<std::string> metric_set;
  for (const auto& [index, row] : rows)
    for (const auto& [column, text] : row.cells)
      if (!fixed.count(column)) metric_set.insert(column);
  std::vector<std::string> metrics(metric_set.begin(), metric_set.end());
  std::stable_sort(metrics.begin(), metrics.end(), metric_column_less);
  columns.insert(columns.end(), metrics.begin(), metrics.end());
  columns.insert(columns.end(), trailing_columns().begin(), trailing_columns().end());
  return columns;
}

std::string results_csv(const std::vector<std::string>& swept, const ResultRows& rows) {
  const std::vector<std::string> columns = result_columns(swept, rows);
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + csv_field(columns[i]);
  out += '\n';
  for (const auto& [index, row] : rows) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (i) out += ',';
      if (columns[i] == "run") {
        out += std::to_string(index);
        continue;
      }
      const auto it = row.cells.find(columns[i]);
      if (it != row.cells.end()) out += csv_field(it->second);
    }
    out += '\n';
  }
  return out;
}

ResultRows read_results_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const auto records = parse_csv(buffer.str());
  if (records.empty() || records.front().empty() || records.front().front() != "run")
    throw std::runtime_error(path + ": not a results.csv (its first column is not 'run')");
  const auto& header = records.front();
  ResultRows rows;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const auto& record = records[r];
    if (record.size() == 1 && record[0].empty()) continue;
    if (record.size() != header.size())
      throw std::runtime_error(path + ":" + std::to_string(r + 1) + ": " + std::to_string(record.size()) +
                               " fields, the header has " + std::to_string(header.size()));
    ResultRow row;
    try {
      std::size_t used = 0;
      row.run = std::stoul(record[0], &used);
      if (used != record[0].size()) throw std::invalid_argument("trailing characters");
    } catch (const std::exception&) {
      throw std::runtime_error(path + ":" + std::to_string(r + 1) + ": run '" + record[0] + "' is not a number");
    }
    for (std::size_t i = 1; i < header.size(); ++i)
      if (!record[i].empty()) row.cells[header[i]] = record[i];
    rows[row.run] = std::move(row);
  }
  return rows;
}

bool row_matches(const ResultRow& row, const RunSpec& run) {
  const auto cell = [&](const std::string& column) {
    const auto it = row.cells.find(column);
    return it == row.cells.end() ? std::string() : it->second;
  };
  if (row.run != run.index || cell("file") != run.scenario) return false;
  for (const auto& [key, value] : run.values)
    if (cell(swept_column(key)) != value) return false;
  return true;
}

}  // namespace signalsim
