// Where the plugins signalsim ships (the autoware_core decider) are: SIGNALSIM_PLUGIN_DIR when set;
// else, installed, lib/signalsim/plugins beside the binary's bin/ (cmake/install.cmake); else, in a
// build tree, plugins/ beside the build tree's marker (scenario/data_dir.hpp). No path of the build or
// source tree is compiled in.
#pragma once

#include <string>

namespace signalsim {

/// The path of a bundled plugin file ("libsignalsim_autoware_core.so"). Throws PluginLoadError saying
/// where it looked when it is in none of those places.
std::string bundled_plugin(const std::string& file_name);

}  // namespace signalsim
