// `signalsim check PATH... --golden DIR`: CI regression. Runs each scenario (worker processes, like
// `batch`) and compares its events.csv with DIR/<scenario file stem>.events.csv: the same events in
// the same order (kind, from, to, source), each within --tolerance metres of s_front and one step
// (or --time-tolerance) of time. A differing event or a failed expectation is a failure (exit 1;
// --ignore-expectations makes the expectations a note); a run error, or a scenario file that does
// not load, is an error (exit 4, wins over 1). A scenario without expectations (status
// no_expectations) is checked on its events only and says so; it is not a failure (JUnit: skipped).
// --update rewrites the golden files from the runs; --junit writes JUnit XML. With a decider or light
// judge under test (--decider, --light-judge or the scenario's keys) the golden file must have been made
// with the same ones (batch/golden_suts.hpp), else the case fails. --set, --params and --strict-params
// change every scenario as for batch, so a candidate parameter set is checked against the golden files.
// A --golden folder that is missing or holds none of the scenarios' golden files, and a folder --update
// or --junit cannot write into, are bad input before any run.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>

#include "app/batch_cli.hpp"
#include "app/cli_numbers.hpp"
#include "app/command.hpp"
#include "app/html_report.hpp"
#include "app/junit_report.hpp"
#include "app/override_flags.hpp"
#include "app/sut_flags.hpp"
#include "batch/golden.hpp"
#include "batch/golden_suts.hpp"
#include "batch/interrupt_guard.hpp"
#include "batch/run_list.hpp"
#include "batch/run_outputs.hpp"
#include "batch/scenario_files.hpp"
#include "core/file_paths.hpp"
#include "core/number_text.hpp"
#include "report/atomic_file.hpp"
#include "report/run_files.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"

