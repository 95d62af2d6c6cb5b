// `signalsim compare PATH... --out DIR` (docs/compare.md): every scenario twice on the same route and traffic,
// driven by signalsim and by SUMO on its own (run --driver sumo), then OUT/comparison.csv, the
// picture OUT/comparison.png (signalsim-plot) and a one-screen summary. With --decider / --light-judge
// three times: the system under test in signalsim ("sut"), signalsim's reference alone, and SUMO.
//
//   check    every scenario is loaded and its route planned, no SUMO (bad input: one line, exit 2,
//            nothing written; a comparison.csv/png left in OUT by an earlier compare is removed)
//   run      per scenario NNNN one worker per driver, OUT/runs/NNNN-<name>-[sut, ]signalsim and -sumo
//            (same seed and --set values), at most --jobs at a time, each with the wall-clock --timeout
//   table    app/comparison: one row per section or light and driver; a run that did not finish
//            gives error rows
//   picture  signalsim-plot OUT/comparison.csv --out OUT
// Exit codes: 0 every run finished and no signalsim (or sut) run failed an expectation (the SUMO runs'
// expectation results are reported, not judged: they measure SUMO against the decider's law),
// 1 a signalsim run failed or any run errored, 2 bad input, 3 the runs were fine but the picture
// could not be drawn, 130 interrupted (no comparison written).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "app/batch_cli.hpp"
#include "app/command.hpp"
#include "app/html_report.hpp"
#include "app/plot_tool.hpp"
#include "app/override_flags.hpp"
#include "app/sut_flags.hpp"
#include "batch/child_process.hpp"
#include "batch/comparison.hpp"
#include "batch/run_outputs.hpp"
#include "batch/scenario_files.hpp"
#include "batch/worker_pool.hpp"
#include "report/atomic_file.hpp"
#include "report/expectations.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"
#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"
#include "net/net_index.hpp"
#include "report/run_files.hpp"

