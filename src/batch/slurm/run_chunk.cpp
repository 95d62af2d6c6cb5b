// A Slurm array task: one chunk of runs through the local pool, a row file per run (run_chunk.hpp).
#include "batch/slurm/run_chunk.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "batch/batch_progress.hpp"
#include "batch/batch_runner.hpp"
#include "batch/run_row_file.hpp"
#include "batch/run_rows.hpp"
#include "batch/slurm/slurm_chunks.hpp"
#include "report/exit_codes.hpp"

namespace signalsim {
namespace fs = std::filesystem;

int run_chunk(const std::string& out_dir, std::size_t index, int jobs) {
  const std::string out = fs::absolute(out_dir).string();
  const ChunkList list = read_chunk_list(out);
  if (index >= list.chunks.size())
    throw std::runtime_error(slurm_dir(out) + "/chunks.json: no chunk " + std::to_string(index) + " (it has " +
                             std::to_string(list.chunks.size()) + ")");
  // Scenario paths are as the user gave them, relative to where the job was submitted.
  if (::chdir(list.directory.c_str()) != 0)
    throw std::runtime_error("cannot enter the submission's directory " + list.directory + " on this node (" +
                             std::strerror(errno) + "): it must be on a filesystem the nodes share");

  std::vector<RunSpec> specs;
  std::size_t max_index = 0;
  for (const ChunkRun& run : list.chunks[index]) max_index = std::max(max_index, run.spec.index);
  std::vector<std::string> run_dirs(max_index + 1);
  std::vector<const RunSpec*> to_run;
  specs.reserve(list.chunks[index].size());
  for (const ChunkRun& run : list.chunks[index]) specs.push_back(run.spec);
  std::size_t already = 0;
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const ChunkRun& run = list.chunks[index][i];
    run_dirs[run.spec.index] = run.run_dir;
    const auto row = read_row_file(out, run.run_dir);
    if (row && is_finished_status(row->cells.count("status") ? row->cells.at("status") : "")) {
      ++already;  // done by an earlier attempt of this task
      continue;
    }
    fs::remove_all(fs::path(out) / run.run_dir);  // half-written by an attempt that was stopped
    to_run.push_back(&specs[i]);
  }
  std::printf("chunk %zu: %zu runs (%zu already done), %d at a time%s\n", index, specs.size(), already, jobs,
              list.isolate ? ", one process per run (--isolate)" : "");
  std::fflush(stdout);

  BatchSettings settings;
  settings.out_dir = out;
  settings.jobs = jobs;
  settings.timeout = list.timeout;
  settings.isolate = list.isolate;
  BatchProgress progress(to_run.size(), false);
  int code = 0;
  const bool completed = run_in_worker_pool(
      to_run, run_dirs, settings,
      [&](const RunSpec& run, ResultRow row) {
        try {
          write_row_file(out, run_dirs[run.index], row);
        } catch (const std::exception& e) {
          std::fprintf(stderr, "signalsim: %s\n", e.what());
          code = kExitBadInput;
        }
        progress.finished(run, row);
      },
      [&] { progress.tick(); });
  progress.end();
  if (!completed) return kExitInterrupted;
  return code;
}

}  // namespace signalsim
