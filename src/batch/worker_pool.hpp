// Persistent workers for a batch's runs (docs/batch.md "How a batch runs"). Starting a process costs
// more than a small run (libsumo pulls in some 200 shared libraries), so each worker -
// `signalsim worker`, worker_process.hpp - runs one run after another, each exactly as
// `signalsim run` would, libsumo closed and started again in between.
//
//   while jobs remain or runs are under way:
//     each idle worker (started when needed, at most `parallel`) gets the next job's `signalsim run`
//       arguments as one request line (worker_protocol.hpp); the run's wall time starts
//     poll the workers' reply and stderr pipes (at most 200 ms); a reply ends the run: its exit
//       code, and everything the worker wrote on stderr since its previous reply
//     a worker that ends without replying (a signal, exit()) or runs past the job's timeout
//       (SIGKILL to its process group) ends its run as one process per run would have ended
//       (signal, exit code, timed out); it is reaped and the next job gets a new worker
//     finished runs go to `on_done` in the calling thread, those of one round by job id
//   on SIGINT/SIGTERM: start nothing more; replies already there are reported; every worker's
//     group gets SIGTERM (SIGKILL after 2 s); a run that still ends by itself in that time (exit
//     code neither 130 nor 143) is reported, the others not; returns false
//   a SIGINT/SIGTERM that reaches a worker itself (a `kill` of it or its group; Slurm's scancel
//     signals every process of a task, often the worker before the pool) stops its run as it stops
//     `signalsim run`: the reply 130 or 143 (or its end by that signal) is no finished run, no row;
//     the pool then stops as above, as if the signal had reached it
#pragma once

#include <functional>
#include <vector>

#include "batch/process_pool.hpp"

namespace signalsim {

/// Runs `jobs` in at most `parallel` persistent workers. Each job's argv is a `signalsim run`
/// command line (argv[0] the program, which is started as `argv[0] worker`; argv[1] "run").
/// The contract is run_processes's: `on_done` for every job that ended, `on_tick` about every 200
/// ms, false when interrupted.
bool run_in_workers(const std::vector<ProcessJob>& jobs, int parallel,
                    const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                    const std::function<void()>& on_tick = {});

/// run_in_workers, or run_processes (one process per run) when `isolate`.
bool run_jobs(const std::vector<ProcessJob>& jobs, int parallel, bool isolate,
              const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
              const std::function<void()>& on_tick = {});

}  // namespace signalsim
