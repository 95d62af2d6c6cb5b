// Scenario paths to scenario files: directories expanded to their *.yaml / *.yml (see scenario_files.hpp).
#include "batch/scenario_files.hpp"

#include <algorithm>
#include <filesystem>

#include "core/file_paths.hpp"
#include "scenario/input_error.hpp"

namespace signalsim {
namespace fs = std::filesystem;

std::vector<std::string> scenario_files(const std::vector<std::string>& paths, const std::string& origin, int line) {
  std::vector<std::string> out;
  for (const std::string& path : paths) {
    const std::string where = origin.empty() ? path : origin;
    const int at = origin.empty() ? 0 : line;
    if (fs::is_directory(path)) {
      std::vector<std::string> found;
      for (const auto& entry : fs::directory_iterator(path)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".yaml" || ext == ".yml")) found.push_back(entry.path().string());
      }
      if (found.empty()) throw InputError(where, at, "directory '" + path + "' holds no scenario (*.yaml)");
      std::sort(found.begin(), found.end());
      out.insert(out.end(), found.begin(), found.end());
    } else if (const std::string problem = input_file_problem(path); problem.empty()) {
      out.push_back(path);
    } else {
      throw InputError(where, at, "scenario path '" + path + "' " + problem);
    }
  }
  return out;
}

}  // namespace signalsim