namespace signalsim::app {
namespace fs = std::filesystem;
namespace {

struct CheckOptions {
  std::vector<std::string> paths;
  std::string golden_dir;
  double tol_s = 0.5;
  double tol_t = 0.0;  // 0: the scenario's step_length
  bool update = false;
  bool ignore_expectations = false;  // a failed expectation is a note, not a failure
  bool expectations_flag = false;    // --expectations: the default behaviour, accepted
  std::string junit;
  BatchCliOptions batch;
  std::vector<std::string> set;  ///< --set, --params, --strict-params, --decider, --light-judge, --sut-timeout
  SutFlags suts;
};

// Compares (or updates) one run; prints its verdict and returns its JUnit case.
JUnitCase check_one(const RunSpec& run, const ResultRow* row, const CheckOptions& o, const std::string& out_dir) {
  const std::string run_dir = row ? (fs::path(out_dir) / row_cell(*row, "run_dir")).string() : std::string();
  JUnitCase c = junit_case(run, row ? summary_or_null(run_dir) : nlohmann::ordered_json());
  const std::string golden = (fs::path(o.golden_dir) / (c.name + ".events.csv")).string();
  auto verdict = [&](JUnitCase::Result result, const std::string& message, const std::string& details = "") {
    c.result = result;
    c.message = message;
    c.details = details;
    if (!o.junit.empty() && !run_dir.empty()) attach_pictures(c, run_dir);  // a failed case's pictures
    const char* tag = result == JUnitCase::Result::Failed ? "FAIL " : result == JUnitCase::Result::Error ? "ERROR" : "ok   ";
    std::printf("%s %s: %s\n%s", tag, c.name.c_str(), message.c_str(), details.c_str());
    for (std::size_t at = 0; at < c.system_out.size();) {  // the failed expectations, indented
      const std::size_t end = c.system_out.find('\n', at);
      std::printf("      %s\n", c.system_out.substr(at, end - at).c_str());
      at = end == std::string::npos ? c.system_out.size() : end + 1;
    }
    return c;
  };
  if (!row) return verdict(JUnitCase::Result::Error, "the run did not finish");
  c.time = std::atof(row_cell(*row, "wall_time").c_str());
  if (row_cell(*row, "status") == "error") return verdict(JUnitCase::Result::Error, "run error: " + row_cell(*row, "error"));

  const std::string events_path = (fs::path(run_dir) / run_files::kEvents).string();
  std::vector<TimelineEvent> events;
  double step = 0.1;
  GoldenSuts suts;  // the decider and light judge that made this run's events
  try {
    events = read_events_csv(events_path);
    const auto summary = read_json_file((fs::path(run_dir) / run_files::kSummary).string());
    step = summary.value("step_length", 0.1);
    suts = run_suts(summary);
    c.system_out += failures_of(summary);
  } catch (const std::exception& e) {
    return verdict(JUnitCase::Result::Error, e.what());
  }
  const bool no_expectations = row_cell(*row, "status") == "no_expectations";
  // A failed run: its failed expectations and, when any, how many law verdicts failed (summary.json law).
  const std::string law_failed = row_cell(*row, "law_failed");
  const bool law_fails = !law_failed.empty() && law_failed != "0";
  const std::string expectations_part = !row_cell(*row, "failed_expectations").empty() || !law_fails
                                            ? "expectations failed: " + row_cell(*row, "failed_expectations")
                                            : "";
  const std::string law_part = law_fails ? "law verdicts failed: " + law_failed : "";
  const std::string failed_expectations =
      row_cell(*row, "status") == "failed"
          ? expectations_part + (!expectations_part.empty() && law_fails ? "; " : "") + law_part
          : "";
  const bool expectations_fail = !failed_expectations.empty() && !o.ignore_expectations;
  const std::string note = !failed_expectations.empty() && !expectations_fail
                               ? " (note: " + failed_expectations + ", ignored: --ignore-expectations)"
                           : no_expectations ? " (note: the scenario has no expectations: only its events are checked)"
                                             : "";
  // The events matched: the expectations decide; without any the case is skipped (JUnit).
  const auto matched = [&](const std::string& message) {
    if (expectations_fail) return verdict(JUnitCase::Result::Failed, failed_expectations + "; " + message);
    return verdict(no_expectations ? JUnitCase::Result::Skipped : JUnitCase::Result::Passed, message + note);
  };

  if (o.update) {
    // A golden file records accepted behaviour: never accept a run whose expectations failed.
    if (!failed_expectations.empty())
      return verdict(JUnitCase::Result::Failed, "not updated: " + failed_expectations);
    fs::create_directories(o.golden_dir);
    write_file_atomically(golden, read_text_file(events_path));
    write_golden_suts(golden, suts);
    return matched(format_text("updated %s (%zu events)", golden.c_str(), events.size()));
  }
  if (const std::string problem = input_file_problem(golden); problem == "not found")
    return verdict(JUnitCase::Result::Failed, "no golden file " + golden + " (create it with --update)");
  else if (!problem.empty())
    return verdict(JUnitCase::Result::Error, golden + ": " + problem);  // a folder, a named pipe: never opened
  std::vector<TimelineEvent> expected;
  GoldenSuts golden_suts;
  try {
    expected = read_events_csv(golden);
    golden_suts = read_golden_suts(golden);
  } catch (const std::exception& e) {
    return verdict(JUnitCase::Result::Error, e.what());
  }
  // Events of one implementation are no golden for another's (docs/batch.md).
  if (golden_suts != suts)
    return verdict(JUnitCase::Result::Failed, golden + " was made with " + describe(golden_suts) + ", this run has " +
                                                  describe(suts) + " (make one for it with --update)");
  const double tol_t = o.tol_t > 0 ? o.tol_t : step;
  const auto diff = compare_events(expected, events, o.tol_s, tol_t);
  const std::size_t differences = count_differences(diff);
  if (differences > 0) {
    const std::string header =
        format_text("         %9s   %9s    event    (= same, ~ moved, - missing, + extra; tolerance %.3g m, %.3g s)\n",
                    "time", "s_front", o.tol_s, tol_t);
    return verdict(
        JUnitCase::Result::Failed,
        (expectations_fail ? failed_expectations + "; " : std::string()) +
            format_text("%zu event difference%s against %s", differences, differences == 1 ? "" : "s", golden.c_str()) +
            note,
        header + format_diff(diff, "      "));
  }
  return matched(format_text("%zu events match %s", events.size(), golden.c_str()));
}

// The golden folder of a comparison (not --update): a folder holding the golden file of at least one
// of the scenarios; else every case would fail alike on a path mistyped in CI.
void check_golden_folder(const std::string& dir, const std::vector<std::string>& files) {
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) throw InputError("--golden", 0, "folder '" + dir + "' not found");
  if (!fs::is_directory(status)) throw InputError("--golden", 0, "'" + dir + "' is not a folder");
  for (const std::string& f : files)
    if (fs::exists(fs::path(dir) / (fs::path(f).stem().string() + ".events.csv"), ec)) return;
  const std::string which = files.size() == 1 ? "the scenario's golden file (" + fs::path(files[0]).stem().string() + ".events.csv)"
                                              : "the golden file (<scenario>.events.csv) of any of the " +
                                                    std::to_string(files.size()) + " scenarios";
  throw InputError("--golden", 0, "folder '" + dir + "' does not hold " + which + "; make golden files with --update");
}

// Where check writes after the runs, checked before them.
void check_destinations(const CheckOptions& o, const std::vector<std::string>& files) {
  if (o.update) check_writable_folder(o.golden_dir, "--update");
  else check_golden_folder(o.golden_dir, files);
  if (!o.junit.empty()) check_junit_destination(o.junit);
}

}  // namespace

