// One process per run: `--isolate` runs every run of a batch as its own `signalsim run` process
// (persistent workers are worker_pool.hpp), and run_foreground starts a program in the foreground.
//
//   while jobs remain or workers run:
//     start jobs until `jobs` workers run (fork; the child gets its own process group, stdin and
//       stdout on /dev/null, stderr into a pipe, dies with the parent; then exec)
//     poll the stderr pipes (at most 200 ms), collect what the workers write
//     reap finished workers (waitpid), hand each result to `on_done` in the calling thread
//     kill (SIGKILL, whole process group) workers past their wall-clock timeout: they finish as
//       timed out
//     on SIGINT/SIGTERM: start nothing more, SIGTERM every worker's group (SIGKILL after 2 s),
//       reap them without reporting them, return false
//     a run that a SIGINT/SIGTERM reached itself (stopped_by_signal: a `kill` of its process or
//       group, Slurm's scancel signalling every process of a task) did not finish: it is not
//       reported and the pool stops as if the signal had reached it (docs/batch.md "Ctrl-C")
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace signalsim {

struct ProcessJob {
  std::size_t id = 0;              ///< the caller's key (the run index)
  std::vector<std::string> argv;   ///< argv[0] is the program path
  double timeout = 0.0;            ///< [s] wall clock; <= 0: none
};

struct ProcessResult {
  bool exited = false;             ///< ended through exit(); exit_code is valid
  int exit_code = -1;
  int signal = 0;                  ///< the signal that ended it, 0 if none
  bool timed_out = false;          ///< killed by the pool after the timeout
  std::string stderr_text;         ///< what it wrote on stderr (at most 64 KiB)
  double wall = 0.0;               ///< [s]
};

/// Whether a run ended because a SIGINT or SIGTERM reached it rather than by finishing: it exited
/// 130 or 143 (what `signalsim run` exits with when one stops it), or one killed it before its
/// handlers were installed. Not for a run the pool killed after its timeout.
bool stopped_by_signal(const ProcessResult& result);

/// Runs `jobs` with at most `parallel` at a time. `on_done` is called for every job that finished
/// (exit, signal, timeout), in completion order; `on_tick` about every 200 ms. Returns false when
/// interrupted by SIGINT or SIGTERM (the signals are handled only while run() runs), or when a run
/// was stopped by one sent to it directly (stopped_by_signal); the jobs still running are then
/// killed and not reported, nor is the stopped run.
bool run_processes(const std::vector<ProcessJob>& jobs, int parallel,
                   const std::function<void(const ProcessJob&, const ProcessResult&)>& on_done,
                   const std::function<void()>& on_tick = {});

/// This program's own executable (/proc/self/exe).
std::string self_executable();

/// "SIGKILL", "SIGSEGV", ... or "signal N".
std::string signal_name(int signal);

/// Runs a program in the foreground (inherits stdout/stderr) and waits. Returns its exit code, or
/// 128 + signal; 127 when it cannot be started.
int run_foreground(const std::vector<std::string>& argv);

}  // namespace signalsim
