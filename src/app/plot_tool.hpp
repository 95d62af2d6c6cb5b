// signalsim-plot (Python, matplotlib): where it is and how to call it; gui.png's caption.
#pragma once

#include <string>
#include <vector>

#include "session/sumo_session.hpp"

namespace signalsim::app {

/// $SIGNALSIM_PLOT_TOOL, else the data directory's python/signalsim-plot (scenario/data_dir.hpp).
std::string plot_tool_path();

/// Runs `signalsim-plot ARGS...` in the foreground. Returns its exit code (127: could not start).
/// Prints "signalsim: plotting failed ..." on stderr when it fails, unless `quiet_failure` (the tool's
/// own line says why: `signalsim report`'s bad folder is one line).
int run_plot_tool(const std::vector<std::string>& args, bool quiet_failure = false);

/// `run --gui`: captions RUN_DIR/gui.png with its timeline row (signalsim-plot --gui-caption: time,
/// blinker and source, the light and the judge's decision) and keeps what `picture` framed in its text
/// chunks. Returns the tool's exit code (reported like run_plot_tool's).
int caption_gui_picture(const std::string& run_dir, const sumo::GuiPicture& picture);

}  // namespace signalsim::app
