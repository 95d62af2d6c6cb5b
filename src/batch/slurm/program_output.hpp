// Running a short-lived program found on PATH (sbatch, squeue, scancel, scontrol) and capturing what
// it prints: the Slurm back-end's only way of talking to Slurm (slurm_commands.hpp).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace signalsim {

struct ProgramOutput {
  bool started = false;  ///< false: not found on PATH, or it could not be started (error says why)
  int exit_code = -1;    ///< its exit code, or 128 + the signal that ended it
  std::string out;       ///< stdout
  std::string err;       ///< stderr (or why it could not be started, or that it timed out)
  bool timed_out = false;  ///< it did not end within the timeout and was killed (err says so)
};

/// The full path of `program` on PATH (or `program` itself when it holds a '/' and is executable);
/// "" when there is none.
std::string find_on_path(const std::string& program);

/// Runs argv (argv[0] looked up on PATH) in a process group of its own (Ctrl-C on the terminal does
/// not reach it), with stdin on /dev/null and `extra_env` ("NAME=value") added to this process's
/// environment; waits for it and returns what it printed. Signals do not stop the wait (the caller
/// polls its own interrupt flag between calls). When it has not ended after `timeout_seconds`
/// (a Slurm controller that never answers), its process group is killed and the result says
/// timed_out, with err "did not answer within N s".
ProgramOutput run_program(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env = {},
                          double timeout_seconds = 60.0);

}  // namespace signalsim
