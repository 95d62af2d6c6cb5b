// `batch` and `sweep`'s back-end options (--backend local|slurm and the Slurm ones, docs/slurm.md)
// and running a batch with the chosen back-end.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/batch_cli.hpp"
#include "batch/batch_runner.hpp"

namespace signalsim::app {

struct BackendCliOptions {
  std::string backend = "local";
  std::size_t chunk = 0;
  int max_parallel = 0;
  std::string partition;
  std::string time;
  std::vector<std::string> slurm_args;
  bool no_wait = false;
  bool collect = false;
};

/// --backend, --chunk, --max-parallel, --partition, --time, --slurm-arg, --no-wait, --collect.
void add_backend_options(CLI::App* sub, BackendCliOptions& o);

struct BackendRun {
  BatchResult result;
  bool merged = true;  ///< false: submitted with --no-wait, results.csv not merged yet
};

/// Runs the batch locally or on Slurm (--collect: collects it) and prints the closing line (unless
/// quiet). `cli` tells whether --jobs was given: on Slurm it is each task's CPUs, default 1. Throws
/// std::runtime_error (bad input) for options that do not go together, and whatever the back-end
/// throws.
BackendRun run_with_backend(const std::vector<RunSpec>& runs, BatchSettings settings, const BatchCliOptions& cli,
                            const BackendCliOptions& o);

}  // namespace signalsim::app
