// The back-end options of batch and sweep, and the choice between the local pool and Slurm
// (batch_backend.hpp).
#include "app/batch_backend.hpp"

#include <cstdio>
#include <stdexcept>

#include "batch/slurm/slurm_backend.hpp"
#include "scenario/notes.hpp"

namespace signalsim::app {

void add_backend_options(CLI::App* sub, BackendCliOptions& o) {
  const std::string group = "Slurm (docs/slurm.md)";
  sub->add_option("--backend", o.backend, "Where the runs run: local (worker processes here, the default) or slurm "
                                          "(one Slurm job array; --jobs is then each task's CPUs, default 1)")
      ->check(CLI::IsMember({"local", "slurm"}));
  sub->add_option("--chunk", o.chunk, "Slurm: runs per array task (default 10 per CPU of a task)")
      ->check(CLI::Range(std::size_t{1}, std::size_t{1000000}))
      ->group(group);
  sub->add_option("--max-parallel", o.max_parallel, "Slurm: array tasks running at a time (sbatch --array=...%M)")
      ->check(CLI::Range(1, 1000000))
      ->group(group);
  sub->add_option("--partition", o.partition, "Slurm: the partition (sbatch --partition)")->group(group);
  sub->add_option("--time", o.time, "Slurm: time limit of each array task (sbatch --time, e.g. 30 or 2:00:00)")
      ->group(group);
  sub->add_option("--slurm-arg", o.slurm_args, "Slurm: one more sbatch option as it is (repeatable), e.g. "
                                               "--slurm-arg=--account=proj")
      ->allow_extra_args(false)
      ->group(group);
  sub->add_flag("--no-wait", o.no_wait, "Slurm: submit and return; --collect merges results.csv later")->group(group);
  sub->add_flag("--collect", o.collect,
                "Slurm: wait for the job submitted to --out (if it still runs) and merge its results.csv")
      ->group(group);
}

BackendRun run_with_backend(const std::vector<RunSpec>& runs, BatchSettings settings, const BatchCliOptions& cli,
                            const BackendCliOptions& o) {
  const bool slurm = o.backend == "slurm" || o.collect;
  if (!slurm) {
    const char* slurm_only = o.chunk ? "--chunk"
                             : o.max_parallel ? "--max-parallel"
                             : !o.partition.empty() ? "--partition"
                             : !o.time.empty() ? "--time"
                             : !o.slurm_args.empty() ? "--slurm-arg"
                             : o.no_wait ? "--no-wait"
                                         : nullptr;
    if (slurm_only) throw std::runtime_error(std::string(slurm_only) + " needs --backend slurm");
    refuse_while_slurm_job_runs(settings.out_dir);  // its tasks write into the same run directories
    release_notes();  // the scenarios' notes, held by the command: from here the batch runs
    forget_slurm_job(settings.out_dir);
    BackendRun run{run_batch(runs, settings)};
    if (!settings.quiet || run.result.interrupted)
      std::printf("%s\n", batch_summary(run.result, settings.out_dir).c_str());
    return run;
  }
  if (cli.jobs == 0) settings.jobs = 1;  // one CPU per task unless --jobs says otherwise
  BackendRun run;
  if (o.collect) {
    if (o.no_wait) throw std::runtime_error("--collect waits for the job; --no-wait is for a submission");
    if (settings.resume) throw std::runtime_error("--collect and --resume do not go together: collect first");
    release_notes();  // the scenarios' notes, held by the command
    run.result = collect_slurm_batch(runs, settings);
  } else {
    SlurmOptions options;
    options.chunk = o.chunk;
    options.max_parallel = o.max_parallel;
    options.partition = o.partition;
    options.time = o.time;
    options.sbatch_args = o.slurm_args;
    options.wait = !o.no_wait;
    const SlurmOutcome outcome = run_batch_on_slurm(runs, settings, options);
    run.result = outcome.result;
    if (!outcome.waited) {
      run.merged = false;
      if (!settings.quiet)
        std::printf("not waiting (--no-wait): the same command with --collect merges %s once the job is done "
                    "(squeue --jobs=%s shows it)\n",
                    results_path(settings.out_dir).c_str(), outcome.job_id.c_str());
      return run;
    }
  }
  if (!settings.quiet || run.result.interrupted)
    std::printf("%s\n", batch_summary(run.result, settings.out_dir).c_str());
  return run;
}

}  // namespace signalsim::app
