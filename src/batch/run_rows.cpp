// A run's row of results.csv from its worker's end and its run directory (run_rows.hpp).
#include "batch/run_rows.hpp"

#include <cctype>
#include <filesystem>

#include "batch/run_outputs.hpp"
#include "core/number_text.hpp"
#include "report/atomic_file.hpp"
#include "report/metric_columns.hpp"
#include "report/run_files.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// Fleet mode's counts (summary.json `fleet`, docs/fleet.md) as fleet_* cells: a country sweep in
// fleet mode shows each country's traffic side by side.
void add_fleet_cells(ResultRow& row, const nlohmann::ordered_json& summary) {
  if (!summary.contains("fleet") || !summary["fleet"].is_object()) return;
  const auto& fleet = summary["fleet"];
  for (const char* count : {"followed", "signalled", "left_to_sumo"})
    row.cells.emplace(std::string("fleet_") + count, fleet["vehicles"][count].dump());
  for (const char* field : {"on", "left", "right", "lead_mean"})
    row.cells.emplace(std::string("fleet_signals_") + field, fleet["signals"][field].dump());
  if (fleet["sumo"].is_object())
    for (const auto& [name, value] : fleet["sumo"].items()) row.cells.emplace("fleet_sumo_" + name, value.dump());
}

// The scenario's own name, as its run loaded it (the run list names a run by its file).
void name_from(ResultRow& row, const nlohmann::ordered_json& summary) {
  // (A file that did not load leaves a summary.json with an empty name: the file's stem stays.)
  if (summary.contains("scenario") && summary["scenario"].is_string() && !summary["scenario"].get<std::string>().empty())
    row.cells["scenario"] = summary["scenario"];
}

// An errored run's name from the summary.json it left (an error after its scenario loaded), if any.
void name_from_summary_file(ResultRow& row, const std::string& dir) {
  std::error_code ec;
  const fs::path path = fs::path(dir) / run_files::kSummary;
  if (!fs::is_regular_file(path, ec)) return;
  try {
    name_from(row, read_json_file(path.string()));
  } catch (const std::exception&) {  // half-written or not JSON: the file's stem stays
  }
}

// Status, expectations and metrics from a finished worker's summary.json.
void read_summary(ResultRow& row, const RunSpec& run, const std::string& dir) {
  const auto summary = read_json_file((fs::path(dir) / run_files::kSummary).string());
  const std::string status = summary.value("status", "");
  name_from(row, summary);
  if (!is_finished_status(status)) {
    row.cells["status"] = "error";
    row.cells["error"] = summary.value("error", "summary.json status '" + status + "'");
    return;
  }
  row.cells["status"] = status;
  int passed = 0, total = 0;
  std::string failed;
  if (summary.contains("expectations"))
    for (const auto& e : summary["expectations"]) {
      ++total;
      if (e.value("passed", false)) ++passed;
      else failed += (failed.empty() ? "" : "; ") + e.value("expectation", std::string("?"));
    }
  row.cells["expectations_passed"] = std::to_string(passed);
  row.cells["expectations_total"] = std::to_string(total);
  if (!failed.empty()) row.cells["failed_expectations"] = failed;
  // The law's failed verdicts (empty for a run SUMO drove, whose "law" is null).
  if (summary.contains("law") && summary["law"].is_object())
    row.cells["law_failed"] = std::to_string(summary["law"].value("failed", 0));
  nlohmann::ordered_json metrics;
  if (summary.contains("metrics")) {
    metrics = summary["metrics"];
  } else {
    // summary.json without "metrics" (written before outputs carried them): compute them here and
    // leave them beside it as metrics.json, where signalsim-plot looks too.
    try {
      metrics = metrics_from_run_dir(dir, run.scenario, run.set);
      write_file_atomically((fs::path(dir) / run_files::kMetrics).string(), metrics.dump(2) + "\n");
    } catch (const std::exception&) {
      metrics = nullptr;
    }
  }
  for (const auto& [column, text] : flatten_metrics(metrics))
    if (!text.empty()) row.cells.emplace(column, text);
  add_fleet_cells(row, summary);
  // A system under test: its name (a swept decider keeps its column as swept) and its agreement.
  for (const std::string role : {"decider", "light_judge"}) {
    if (!summary.contains(role) || !summary[role].is_object()) continue;
    const auto& block = summary[role];
    row.cells.emplace(role, block.value("name", std::string()));
    if (block.contains("agreement") && block["agreement"].is_number())
      row.cells.emplace(role + "_agreement", block["agreement"].dump());
  }
}

}  // namespace

bool is_finished_status(const std::string& status) {
  return status == "passed" || status == "failed" || status == "no_expectations";
}

std::string run_dir_name(const RunSpec& run, std::size_t total) {
  int width = 4;
  for (std::size_t n = total; n >= 10000; n /= 10) ++width;
  std::string name;
  for (const char c : run.name) name += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  return run_files::kRunsDir + format_text("/%0*zu-", width, run.index) + name;
}

std::string stderr_one_line(const std::string& text) {
  std::string out, line;
  auto flush = [&] {
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    std::size_t start = 0;
    while (start < line.size() && std::isspace(static_cast<unsigned char>(line[start]))) ++start;
    line.erase(0, start);
    if (line.rfind("signalsim: ", 0) == 0) line.erase(0, 11);
    if (!line.empty()) out += (out.empty() ? "" : " / ") + line;
    line.clear();
  };
  for (const char c : text) {
    if (c == '\n') flush();
    else line += c;
  }
  flush();
  if (out.size() > 600) out = out.substr(0, 600) + "...";
  return out;
}

std::string describe_run(const RunSpec& run) {
  std::string out = "run " + std::to_string(run.index) + " " + run.name;
  for (const auto& [key, value] : run.values) out += " " + key + "=" + value;
  return out;
}

ResultRow make_row(const RunSpec& run, const std::string& out_dir, const std::string& run_dir, double timeout,
                   const ProcessResult& result) {
  ResultRow row;
  row.run = run.index;
  row.cells["scenario"] = run.name;
  row.cells["file"] = run.scenario;
  for (const auto& [key, value] : run.values) row.cells[swept_column(key)] = value;
  row.cells["run_dir"] = run_dir;
  row.cells["wall_time"] = format_text("%.2f", result.wall);
  const std::string dir = (fs::path(out_dir) / run_dir).string();
  const std::string message = stderr_one_line(result.stderr_text);
  auto error = [&](const std::string& what) {
    row.cells["status"] = "error";
    row.cells["error"] = what;
  };
  if (result.timed_out) {
    error(format_text("timed out: still running after the %g s limit (worker killed)", timeout));
  } else if (!result.exited) {
    error(result.signal ? "worker killed by " + signal_name(result.signal) + (message.empty() ? "" : ": " + message)
                        : "worker failed: " + message);
  } else if (result.exit_code == 0 || result.exit_code == 1) {
    try {
      read_summary(row, run, dir);
    } catch (const std::exception& e) {
      error(std::string("exit code ") + std::to_string(result.exit_code) + " but " + e.what());
    }
  } else {
    error(message.empty() ? "exit code " + std::to_string(result.exit_code) : message);
    name_from_summary_file(row, dir);
  }
  return row;
}

}  // namespace signalsim
