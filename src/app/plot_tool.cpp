// tools/plot: where it is ($SIGNALSIM_PLOT_TOOL or the data directory) and running it; see plot_tool.hpp.
#include "app/plot_tool.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "batch/child_process.hpp"
#include "scenario/data_dir.hpp"

namespace signalsim::app {

std::string plot_tool_path() {
  if (const char* env = std::getenv("SIGNALSIM_PLOT_TOOL"); env && *env) return env;
  return (std::filesystem::path(data_dir()) / "tools" / "plot").string();
}

int run_plot_tool(const std::vector<std::string>& args) {
  const std::string tool = plot_tool_path();
  if (!std::filesystem::is_regular_file(tool)) {
    std::fprintf(stderr, "signalsim: plotting failed: %s not found (set SIGNALSIM_PLOT_TOOL)\n", tool.c_str());
    return 127;
  }
  std::vector<std::string> argv = {tool};
  argv.insert(argv.end(), args.begin(), args.end());
  std::fflush(stdout);
  const int code = run_foreground(argv);
  if (code != 0) std::fprintf(stderr, "signalsim: plotting failed (%s exit code %d)\n", tool.c_str(), code);
  return code;
}

}  // namespace signalsim::app