namespace signalsim::app {
namespace fs = std::filesystem;
namespace {

constexpr const char* kCsv = "comparison.csv";
constexpr const char* kPicture = "comparison.png";

struct CompareOptions {
  std::vector<std::string> paths;
  std::vector<std::string> set;
  std::vector<std::string> sut_set;  ///< the overrides of --decider, --light-judge, --sut-timeout
  SutFlags suts;
  BatchCliOptions batch;
};

// The drivers of each scenario and the overrides each adds to --set: with a decider or light judge
// under test, "sut" (signalsim with it), "signalsim" (the reference alone) and "sumo"; else
// "signalsim" (the scenario as written) and "sumo". SUMO's run never has a SUT in the loop.
struct DriverPlan {
  std::string name;
  std::string driver;  ///< run --driver
  std::vector<std::string> set;
};

std::vector<DriverPlan> driver_plans(const CompareOptions& o) {
  const std::vector<std::string> reference = {"decider=reference", "light_judge=reference"};
  std::vector<DriverPlan> plans;
  if (o.suts.any()) {
    plans.push_back({"sut", "signalsim", o.sut_set});
    plans.push_back({"signalsim", "signalsim", reference});
  } else {
    plans.push_back({"signalsim", "signalsim", {}});
  }
  plans.push_back({"sumo", "sumo", reference});
  return plans;
}

// One scenario as checked before anything runs.
struct Checked {
  std::string file;
  ScenarioComparison comparison;
};

// Loads every scenario with the overrides and plans its route (nets read once each). Throws
// InputError / sumo::NetError for the first bad one.
std::vector<Checked> check_scenarios(const std::vector<std::string>& files, const std::vector<std::string>& set) {
  std::map<std::string, sumo::NetIndex> nets;
  std::vector<Checked> out;
  for (const std::string& file : files) {
    const Scenario scenario = load_scenario(file, ScenarioOverrides{set});
    if (!scenario.has_ego)  // an egoless fleet run (docs/fleet.md "Without an ego")
      throw InputError(file, 0, "compare drives the ego with signalsim and with SUMO, and the scenario has none");
    auto net = nets.find(scenario.net);
    if (net == nets.end()) net = nets.emplace(scenario.net, sumo::NetIndex::load(scenario.net)).first;
    const PlannedRun planned = plan_run(scenario, net->second);
    check_expectations_apply(planned.scenario, planned.plan.map);
    Checked c;
    c.file = file;
    c.comparison.scenario = scenario.name;
    c.comparison.base_link_to_front = planned.scenario.ego.base_link_to_front;
    c.comparison.items = compared_items(planned.plan.map, planned.scenario.run_params.decider);
    out.push_back(std::move(c));
  }
  return out;
}

// "runs/0003-intersection_left-sumo"
std::string run_dir_name(std::size_t index, const std::string& name, const std::string& driver) {
  std::string safe;
  for (const char c : name) safe += (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-') ? c : '_';
  char prefix[32];
  std::snprintf(prefix, sizeof prefix, "%s/%04zu-", run_files::kRunsDir, index);
  return prefix + safe + "-" + driver;
}

// A finished worker's run: its summary, or why there is none.
DriverRun driver_run(const std::string& out_dir, const std::string& run_dir, const std::string& driver,
                     const ProcessResult& result, double timeout) {
  DriverRun run;
  run.driver = driver;
  run.run_dir = run_dir;
  run.status = "error";
  const std::string message = stderr_one_line(result.stderr_text);
  if (result.timed_out) {
    char text[128];
    std::snprintf(text, sizeof text, "timed out: still running after the %g s limit (worker killed)", timeout);
    run.error = text;
    return run;
  }
  if (!result.exited) {
    run.error = "worker killed by " + signal_name(result.signal) + (message.empty() ? "" : ": " + message);
    return run;
  }
  if (result.exit_code != 0 && result.exit_code != 1) {
    run.error = message.empty() ? "exit code " + std::to_string(result.exit_code) : message;
    return run;
  }
  const fs::path dir = fs::path(out_dir) / run_dir;
  try {
    run.summary = read_json_file((dir / run_files::kSummary).string());
    const std::string status = run.summary.value("status", "");
    if (!is_finished_status(status)) {
      run.error = run.summary.value("error", "summary.json status '" + status + "'");
      return run;
    }
    run.status = status;
  } catch (const std::exception& e) {
    run.error = "exit code " + std::to_string(result.exit_code) + " but " + e.what();
  }
  return run;
}

// A bad-input exit: the comparison files (and the HTML report) of an earlier compare must not pass for this one's.
int bad_input(const std::string& out_dir, const std::string& message) {
  std::error_code ignored;
  for (const char* name : {kCsv, kPicture}) fs::remove(fs::path(out_dir) / name, ignored);
  remove_html_report(out_dir);
  return report_bad_input(message);
}

int compare(const CompareOptions& o) {
  const auto start = std::chrono::steady_clock::now();
  const BatchSettings settings = to_settings(o.batch, "out/compare", 300.0);
  std::vector<Checked> scenarios;
  if (o.paths.empty()) return bad_input(settings.out_dir, "compare: no scenario given (signalsim compare PATH... --out DIR)");
  try {
    std::vector<std::string> set = o.set;
    set.insert(set.end(), o.sut_set.begin(), o.sut_set.end());
    hold_notes();  // bad input is one line: the notes of the scenarios loaded before it are not printed
    scenarios = check_scenarios(scenario_files(o.paths), set);
    release_notes();
  } catch (const std::exception& e) {
    return bad_input(settings.out_dir, e.what());
  }
  const std::vector<DriverPlan> plans = driver_plans(o);
  const std::size_t n = plans.size();
  std::vector<ProcessJob> jobs;
  std::vector<std::string> run_dirs;
  try {
    fs::create_directories(fs::path(settings.out_dir) / run_files::kRunsDir);
    for (const char* name : {kCsv, kPicture}) fs::remove(fs::path(settings.out_dir) / name);
    remove_html_report(settings.out_dir);  // an interrupted compare leaves no report of an earlier one
    const std::string self = self_executable();
    for (std::size_t i = 0; i < scenarios.size(); ++i)
      for (const DriverPlan& plan : plans) {
        const std::string dir = run_dir_name(i, scenarios[i].comparison.scenario, plan.name);
        fs::remove_all(fs::path(settings.out_dir) / dir);  // a stale run of an earlier compare
        ProcessJob job;
        job.id = run_dirs.size();
        job.timeout = settings.timeout;
        job.argv = {self, "run", scenarios[i].file, "--out", (fs::path(settings.out_dir) / dir).string(), "--quiet",
                    "--driver", plan.driver};
        for (const std::string& item : o.set) job.argv.insert(job.argv.end(), {"--set", item});
        for (const std::string& item : plan.set) job.argv.insert(job.argv.end(), {"--set", item});
        jobs.push_back(std::move(job));
        run_dirs.push_back(dir);
      }
  } catch (const std::exception& e) {
    return bad_input(settings.out_dir, settings.out_dir + ": " + e.what());
  }
  if (!settings.quiet) {
    std::string names;
    for (const DriverPlan& plan : plans) names += (names.empty() ? "" : ", ") + plan.name;
    std::printf("compare: %zu scenario%s x %zu drivers (%s), %d at a time -> %s\n", scenarios.size(),
                scenarios.size() == 1 ? "" : "s", n, names.c_str(), settings.jobs, settings.out_dir.c_str());
    std::fflush(stdout);
  }

  std::vector<DriverRun> runs(jobs.size());
  const bool completed = run_jobs(jobs, settings.jobs, settings.isolate, [&](const ProcessJob& job, const ProcessResult& result) {
    runs[job.id] = driver_run(settings.out_dir, run_dirs[job.id], plans[job.id % n].name, result, settings.timeout);
  });
  if (!completed) {
    std::printf("interrupted: no comparison written; the finished runs are in %s/runs\n", settings.out_dir.c_str());
    return kExitInterrupted;
  }
  std::vector<ScenarioComparison> table;
  bool failed = false;
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    ScenarioComparison c = std::move(scenarios[i].comparison);
    for (std::size_t d = 0; d < n; ++d) {
      c.runs.push_back(std::move(runs[n * i + d]));
      // signalsim's runs (the SUT's too) are judged by their expectations; SUMO's are only reported.
      const DriverRun& r = c.runs.back();
      failed = failed || r.status == "error" || (plans[d].driver == "signalsim" && r.status == "failed");
    }
    table.push_back(std::move(c));
  }
  const std::string csv = (fs::path(settings.out_dir) / kCsv).string();
  try {
    write_file_atomically(csv, comparison_csv(table));
  } catch (const std::exception& e) {
    return report_bad_input(e.what());
  }
  const int plotted = run_plot_tool({csv, "--out", settings.out_dir, "--quiet"});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!settings.quiet) {
    std::size_t errors = 0;
    for (const ScenarioComparison& c : table)
      for (const DriverRun& r : c.runs) errors += r.status == "error";
    std::printf("%s", comparison_screen(table).c_str());
    std::printf("%zu runs, %zu error%s in %.1f s; comparison: %s%s\n", jobs.size(), errors, errors == 1 ? "" : "s",
                wall, csv.c_str(),
                plotted == 0 ? (", " + (fs::path(settings.out_dir) / kPicture).string()).c_str() : " (no picture)");
  }
  std::vector<std::string> overrides = o.set;
  overrides.insert(overrides.end(), o.sut_set.begin(), o.sut_set.end());
  write_command_facts(settings.out_dir, {"compare", o.paths, "", "", overrides, {}, settings.jobs});
  return finish_with_report(failed ? kExitFailed : plotted == 0 ? 0 : kExitPicture, o.batch.report, settings.out_dir,
                            settings.jobs, settings.quiet);
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto o = std::make_shared<CompareOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare", "Run each scenario driven by signalsim and by SUMO alone; comparison.csv and comparison.png");
  // Not required() for CLI11: with no path, compare itself refuses (and removes an earlier comparison).
  sub->add_option("paths", o->paths, "Scenario files or directories of them (*.yaml)");
  add_override_flags(sub, o->set);
  add_sut_flags(sub, o->sut_set, o->suts);
  add_batch_options(sub, o->batch, "out/compare", false);
  return {sub, [o] { return compare(*o); }};
}

}  // namespace signalsim::app
