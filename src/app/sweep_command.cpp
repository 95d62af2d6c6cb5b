// `signalsim sweep FILE`: a grid (and zipped lists) of runs over scenarios and `--set` values. The runs
// are made one at a time from the file (sweep --list of a million runs holds none of them whole) and
// checked before any starts (batch/sweep_check.hpp).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "app/batch_backend.hpp"
#include "app/batch_cli.hpp"
#include "app/command.hpp"
#include "app/html_report.hpp"
#include "app/plot_tool.hpp"
#include "app/sut_flags.hpp"
#include "batch/interrupt_guard.hpp"
#include "batch/results_table.hpp"
#include "batch/run_list.hpp"
#include "batch/sweep_check.hpp"
#include "batch/sweep_file.hpp"
#include "batch/sweep_plot_check.hpp"
#include "batch/sweep_keys.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"

namespace signalsim::app {
namespace {

// Prints the runs one at a time (a grid of a million runs is never held whole), until stdout fails (a
// closed pipe, | head: SIGPIPE is ignored while the caller's InterruptGuard lives, and all is flushed then).
void list_runs(const SweepRuns& runs) {
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (i % 4096 == 0) {
      InterruptGuard::throw_if_interrupted();
      if (std::ferror(stdout)) break;
    }
    const RunSpec run = runs.at(i);
    std::printf("%4zu  %s", run.index, run.scenario.c_str());
    for (const auto& [key, value] : run.values) std::printf("  %s=%s", key.c_str(), value.c_str());
    std::printf("\n");
  }
  std::fflush(stdout);
}

// Every run, named, for the back-end.
std::vector<RunSpec> named_runs(const SweepRuns& runs, const SweepCheck& check) {
  std::vector<RunSpec> out;
  out.reserve(runs.size());
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (i % 4096 == 0) InterruptGuard::throw_if_interrupted();
    out.push_back(runs.at(i));
    out.back().name = check.name_of(out.back());
  }
  return out;
}

// A plot: axis as its results.csv column: the axes are swept keys (or scenario), and a swept key's
// column may be renamed (swept_column).
std::string plot_axis(const std::string& key) { return key == "scenario" ? key : swept_column(key); }

// One picture per plot: entry (signalsim-plot's defaults without one); whether one failed.
bool draw_plots(const Sweep& sweep, const std::string& out_dir) {
  const std::vector<SweepPlot> plots = sweep.plots.empty() ? std::vector<SweepPlot>{{}} : sweep.plots;
  bool failed = false;
  for (const SweepPlot& plot : plots) {
    std::vector<std::string> args = {out_dir};
    if (!plot.metric.empty()) args.insert(args.end(), {"--metric", plot.metric});
    if (!plot.x.empty()) args.insert(args.end(), {"--x", plot_axis(plot.x)});
    if (!plot.y.empty()) args.insert(args.end(), {"--y", plot_axis(plot.y)});
    failed = run_plot_tool(args) != 0 || failed;
  }
  return failed;
}

// What the report's first screen says of the sweep: its file, the overrides, its plot: axes as columns.
CommandFacts sweep_facts(const Sweep& sweep, const std::string& file, const std::vector<std::string>& set, int jobs) {
  CommandFacts facts{"sweep", {file}, file, "", set, {}, jobs};
  for (const SweepPlot& plot : sweep.plots)
    if (!plot.metric.empty() && !plot.x.empty() && !plot.y.empty())
      facts.plots.push_back({plot.metric, plot_axis(plot.x), plot_axis(plot.y)});
  return facts;
}

}  // namespace

Command add_sweep_command(CLI::App& app) {
  struct Options {
    std::string file;
    BatchCliOptions batch;
    BackendCliOptions backend;
    bool plot = false;
    bool list = false;
    std::vector<std::string> set;  // the overrides of --decider, --light-judge, --sut-timeout
    SutFlags suts;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("sweep", "Run a sweep file: scenarios x grid x zipped values; results.csv");
  sub->add_option("file", o->file, "Sweep file (YAML, see docs/batch.md)")->required();
  add_batch_options(sub, o->batch, "the file's out:, else out/<sweep name>", true);
  sub->add_flag("--plot", o->plot, "Draw the file's plot: (a heat map of a metric over two swept keys) with signalsim-plot");
  sub->add_flag("--list", o->list, "Print the runs and exit without running them");
  add_backend_options(sub, o->backend);
  add_sut_flags(sub, o->set, o->suts);
  return {sub, [o]() -> int {
            // Ctrl-C or SIGTERM while the sweep is read, expanded and checked: exit 130, nothing ran.
            std::optional<InterruptGuard> signals;
            signals.emplace();
            try {
              hold_notes();  // until every run is checked: bad input is one line
              const Sweep sweep = load_sweep(o->file);
              for (const std::string& key : swept_keys(sweep))
                if ((key == "decider" && !o->suts.decider.empty()) || (key == "light_judge" && !o->suts.light_judge.empty()))
                  throw InputError(key == "decider" ? "--decider" : "--light-judge", 0,
                                   "the sweep file " + o->file + " sweeps " + key + " itself");
              const SweepRuns runs(sweep, o->set);
              const SweepCheck check(runs);
              check_sweep_plot(runs);  // a plot: no run can give is refused before any run
              const std::string default_out = sweep.out.empty() ? "out/" + sweep.name : sweep.out;
              const double timeout = sweep.timeout.value_or(*sweep_keys().at("timeout").default_number);
              BatchSettings settings = to_settings(o->batch, default_out, timeout);
              settings.swept = swept_keys(sweep);
              if (o->list) {
                release_notes();  // else run_with_backend releases them once the back-end is there
                list_runs(runs);
                return 0;
              }
              const BackendRun run = run_with_backend(named_runs(runs, check), settings, o->batch, o->backend);
              signals.reset();  // the runs are over: the pictures are the plot tool's
              if (!run.merged) return 0;  // --no-wait: submitted; --collect merges (and --plot draws) later
              const BatchResult& result = run.result;
              // The pictures were asked for: a failure is a failure of the command (exit 3, kExitPicture), after
              // the runs' own failures (their code wins when it is not 0).
              int code = result.exit_code();
              if (o->plot && !result.interrupted && draw_plots(sweep, settings.out_dir) && code == 0) code = kExitPicture;
              write_command_facts(settings.out_dir, sweep_facts(sweep, o->file, o->set, settings.jobs));
              return finish_with_report(code, result.interrupted ? "" : o->batch.report, settings.out_dir, settings.jobs,
                                        settings.quiet);
            } catch (const BatchInterrupted& e) {
              return report_interrupted(e.what());
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
