// `signalsim batch PATH...`: a suite of scenarios (files or directories), run by persistent workers;
// --junit FILE also writes the results as JUnit XML (app/junit_report.hpp), once results.csv is merged.
#include <cstdio>
#include <memory>

#include "app/batch_backend.hpp"
#include "app/batch_cli.hpp"
#include "app/command.hpp"
#include "app/html_report.hpp"
#include "app/junit_report.hpp"
#include "app/override_flags.hpp"
#include "app/sut_flags.hpp"
#include "batch/interrupt_guard.hpp"
#include "batch/run_list.hpp"
#include "batch/scenario_files.hpp"
#include "scenario/input_error.hpp"
#include "scenario/notes.hpp"

namespace signalsim::app {

Command add_batch_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> paths;
    std::vector<std::string> set;
    BatchCliOptions batch;
    BackendCliOptions backend;
    SutFlags suts;
    std::string junit;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("batch", "Run a suite of scenarios (files or directories) in parallel; results.csv");
  sub->add_option("paths", o->paths, "Scenario files or directories of them (*.yaml)")->required();
  add_override_flags(sub, o->set);
  add_batch_options(sub, o->batch, "out/batch", true);
  add_sut_flags(sub, o->set, o->suts);
  add_backend_options(sub, o->backend);
  sub->add_option("--junit", o->junit,
                  "Also write the results as JUnit XML to this file (a failed run's pictures attached)");
  return {sub, [o]() -> int {
            const InterruptGuard signals;  // Ctrl-C or SIGTERM while the scenarios load: exit 130, nothing ran
            try {
              hold_notes();  // until every scenario loaded: a bad --set or --params is one line
              const std::vector<RunSpec> runs = suite_runs(scenario_files(o->paths), o->set);
              if (!o->junit.empty()) check_junit_destination(o->junit);  // bad input before any run
              // run_with_backend releases the held notes once the back-end is there to run them
              const BatchSettings settings = to_settings(o->batch, "out/batch", 300.0);
              const BackendRun run = run_with_backend(runs, settings, o->batch, o->backend);
              if (!run.merged) return 0;  // --no-wait: submitted; --collect merges later
              if (!o->junit.empty() && !run.result.interrupted)
                write_junit(o->junit, "signalsim batch", batch_junit_cases(runs, run.result.rows, settings.out_dir),
                            run.result.wall);
              write_command_facts(settings.out_dir, {"batch", o->paths, "", "", o->set, {}, settings.jobs});
              return finish_with_report(run.result.exit_code(), run.result.interrupted ? "" : o->batch.report,
                                        settings.out_dir, settings.jobs, settings.quiet);
            } catch (const BatchInterrupted& e) {
              return report_interrupted(e.what());
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
