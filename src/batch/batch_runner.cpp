#include "batch/batch_runner.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <csignal>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "batch/process_pool.hpp"
#include "batch/results_file.hpp"
#include "batch/run_outputs.hpp"
#include "scenario/input_error.hpp"
#include "report/atomic_file.hpp"
#include "report/metric_columns.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

std::string duration_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) return format("%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return format("%ld:%02ld", s / 60, s % 60);
}

// "runs/0007-close_turns": by index, so names never collide.
std::string run_dir_name(const RunSpec& run, std::size_t total) {
  int width = 4;
  for (std::size_t n = total; n >= 10000; n /= 10) ++width;
  std::string name;
  for (const char c : run.name) name += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  return format("runs/%0*zu-", width, run.index) + name;
}

// The worker's stderr as one line: "signalsim: " prefixes dropped, lines joined with " / ".
std::string one_line(const std::string& text) {
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

// Status, expectations and metrics from a finished worker's summary.json.
void read_summary(ResultRow& row, const RunSpec& run, const std::string& dir) {
  const auto summary = read_json_file((fs::path(dir) / "summary.json").string());
  const std::string status = summary.value("status", "");
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
  nlohmann::ordered_json metrics;
  if (summary.contains("metrics")) {
    metrics = summary["metrics"];
  } else {
    // summary.json without "metrics" (written before outputs carried them): compute them here and
    // leave them beside it as metrics.json, where tools/plot looks too.
    try {
      metrics = metrics_from_run_dir(dir, run.scenario, run.set);
      write_file_atomically((fs::path(dir) / "metrics.json").string(), metrics.dump(2) + "\n");
    } catch (const std::exception&) {
      metrics = nullptr;
    }
  }
  for (const auto& [column, text] : flatten_metrics(metrics))
    if (!text.empty()) row.cells.emplace(column, text);
}

ResultRow make_row(const RunSpec& run, const std::string& out_dir, const std::string& run_dir, double timeout,
                   const ProcessResult& result) {
  ResultRow row;
  row.run = run.index;
  row.cells["scenario"] = run.name;
  row.cells["file"] = run.scenario;
  for (const auto& [key, value] : run.values) row.cells[key] = value;
  row.cells["run_dir"] = run_dir;
  row.cells["wall_time"] = format("%.2f", result.wall);
  const std::string dir = (fs::path(out_dir) / run_dir).string();
  const std::string message = one_line(result.stderr_text);
  auto error = [&](const std::string& what) {
    row.cells["status"] = "error";
    row.cells["error"] = what;
  };
  if (result.timed_out) {
    error(format("timed out: still running after the %g s limit (worker killed)", timeout));
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
  }
  return row;
}

// A suite's scenario file that did not load: its row says why; the batch runs the others.
ResultRow load_error_row(const RunSpec& run) {
  ResultRow row;
  row.run = run.index;
  row.cells["scenario"] = run.name;
  row.cells["file"] = run.scenario;
  for (const auto& [key, value] : run.values) row.cells[key] = value;
  row.cells["wall_time"] = "0.00";
  row.cells["status"] = "error";
  row.cells["error"] = one_line(run.load_error);
  return row;
}

class Progress {
 public:
  Progress(std::size_t total, bool quiet) : total_(total), quiet_(quiet), tty_(isatty(STDOUT_FILENO) == 1) {}

  void finished(const RunSpec& run, const ResultRow& row) {
    ++done_;
    const std::string status = row.cells.at("status");
    failed_ += status == "failed";
    errors_ += status == "error";
    if (quiet_) return;
    std::string line = format("[%zu/%zu] ", done_, total_) + describe_run(run) + ": " + status;
    if (status == "error") line += ": " + row.cells.at("error");
    else line += " (" + row.cells.at("wall_time") + " s)";
    if (!tty_) {
      std::printf("%s\n", line.c_str());
      std::fflush(stdout);
      return;
    }
    if (status != "passed") std::printf("\r\033[K%s\n", line.c_str());  // keep failures (and notices) on screen
    draw();
  }

  void tick() {
    if (!quiet_ && tty_ && Clock::now() - last_draw_ > std::chrono::milliseconds(500)) draw();
  }

  void end() {
    if (!quiet_ && tty_ && drawn_) {
      draw();
      std::printf("\n");
      std::fflush(stdout);
    }
  }

 private:
  void draw() {
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    std::string eta = "--:--";
    if (done_ > 0) eta = duration_text(elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_));
    std::printf("\r\033[K[%zu/%zu] %zu failed, %zu error%s, ETA %s", done_, total_, failed_, errors_,
                errors_ == 1 ? "" : "s", eta.c_str());
    std::fflush(stdout);
    drawn_ = true;
    last_draw_ = Clock::now();
  }

  std::size_t total_, done_ = 0, failed_ = 0, errors_ = 0;
  bool quiet_, tty_, drawn_ = false;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_ = Clock::now();
};

