// signalsim-plot: where it is ($SIGNALSIM_PLOT_TOOL or the data directory's python/) and running it; see plot_tool.hpp.
#include "app/plot_tool.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "batch/child_process.hpp"
#include "core/number_text.hpp"
#include "scenario/data_dir.hpp"

namespace signalsim::app {

std::string plot_tool_path() {
  if (const char* env = std::getenv("SIGNALSIM_PLOT_TOOL"); env && *env) return env;
  return (std::filesystem::path(data_dir()) / "python" / "signalsim-plot").string();
}

int run_plot_tool(const std::vector<std::string>& args, bool quiet_failure) {
  const std::string tool = plot_tool_path();
  if (!std::filesystem::is_regular_file(tool)) {
    std::fprintf(stderr, "signalsim: plotting failed: %s not found (set SIGNALSIM_PLOT_TOOL)\n", tool.c_str());
    return 127;
  }
  std::vector<std::string> argv = {tool};
  argv.insert(argv.end(), args.begin(), args.end());
  std::fflush(stdout);
  const int code = run_foreground(argv);
  if (code != 0 && !quiet_failure)
    std::fprintf(stderr, "signalsim: plotting failed (%s exit code %d)\n", tool.c_str(), code);
  return code;
}

int caption_gui_picture(const std::string& run_dir, const sumo::GuiPicture& picture) {
  std::string view;
  for (const double v : picture.view) view += (view.empty() ? "" : ",") + format_text("%.2f", v);
  // NAME=VALUE: a value may start with '-' (a view's negative coordinate)
  return run_plot_tool({run_dir, "--quiet", "--gui-caption=" + format_text("%.3f", picture.time),
                        "--gui-junction=" + picture.junction, "--gui-light=" + picture.light, "--gui-view=" + view});
}

}  // namespace signalsim::app
