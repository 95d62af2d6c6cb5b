// The search for the data directory (see data_dir.hpp): environment, installed layout, build tree.
#include "scenario/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/program_location.hpp"
#include "scenario/input_error.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

constexpr const char* kEnvironment = "SIGNALSIM_DATA_DIR";

bool holds_data(const fs::path& dir) {
  std::error_code ec;
  return fs::is_directory(dir / "config" / "countries", ec);
}

DataDirLookup search() {
  if (const char* env = std::getenv(kEnvironment); env && *env) {
    if (holds_data(env)) return {env, "", ""};
    return {"", std::string(kEnvironment) + "=" + env, "not a signalsim data directory (no config/countries in it)"};
  }
  const fs::path exe = running_binary();
  const fs::path bin = exe.parent_path();
  if (exe.empty()) return {"", "/proc/self/exe", std::string("cannot be read to find the data directory; set ") + kEnvironment};
  const fs::path installed = (bin / SIGNALSIM_INSTALL_DATA_FROM_BIN).lexically_normal();
  if (holds_data(installed)) return {installed.string(), "", ""};
  if (const fs::path tree = build_tree_above(bin); !tree.empty()) {
    const fs::path marker = tree / kBuildTreeMarker;
    std::ifstream in(marker);
    std::string source;
    std::getline(in, source);
    if (!source.empty() && holds_data(source)) return {source, "", ""};
    return {"", marker.string(),
            "names the source tree '" + source + "', which has no config/countries (moved? re-run cmake); or set " +
                kEnvironment};
  }
  return {"", exe.string(),
          "no data directory: " + installed.string() + " has no config/countries and no build tree (" +
              kBuildTreeMarker + ") is above " + bin.string() + "; install with cmake --install or set " +
              kEnvironment + " (docs/install.md)"};
}

}  // namespace

const DataDirLookup& find_data_dir() {
  static const DataDirLookup found = search();
  return found;
}

const std::string& data_dir() {
  const DataDirLookup& found = find_data_dir();
  if (found.path.empty()) throw InputError(found.where, 0, found.reason);
  return found.path;
}

}  // namespace signalsim
