// `signalsim run-chunk OUT INDEX`: what one Slurm array task runs (docs/slurm.md): chunk INDEX of
// OUT/slurm/chunks.json with the local pool, --jobs (default $SLURM_CPUS_PER_TASK, else 1) at a
// time, one row file per finished run. Written into task.sh by `--backend slurm`; not for typing.
#include <cstdlib>
#include <memory>

#include "app/command.hpp"
#include "batch/slurm/run_chunk.hpp"

namespace signalsim::app {

Command add_run_chunk_command(CLI::App& app) {
  struct Options {
    std::string out_dir;
    std::size_t index = 0;
    int jobs = 0;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand("run-chunk", "One Slurm array task of --backend slurm: run chunk INDEX of "
                                                  "OUT/slurm/chunks.json (written by the submission)");
  sub->add_option("out", o->out_dir, "The batch's --out directory")->required();
  sub->add_option("index", o->index, "The chunk (the array task index)")->required();
  sub->add_option("--jobs,-j", o->jobs, "Worker processes at a time (default: $SLURM_CPUS_PER_TASK, else 1)")
      ->check(CLI::Range(1, 4096));
  return {sub, [o]() -> int {
            int jobs = o->jobs;
            if (jobs <= 0) {
              const char* cpus = std::getenv("SLURM_CPUS_PER_TASK");
              jobs = cpus ? std::atoi(cpus) : 1;
              if (jobs <= 0) jobs = 1;
            }
            try {
              return run_chunk(o->out_dir, o->index, jobs);
            } catch (const std::exception& e) {
              return report_bad_input(e.what());
            }
          }};
}

}  // namespace signalsim::app
