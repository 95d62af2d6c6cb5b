// The two ways a batch runs its runs, both watched by the one supervisor (child_supervisor.hpp,
// docs/batch.md "How a batch runs"):
//   persistent workers (the default): starting a process costs more than a small run (libsumo pulls
//     in some 200 shared libraries), so each worker - `signalsim worker`, worker_process.hpp - runs
//     one run after another, each exactly as `signalsim run` would, libsumo closed and started
//     again in between; a worker that ends without replying (a signal, exit()) or runs past the
//     job's timeout ends its run as one process per run would have ended, and the next job gets a
//     new worker
//   one process per run (`--isolate`): every run is a `signalsim run` process of its own (stdin
//     and stdout on /dev/null, stderr into a pipe); its run ends with it
#pragma once

#include <functional>
#include <vector>

#include "batch/child_supervisor.hpp"

namespace signalsim {

/// Runs `jobs` in at most `parallel` persistent workers. Each job's argv is a `signalsim run`
/// command line (argv[0] the program, which is started as `argv[0] worker`; argv[1] "run").
/// `on_done` for every job that ended, `on_tick` about every 200 ms, false when interrupted
/// (supervise).
bool run_in_workers(const std::vector<ProcessJob>& jobs, int parallel,
                    const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                    const std::function<void()>& on_tick = {});

/// The same with one process per run: each job's argv is exec'd as it is.
bool run_processes(const std::vector<ProcessJob>& jobs, int parallel,
                   const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                   const std::function<void()>& on_tick = {});

/// run_in_workers, or run_processes when `isolate`.
bool run_jobs(const std::vector<ProcessJob>& jobs, int parallel, bool isolate,
              const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
              const std::function<void()>& on_tick = {});

}  // namespace signalsim