void count(BatchResult& result) {
  result.passed = result.failed = result.no_expectations = result.errors = 0;
  for (const auto& [index, row] : result.rows) {
    const auto it = row.cells.find("status");
    const std::string status = it == row.cells.end() ? "" : it->second;
    if (status == "passed") ++result.passed;
    else if (status == "failed") ++result.failed;
    else if (status == "no_expectations") ++result.no_expectations;
    else ++result.errors;
  }
}

// The settings every run was made with: one line per run (index, scenario, the FNV-1a hash of the
// scenario file's bytes, every --set). --resume keeps earlier rows only when this is unchanged, so
// rows of another configuration never pass for this batch's.
std::string manifest_of(const std::vector<RunSpec>& runs) {
  std::string out = "signalsim batch manifest 1\n";
  for (const RunSpec& run : runs) {
    std::ifstream in(run.scenario, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::uint64_t hash = 1469598103934665603ULL;
    for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ULL;
    out += std::to_string(run.index) + "\t" + run.scenario + "\t" + format("%016llx", static_cast<unsigned long long>(hash));
    for (const std::string& item : run.set) out += "\t" + item;
    out += "\n";
  }
  return out;
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// One batch per output directory at a time: a second one would remove the first one's runs.
class OutputLock {
 public:
  explicit OutputLock(const std::string& out_dir) {
    const std::string path = (fs::path(out_dir) / ".lock").string();
    fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0 || flock(fd_, LOCK_EX | LOCK_NB) != 0)
      throw InputError(out_dir, 0, "another signalsim batch is writing to this --out directory");
  }
  ~OutputLock() {
    if (fd_ >= 0) close(fd_);  // releases the lock
  }
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace

std::string stderr_one_line(const std::string& text) { return one_line(text); }

int BatchResult::exit_code() const {
  if (interrupted) return kExitInterrupted;
  if (errors > 0 || !results_error.empty()) return kExitRunErrors;
  return failed > 0 ? kExitFailed : 0;
}

bool is_finished_status(const std::string& status) {
  return status == "passed" || status == "failed" || status == "no_expectations";
}

int default_jobs() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

std::string results_path(const std::string& out_dir) { return (fs::path(out_dir) / "results.csv").string(); }

BatchResult run_batch(const std::vector<RunSpec>& runs, const BatchSettings& settings) {
  const auto start = Clock::now();
  BatchResult result;
  result.total = runs.size();
  fs::create_directories(fs::path(settings.out_dir) / "runs");
  const OutputLock lock(settings.out_dir);
  std::signal(SIGPIPE, SIG_IGN);  // a closed stdout (| head) must not kill the batch
  const std::string csv = results_path(settings.out_dir);
  const std::string manifest_path = (fs::path(settings.out_dir) / "batch.manifest").string();
  const std::string manifest = manifest_of(runs);

  if (settings.resume && fs::exists(csv)) {
    if (!fs::exists(manifest_path) || read_text(manifest_path) != manifest)
      throw InputError(settings.out_dir, 0,
                       "--resume: the results there were made with other settings (scenarios, their "
                       "contents or --set values changed); use another --out");
    for (auto& [index, row] : read_results_csv(csv)) {
      if (index >= runs.size() || !row_matches(row, runs[index]))
        throw InputError(csv, static_cast<int>(index) + 2,
                         "--resume: run " + std::to_string(index) +
                             " was not this run of this batch (other scenarios or values); use another --out");
      const auto status = row.cells.find("status");
      if (status != row.cells.end() && is_finished_status(status->second))
        result.rows[index] = std::move(row);  // error rows are run again
    }
    result.skipped = result.rows.size();
  }
  write_file_atomically(manifest_path, manifest);
  ResultsFile results_file(csv);
  if (!results_file.write(results_csv(settings.swept, result.rows))) throw std::runtime_error(results_file.error());

  std::vector<ProcessJob> jobs;
  std::vector<const RunSpec*> not_loaded;
  std::vector<std::string> run_dirs(runs.size());
  const std::string self = self_executable();
  for (const RunSpec& run : runs) {
    run_dirs[run.index] = run_dir_name(run, runs.size());
    if (result.rows.count(run.index)) continue;
    const fs::path dir = fs::path(settings.out_dir) / run_dirs[run.index];
    fs::remove_all(dir);  // a stale or half-written run of an earlier batch
    if (!run.load_error.empty()) {
      not_loaded.push_back(&run);  // an error row with the file's message; no worker
      continue;
    }
    ProcessJob job;
    job.id = run.index;
    job.timeout = settings.timeout;
    job.argv = {self, "run", run.scenario, "--out", dir.string(), "--quiet"};
    for (const std::string& item : run.set) {
      job.argv.push_back("--set");
      job.argv.push_back(item);
    }
    jobs.push_back(std::move(job));
  }
  if (!settings.quiet && result.skipped > 0)
    std::printf("resuming: %zu of %zu runs already done, %zu to run\n", result.skipped, runs.size(), jobs.size());

  Progress progress(jobs.size() + not_loaded.size(), settings.quiet);
  for (const RunSpec* run : not_loaded) {
    ResultRow row = load_error_row(*run);
    progress.finished(*run, row);
    result.rows[run->index] = std::move(row);
  }
  auto last_write = Clock::now();
  const bool completed = run_processes(
      jobs, settings.jobs,
      [&](const ProcessJob& job, const ProcessResult& process) {
        const RunSpec& run = runs[job.id];
        ResultRow row = make_row(run, settings.out_dir, run_dirs[job.id], settings.timeout, process);
        progress.finished(run, row);
        result.rows[job.id] = std::move(row);
        // Each run's own summary.json is already on disk; results.csv is rewritten at most once a
        // second (and at the end), so a batch of many thousands of runs stays linear.
        // A rewrite that fails (a full disk) stops nothing: the previous complete file stays, the
        // batch goes on and tries again with the next finished run.
        if (Clock::now() - last_write >= std::chrono::seconds(1) || !results_file.error().empty()) {
          const bool had_error = !results_file.error().empty();
          if (!results_file.write(results_csv(settings.swept, result.rows)) && !had_error)
            std::fprintf(stderr, "signalsim: %s; the batch goes on and writes it again later\n",
                         results_file.error().c_str());
          last_write = Clock::now();
        }
      },
      [&] { progress.tick(); });
  progress.end();
  result.interrupted = !completed;
  const std::string table = results_csv(settings.swept, result.rows);
  if (!results_file.write(table)) {
    // The finished rows must not be lost: the table goes to stdout instead, after one line that says so.
    result.results_error = results_file.error();
    std::fprintf(stderr, "signalsim: %s; the finished rows follow on stdout\n", result.results_error.c_str());
    std::fwrite(table.data(), 1, table.size(), stdout);
    std::fflush(stdout);
  }
  count(result);
  result.wall = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

std::string batch_summary(const BatchResult& result, const std::string& out_dir) {
  std::string out = std::to_string(result.total) + " run" + (result.total == 1 ? "" : "s") + ": " +
                    std::to_string(result.passed) + " passed, " + std::to_string(result.failed) + " failed, " +
                    std::to_string(result.no_expectations) + " without expectations, " +
                    std::to_string(result.errors) + " error" + (result.errors == 1 ? "" : "s");
  if (result.rows.size() < result.total) out += ", " + std::to_string(result.total - result.rows.size()) + " not run";
  if (result.skipped) out += " (" + std::to_string(result.skipped) + " from the earlier results.csv)";
  out += format(" in %.1f s; results: ", result.wall) + results_path(out_dir);
  if (result.interrupted) out += "\ninterrupted: finished runs are kept; run again with --resume to complete";
  return out;
}

}  // namespace signalsim
