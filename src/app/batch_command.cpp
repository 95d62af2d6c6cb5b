// `signalsim batch PATH...`: a suite of scenarios (files or directories), run by persistent workers.
#include <cstdio>
#include <memory>

#include "app/batch_cli.hpp"
#include "app/command.hpp"
#include "app/strict_params_flag.hpp"
#include "batch/run_list.hpp"
#include "batch/scenario_files.hpp"
#include "scenario/input_error.hpp"

namespace signalsim::app {

Command add_batch_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> paths;
    std::vector<std::string> set;
    BatchCliOptions batch;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("batch", "Run a suite of scenarios (files or directories) in parallel; results.csv");
  sub->add_option("paths", o->paths, "Scenario files or directories of them (*.yaml)")->required();
  sub->add_option("--set", o->set, "Override for every run: a scenario key or a parameter (key=value); repeatable");
  add_batch_options(sub, o->batch, "out/batch", true);
  add_strict_params_flag(sub, o->set);
  return {sub, [o]() -> int {
            try {
              const std::vector<RunSpec> runs = suite_runs(scenario_files(o->paths), o->set);
              const BatchSettings settings = to_settings(o->batch, "out/batch", 300.0);
              const BatchResult result = run_batch(runs, settings);
              if (!settings.quiet || result.interrupted) std::printf("%s\n", batch_summary(result, settings.out_dir).c_str());
              return result.exit_code();
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
