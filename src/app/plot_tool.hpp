// signalsim-plot (Python, matplotlib): where it is and how to call it.
#pragma once

#include <string>
#include <vector>

namespace signalsim::app {

/// $SIGNALSIM_PLOT_TOOL, else the data directory's python/signalsim-plot (scenario/data_dir.hpp).
std::string plot_tool_path();

/// Runs `signalsim-plot ARGS...` in the foreground. Returns its exit code (127: could not start).
/// Prints "signalsim: plotting failed ..." on stderr when it fails.
int run_plot_tool(const std::vector<std::string>& args);

}  // namespace signalsim::app