Command add_check_command(CLI::App& app) {
  auto o = std::make_shared<CheckOptions>();
  CLI::App* sub = app.add_subcommand("check", "CI regression: run scenarios and compare their events with golden files");
  sub->add_option("paths", o->paths, "Scenario files or directories of them (*.yaml)")->required();
  sub->add_option("--golden", o->golden_dir, "Directory of golden files <scenario file stem>.events.csv")->required();
  sub->add_option("--tolerance", o->tol_s, "Largest |ds| of an event's s_front, metres")
      ->capture_default_str()
      ->check(non_negative_number());
  sub->add_option("--time-tolerance", o->tol_t, "Largest |dt| of an event's time, seconds (default: one step)")
      ->check(non_negative_number());
  sub->add_flag("--update", o->update, "Rewrite the golden files from this run");
  sub->add_flag("--ignore-expectations", o->ignore_expectations,
                "A failed expectation is only a note (by default it fails the check, as a differing event does)");
  sub->add_flag("--expectations", o->expectations_flag,
                "A failed expectation fails the check: the default (accepted for old scripts)")
      ->excludes("--ignore-expectations");
  sub->add_option("--junit", o->junit, "Also write the results as JUnit XML to this file");
  add_override_flags(sub, o->set);  // before the SUT flags, which append to the same overrides
  add_batch_options(sub, o->batch, "out/check", false);
  add_sut_flags(sub, o->set, o->suts);
  return {sub, [o]() -> int {
            const InterruptGuard signals;  // Ctrl-C or SIGTERM while the scenarios load: exit 130, nothing ran
            try {
              hold_notes();  // until every scenario loaded: a bad --set or --params is one line
              const std::vector<std::string> files = scenario_files(o->paths);
              std::map<std::string, std::string> stems;
              for (const std::string& f : files) {
                const auto [it, fresh] = stems.emplace(fs::path(f).stem().string(), f);
                if (!fresh)
                  throw InputError(f, 0, "same golden name '" + it->first + "' as " + it->second + " (file names must differ)");
              }
              const std::vector<RunSpec> runs = suite_runs(files, o->set);
              check_destinations(*o, files);  // after the overrides' own errors, before any run
              release_notes();
              BatchSettings settings = to_settings(o->batch, "out/check", 300.0);
              settings.quiet = settings.quiet || isatty(STDOUT_FILENO) != 1;  // the verdicts below say it all
              const BatchResult result = run_batch(runs, settings);
              const CommandFacts facts{"check", o->paths, "", o->golden_dir, o->set, {}, settings.jobs};
              if (result.interrupted) {
                write_command_facts(settings.out_dir, facts);  // and no report or verdicts of an earlier check
                std::printf("%s\n", batch_summary(result, settings.out_dir).c_str());
                return kExitInterrupted;
              }
              std::vector<JUnitCase> cases;
              std::size_t failed = 0, errors = 0;
              for (const RunSpec& run : runs) {
                const auto row = result.rows.find(run.index);
                cases.push_back(check_one(run, row == result.rows.end() ? nullptr : &row->second, *o, settings.out_dir));
                failed += cases.back().result == JUnitCase::Result::Failed;
                errors += cases.back().result == JUnitCase::Result::Error;
              }
              // Scenarios without expectations pass on their events alone: counted apart, not failed.
              std::printf("check: %zu scenario%s, %zu passed, %zu failed, %zu error%s; %zu without expectations%s\n",
                          cases.size(), cases.size() == 1 ? "" : "s", cases.size() - failed - errors, failed, errors,
                          errors == 1 ? "" : "s", result.no_expectations, o->update ? " (golden files updated)" : "");
              if (!o->junit.empty()) write_junit(o->junit, "signalsim check", cases, result.wall);
              write_command_facts(settings.out_dir, facts);
              write_check_record(settings.out_dir, cases);
              const int code = errors > 0 ? kExitRunErrors : failed > 0 ? kExitFailed : 0;
              return finish_with_report(code, o->batch.report, settings.out_dir, settings.jobs, o->batch.quiet);
            } catch (const BatchInterrupted& e) {
              return report_interrupted(e.what());
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
