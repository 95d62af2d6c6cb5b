// `signalsim sweep FILE`: a grid (and zipped lists) of runs over scenarios and `--set` values.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "app/batch_backend.hpp"
#include "app/batch_cli.hpp"
#include "app/command.hpp"
#include "app/plot_tool.hpp"
#include "app/sut_flags.hpp"
#include "batch/results_table.hpp"
#include "batch/run_list.hpp"
#include "batch/sweep_file.hpp"
#include "batch/sweep_plot_check.hpp"
#include "batch/sweep_keys.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"

namespace signalsim::app {

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
            try {
              hold_notes();  // until every run is checked: bad input is one line
              const Sweep sweep = load_sweep(o->file);
              std::vector<RunSpec> runs = expand_sweep(sweep);
              for (const std::string& key : swept_keys(sweep))
                if ((key == "decider" && !o->suts.decider.empty()) || (key == "light_judge" && !o->suts.light_judge.empty()))
                  throw InputError(key == "decider" ? "--decider" : "--light-judge", 0,
                                   "the sweep file " + o->file + " sweeps " + key + " itself");
              for (RunSpec& run : runs) run.set.insert(run.set.end(), o->set.begin(), o->set.end());
              check_sweep_runs(sweep, runs);
              check_sweep_plot(sweep, runs);  // a plot: no run can give is refused before any run
              const std::string default_out = sweep.out.empty() ? "out/" + sweep.name : sweep.out;
              const double timeout = sweep.timeout.value_or(*sweep_keys().at("timeout").default_number);
              BatchSettings settings = to_settings(o->batch, default_out, timeout);
              settings.swept = swept_keys(sweep);
              if (o->list) {
                release_notes();  // else run_with_backend releases them once the back-end is there
                for (const RunSpec& run : runs) {
                  std::printf("%4zu  %s", run.index, run.scenario.c_str());
                  for (const auto& [key, value] : run.values) std::printf("  %s=%s", key.c_str(), value.c_str());
                  std::printf("\n");
                }
                return 0;
              }
              const BackendRun run = run_with_backend(runs, settings, o->batch, o->backend);
              if (!run.merged) return 0;  // --no-wait: submitted; --collect merges (and --plot draws) later
              const BatchResult& result = run.result;
              if (o->plot && !result.interrupted) {
                // One picture per plot: entry (signalsim-plot's defaults without one).
                const std::vector<SweepPlot> plots = sweep.plots.empty() ? std::vector<SweepPlot>{{}} : sweep.plots;
                bool failed = false;
                for (const SweepPlot& plot : plots) {
                  std::vector<std::string> args = {settings.out_dir};
                  if (!plot.metric.empty()) args.insert(args.end(), {"--metric", plot.metric});
                  // the axes are swept keys (or scenario): their columns may be renamed (swept_column)
                  const auto axis = [](const std::string& key) { return key == "scenario" ? key : swept_column(key); };
                  if (!plot.x.empty()) args.insert(args.end(), {"--x", axis(plot.x)});
                  if (!plot.y.empty()) args.insert(args.end(), {"--y", axis(plot.y)});
                  failed = run_plot_tool(args) != 0 || failed;
                }
                // The pictures were asked for: a failure is a failure of the command (exit 3, kExitPicture), after
                // the runs' own failures (their code wins when it is not 0).
                if (failed && result.exit_code() == 0) return kExitPicture;
              }
              return result.exit_code();
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
