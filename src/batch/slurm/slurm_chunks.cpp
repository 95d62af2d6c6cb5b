// OUT/slurm/: the chunk list, the task script and the job record (slurm_chunks.hpp).
#include "batch/slurm/slurm_chunks.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "batch/run_outputs.hpp"
#include "report/atomic_file.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

constexpr const char* kChunkFormat = "signalsim chunk list 1";

std::string chunks_path(const std::string& out_dir) { return (fs::path(slurm_dir(out_dir)) / "chunks.json").string(); }
std::string job_path(const std::string& out_dir) { return (fs::path(slurm_dir(out_dir)) / "job.json").string(); }

// A path for a POSIX shell, in single quotes.
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string slurm_dir(const std::string& out_dir) { return (fs::path(out_dir) / "slurm").string(); }

std::size_t chunk_size(std::size_t runs, std::size_t requested, int cpus_per_task, std::size_t max_array,
                       std::string& note) {
  std::size_t size = requested > 0 ? requested : 10 * static_cast<std::size_t>(cpus_per_task > 0 ? cpus_per_task : 1);
  if (max_array == 0) max_array = 1;
  if (runs > 0 && (runs + size - 1) / size > max_array) {
    const std::size_t raised = (runs + max_array - 1) / max_array;
    note = "--chunk " + std::to_string(size) + " would need " + std::to_string((runs + size - 1) / size) +
           " array tasks, more than the cluster's MaxArraySize of " + std::to_string(max_array) + ": " +
           std::to_string(raised) + " runs per task";
    size = raised;
  }
  return size;
}

std::vector<std::vector<ChunkRun>> make_chunks(const std::vector<ChunkRun>& runs, std::size_t size) {
  std::vector<std::vector<ChunkRun>> chunks;
  for (std::size_t at = 0; at < runs.size(); at += size)
    chunks.emplace_back(runs.begin() + static_cast<std::ptrdiff_t>(at),
                        runs.begin() + static_cast<std::ptrdiff_t>(std::min(runs.size(), at + size)));
  return chunks;
}

void write_chunk_list(const std::string& out_dir, const ChunkList& list) {
  nlohmann::ordered_json doc;
  doc["format"] = kChunkFormat;
  doc["directory"] = list.directory;
  doc["timeout"] = list.timeout;
  doc["isolate"] = list.isolate;
  doc["chunks"] = nlohmann::ordered_json::array();
  for (const auto& chunk : list.chunks) {
    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const ChunkRun& run : chunk) {
      nlohmann::ordered_json values = nlohmann::ordered_json::array();
      for (const auto& [key, value] : run.spec.values) values.push_back({key, value});
      runs.push_back({{"index", run.spec.index},
                      {"scenario", run.spec.scenario},
                      {"name", run.spec.name},
                      {"values", values},
                      {"set", run.spec.set},
                      {"run_dir", run.run_dir}});
    }
    doc["chunks"].push_back(runs);
  }
  fs::create_directories(slurm_dir(out_dir));
  std::string text;
  try {
    text = doc.dump(1) + "\n";
  } catch (const nlohmann::json::exception&) {
    throw std::runtime_error(chunks_path(out_dir) + ": cannot write: a scenario path or value is not UTF-8 text");
  }
  write_file_atomically(chunks_path(out_dir), text);
}

ChunkList read_chunk_list(const std::string& out_dir) {
  const std::string path = chunks_path(out_dir);
  const auto doc = read_json_file(path);
  ChunkList list;
  try {
    if (doc.value("format", "") != kChunkFormat) throw std::runtime_error("not a signalsim chunk list");
    list.directory = doc.at("directory").get<std::string>();
    list.timeout = doc.at("timeout").get<double>();
    list.isolate = doc.value("isolate", false);  // absent in lists written before --isolate was kept
    for (const auto& chunk : doc.at("chunks")) {
      std::vector<ChunkRun> runs;
      for (const auto& item : chunk) {
        ChunkRun run;
        run.spec.index = item.at("index").get<std::size_t>();
        run.spec.scenario = item.at("scenario").get<std::string>();
        run.spec.name = item.at("name").get<std::string>();
        for (const auto& pair : item.at("values"))
          run.spec.values.emplace_back(pair.at(0).get<std::string>(), pair.at(1).get<std::string>());
        run.spec.set = item.at("set").get<std::vector<std::string>>();
        run.run_dir = item.at("run_dir").get<std::string>();
        runs.push_back(std::move(run));
      }
      list.chunks.push_back(std::move(runs));
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  return list;
}

std::string write_task_script(const std::string& out_dir, const std::string& program) {
  const std::string path = (fs::path(slurm_dir(out_dir)) / "task.sh").string();
  write_file_atomically(path, "#!/bin/sh\n"
                              "# Written by signalsim (--backend slurm, docs/slurm.md): array task N runs chunk N\n"
                              "# of OUT/slurm/chunks.json with the local pool, one row file per run.\n"
                              "exec " + shell_quoted(program) + " run-chunk " + shell_quoted(out_dir) +
                              " \"$SLURM_ARRAY_TASK_ID\"\n");
  ::chmod(path.c_str(), 0755);
  return path;
}

void write_job_record(const std::string& out_dir, const SlurmJob& job) {
  const nlohmann::ordered_json doc = {{"job", job.id}, {"tasks", job.tasks}};
  write_file_atomically(job_path(out_dir), doc.dump(1) + "\n");
}

void remove_job_record(const std::string& out_dir) { fs::remove(job_path(out_dir)); }

std::optional<SlurmJob> read_job_record(const std::string& out_dir) {
  const std::string path = job_path(out_dir);
  if (!fs::exists(path)) return std::nullopt;
  const auto doc = read_json_file(path);
  try {
    return SlurmJob{doc.at("job").get<std::string>(), doc.at("tasks").get<std::size_t>()};
  } catch (const std::exception& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace signalsim
