// Waiting for a Slurm job's row files, squeue, error rows for runs of tasks that died (slurm_wait.hpp).
#include "batch/slurm/slurm_wait.hpp"

#include <poll.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "batch/interrupt_guard.hpp"
#include "batch/run_row_file.hpp"
#include "batch/slurm/slurm_commands.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

using Clock = std::chrono::steady_clock;

// The runs of each chunk still without a row.
struct Waiting {
  std::vector<std::vector<const ChunkRun*>> open;  // by task index
  std::size_t count = 0;
};

std::string task_name(const SlurmJob& job, std::size_t task) { return job.id + "_" + std::to_string(task); }

}  // namespace

ResultRow lost_run_row(const RunSpec& run, const std::string& out_dir, const std::string& run_dir,
                       const std::string& task, const std::string& state) {
  ResultRow row;
  row.run = run.index;
  row.cells["scenario"] = run.name;
  row.cells["file"] = run.scenario;
  for (const auto& [key, value] : run.values) row.cells[swept_column(key)] = value;
  if (fs::exists(fs::path(out_dir) / run_dir)) row.cells["run_dir"] = run_dir;
  row.cells["wall_time"] = "0.00";
  row.cells["status"] = "error";
  const std::string log = (fs::path(slurm_dir(out_dir)) / "logs" / ("task-" + task + ".log")).string();
  std::string error;
  if (state.empty())
    error = "Slurm task " + task + " ended without a row for this run, and Slurm no longer knows the task " +
            "(cancelled while pending, or ended longer ago than the cluster's MinJobAge)";
  else if (state == "COMPLETED")
    error = "Slurm task " + task + " COMPLETED but left no row for this run in " + run_dir +
            ": is --out on a filesystem the nodes share? (log: " + log + ")";
  else
    error = "Slurm task " + task + " ended " + state + " before this run finished (log: " + log + ")";
  row.cells["error"] = error;
  return row;
}

bool wait_for_slurm_job(BatchStart& batch, const BatchSettings& settings, const ChunkList& list, const SlurmJob& job,
                        BatchProgress& progress, bool cancel_on_interrupt) {
  Waiting waiting;
  waiting.open.resize(list.chunks.size());
  for (std::size_t task = 0; task < list.chunks.size(); ++task)
    for (const ChunkRun& run : list.chunks[task]) {
      waiting.open[task].push_back(&run);
      ++waiting.count;
    }

  TaskStates states;
  bool states_known = false;
  std::string last_queue_error;
  // Moves every run whose row file is there now into the rows; `all`: also of pending tasks.
  auto scan = [&](bool all) {
    for (std::size_t task = 0; task < waiting.open.size(); ++task) {
      auto& open = waiting.open[task];
      if (open.empty()) continue;
      if (!all && states_known) {
        const auto it = states.find(task);
        if (it != states.end() && it->second == "PENDING") continue;  // nothing of it can be there yet
      }
      std::vector<const ChunkRun*> still;
      for (const ChunkRun* run : open) {
        auto row = read_row_file(settings.out_dir, run->run_dir);
        if (!row || row->run != run->spec.index) {
          still.push_back(run);
          continue;
        }
        progress.finished(run->spec, *row);
        batch.result.rows[run->spec.index] = std::move(*row);
        --waiting.count;
      }
      open = std::move(still);
    }
    rewrite_results(batch, settings);
  };

  const auto begin = Clock::now();
  auto next_queue = begin;
  std::optional<Clock::time_point> grace_end;  // set when a COMPLETED task's rows are not visible yet
  while (true) {
    if (InterruptGuard::interrupted()) {
      if (cancel_on_interrupt) {
        const std::string error = cancel_job(job.id);
        if (error.empty()) std::fprintf(stderr, "\nsignalsim: interrupted: Slurm job %s cancelled\n", job.id.c_str());
        else std::fprintf(stderr, "\nsignalsim: interrupted, and the job could not be cancelled: %s\n", error.c_str());
      } else {
        std::fprintf(stderr, "\nsignalsim: stopped waiting; Slurm job %s goes on (--collect again later)\n",
                     job.id.c_str());
      }
      scan(true);  // the runs that finished until now are kept
      return false;
    }
    scan(false);
    if (waiting.count == 0) return true;

    const auto now = Clock::now();
    if (now >= next_queue) {
      const QueueReading reading = read_queue(job.id);
      next_queue = now + (now - begin < std::chrono::minutes(1) ? std::chrono::seconds(1) : std::chrono::seconds(5));
      if (!reading.ok) {
        if (reading.error != last_queue_error)
          std::fprintf(stderr, "signalsim: %s (still waiting for Slurm job %s)\n", reading.error.c_str(),
                       job.id.c_str());
        last_queue_error = reading.error;
        progress.set_extra("Slurm job " + job.id + ": " + reading.error);
      } else {
        last_queue_error.clear();
        states = reading.tasks;
        states_known = true;
        progress.set_extra("Slurm job " + job.id + ": " + describe_task_states(states));
        bool active = false;
        for (const auto& [task, state] : states) active = active || is_active_task_state(state);
        if (!active) {
          scan(true);
          if (waiting.count == 0) return true;
          bool completed_but_missing = false;
          for (std::size_t task = 0; task < waiting.open.size(); ++task)
            if (!waiting.open[task].empty() && states.count(task) && states.at(task) == "COMPLETED")
              completed_but_missing = true;
          if (completed_but_missing && !grace_end) grace_end = now + std::chrono::seconds(30);
          if (!completed_but_missing || now >= *grace_end) {
            for (std::size_t task = 0; task < waiting.open.size(); ++task)
              for (const ChunkRun* run : waiting.open[task]) {
                const auto it = states.find(task);
                ResultRow row = lost_run_row(run->spec, settings.out_dir, run->run_dir, task_name(job, task),
                                             it == states.end() ? "" : it->second);
                progress.finished(run->spec, row);
                batch.result.rows[run->spec.index] = std::move(row);
              }
            return true;
          }
        }
      }
    }
    progress.tick();
    ::poll(nullptr, 0, 250);  // a signal ends the sleep early
  }
}

}  // namespace signalsim
