// The search for the bundled plugins; see bundled_plugins.hpp.
#include "sut/bundled_plugins.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

#include "core/program_location.hpp"
#include "sut/plugin_library.hpp"

#ifndef SIGNALSIM_INSTALL_PLUGINS_FROM_BIN
#define SIGNALSIM_INSTALL_PLUGINS_FROM_BIN "../lib/signalsim/plugins"
#endif

namespace signalsim {
namespace fs = std::filesystem;
namespace {

constexpr const char* kEnvironment = "SIGNALSIM_PLUGIN_DIR";

}  // namespace

std::string bundled_plugin(const std::string& file_name) {
  std::error_code ec;
  if (const char* env = std::getenv(kEnvironment); env && *env) {
    const fs::path file = fs::path(env) / file_name;
    if (fs::is_regular_file(file, ec)) return file.string();
    throw PluginLoadError(file.string() + " does not exist (" + kEnvironment + "=" + env + ")");
  }
  const fs::path bin = running_binary().parent_path();
  const fs::path installed = (bin / SIGNALSIM_INSTALL_PLUGINS_FROM_BIN / file_name).lexically_normal();
  if (fs::is_regular_file(installed, ec)) return installed.string();
  if (const fs::path tree = build_tree_above(bin); !tree.empty()) {
    const fs::path built = tree / "plugins" / file_name;
    if (fs::is_regular_file(built, ec)) return built.string();
    throw PluginLoadError(built.string() + " is not built (cmake --build build --target " +
                          fs::path(file_name).stem().string().substr(3) + ")");
  }
  throw PluginLoadError(installed.string() + " does not exist and no build tree is above " + bin.string() +
                        "; install with cmake --install or set " + kEnvironment);
}

}  // namespace signalsim
