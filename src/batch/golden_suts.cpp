// The side file naming a golden file's implementations (see golden_suts.hpp).
#include "batch/golden_suts.hpp"

#include <filesystem>
#include <stdexcept>

#include "batch/run_outputs.hpp"
#include "report/atomic_file.hpp"

namespace signalsim {
namespace fs = std::filesystem;

std::string golden_suts_path(const std::string& golden_events) {
  std::string path = golden_events;
  const std::string suffix = ".events.csv";
  if (path.size() >= suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0)
    path.resize(path.size() - suffix.size());
  return path + ".suts.json";
}

GoldenSuts run_suts(const nlohmann::ordered_json& summary) {
  GoldenSuts suts;
  for (auto [key, name] : {std::pair{"decider", &suts.decider}, std::pair{"light_judge", &suts.light_judge}})
    if (summary.contains(key) && summary[key].is_object() && summary[key].contains("name") &&
        summary[key]["name"].is_string())
      *name = summary[key]["name"].get<std::string>();
  return suts;
}

GoldenSuts read_golden_suts(const std::string& golden_events) {
  GoldenSuts suts;
  const std::string path = golden_suts_path(golden_events);
  if (!fs::exists(path)) return suts;
  const nlohmann::ordered_json j = read_json_file(path);
  if (!j.is_object()) throw std::runtime_error(path + ": expected a JSON object {\"decider\": ..., \"light_judge\": ...}");
  for (auto [key, name] : {std::pair{"decider", &suts.decider}, std::pair{"light_judge", &suts.light_judge}}) {
    if (!j.contains(key)) continue;
    if (!j[key].is_string()) throw std::runtime_error(path + ": '" + key + "' is not a text");
    *name = j[key].get<std::string>();
  }
  return suts;
}

void write_golden_suts(const std::string& golden_events, const GoldenSuts& suts) {
  const std::string path = golden_suts_path(golden_events);
  if (suts == GoldenSuts{}) {
    fs::remove(path);
    return;
  }
  nlohmann::ordered_json j;
  j["decider"] = suts.decider;
  j["light_judge"] = suts.light_judge;
  write_file_atomically(path, j.dump(2) + "\n");
}

std::string describe(const GoldenSuts& suts) { return "decider " + suts.decider + ", light_judge " + suts.light_judge; }

}  // namespace signalsim
