// --report, OUT/command.json, OUT/check.json and signalsim-plot report: see html_report.hpp.
#include "app/html_report.hpp"

#include <sys/utsname.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/command.hpp"
#include "app/plot_tool.hpp"
#include "report/atomic_file.hpp"
#include "report/exit_codes.hpp"

namespace signalsim::app {
namespace fs = std::filesystem;
namespace {

struct CommandLine {
  std::vector<std::string> argv;
  std::chrono::system_clock::time_point started = std::chrono::system_clock::now();
  std::chrono::steady_clock::time_point steady_start = std::chrono::steady_clock::now();
};

CommandLine& command_line() {
  static CommandLine line;
  return line;
}

// 2026-12-06T22:45:00Z
std::string utc_text(std::chrono::system_clock::time_point when) {
  const std::time_t t = std::chrono::system_clock::to_time_t(when);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return text;
}

std::string host_name() {
  char name[256] = {};
  return gethostname(name, sizeof name - 1) == 0 ? name : "";
}

std::string system_name() {
  utsname u{};
  if (uname(&u) != 0) return "";
  return std::string(u.sysname) + " " + u.release + " " + u.machine;
}

const char* check_status(JUnitCase::Result result) {
  switch (result) {
    case JUnitCase::Result::Failed: return "failed";
    case JUnitCase::Result::Error: return "error";
    case JUnitCase::Result::Skipped: return "skipped";
    case JUnitCase::Result::Passed: break;
  }
  return "passed";
}

// JSON text of `j`; a byte of a name or message that is not UTF-8 (a file name in Latin-1 on the
// command line) becomes U+FFFD rather than an exception after the runs.
std::string json_text(const nlohmann::ordered_json& j) {
  return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void write_or_warn(const fs::path& path, const std::string& text) {
  try {
    write_file_atomically(path.string(), text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "signalsim: warning: %s\n", e.what());
  }
}

}  // namespace

void remember_command_line(int argc, char** argv) {
  CommandLine& line = command_line();
  line.argv.assign(argv, argv + argc);
  line.started = std::chrono::system_clock::now();
  line.steady_start = std::chrono::steady_clock::now();
}

void add_report_flag(CLI::App* sub, std::string& mode) {
  sub->add_flag("--report{failed}", mode,
                "Also write OUT/report.html (docs/report.md); --report=all draws the pictures of every run, not "
                "only of failed and errored ones")
      ->check(CLI::IsMember({"failed", "all"}));
}

void write_command_facts(const std::string& out_dir, const CommandFacts& facts) {
  const CommandLine& line = command_line();
  const auto now = std::chrono::system_clock::now();
  nlohmann::ordered_json j;
  j["format"] = 1;
  j["command"] = facts.command;
  j["argv"] = line.argv;
  j["inputs"] = facts.inputs;
  if (!facts.sweep_file.empty()) j["sweep_file"] = facts.sweep_file;
  if (!facts.golden.empty()) j["golden"] = facts.golden;
  j["set"] = facts.set;
  if (!facts.plots.empty()) {
    j["sweep_plots"] = nlohmann::ordered_json::array();
    for (const auto& p : facts.plots) j["sweep_plots"].push_back({{"metric", p.metric}, {"x", p.x}, {"y", p.y}});
  }
  j["started"] = utc_text(line.started);
  j["finished"] = utc_text(now);
  j["wall_time"] = std::round(std::chrono::duration<double>(std::chrono::steady_clock::now() - line.steady_start).count() * 1000) / 1000;
  j["host"] = host_name();
  j["system"] = system_name();
  j["cores"] = std::thread::hardware_concurrency();
  j["jobs"] = facts.jobs;
  j["version"] = kVersionText;
  remove_html_report(out_dir);  // an earlier command's must not pass for this one's: --report writes it anew
  write_or_warn(fs::path(out_dir) / kCommandFacts, json_text(j));
}

void remove_html_report(const std::string& out_dir) {
  std::error_code ignored;
  fs::remove(fs::path(out_dir) / kReportPage, ignored);
  fs::remove_all(fs::path(out_dir) / kReportDir, ignored);
  fs::remove(fs::path(out_dir) / kCheckRecord, ignored);  // an earlier check's verdicts are not this command's
}

void write_check_record(const std::string& out_dir, const std::vector<JUnitCase>& cases) {
  nlohmann::ordered_json j;
  j["format"] = 1;
  j["cases"] = nlohmann::ordered_json::array();
  for (const JUnitCase& c : cases)
    j["cases"].push_back({{"name", c.name}, {"file", c.file}, {"status", check_status(c.result)}, {"message", c.message},
                          {"details", c.details}, {"system_out", c.system_out}, {"time", c.time}});
  write_or_warn(fs::path(out_dir) / kCheckRecord, json_text(j));
}

int make_html_report(const std::string& out_dir, bool all_pictures, int jobs, bool quiet) {
  std::vector<std::string> args = {"report", out_dir, "--quiet"};
  if (all_pictures) args.push_back("--all");
  if (jobs > 0) args.insert(args.end(), {"--jobs", std::to_string(jobs)});
  // exit 2 (not an output folder) and 3 (not writable) are the tool's one line; others (a crash) also ours
  const int code = run_plot_tool(args, true);
  if (code != 0 && code != kExitBadInput && code != kExitPicture)
    std::fprintf(stderr, "signalsim: the report failed (signalsim-plot exit code %d)\n", code);
  if (code == 0 && !quiet) std::printf("report: %s\n", (fs::path(out_dir) / kReportPage).string().c_str());
  return code;
}

int finish_with_report(int code, const std::string& mode, const std::string& out_dir, int jobs, bool quiet) {
  if (mode.empty()) return code;
  const int made = make_html_report(out_dir, mode == "all", jobs, quiet);
  return made != 0 && code == 0 ? kExitPicture : code;
}

}  // namespace signalsim::app
