// Where the running program is, and the build tree above it: the one home of the searches that find
// signalsim's data, its bundled plugins and its SUMO back-end module relative to the binary (never
// through a path of the build or source tree compiled in; docs/install.md).
#pragma once

#include <filesystem>

namespace signalsim {

/// The marker CMake writes into the top of the build folder (cmake/install.cmake); its one line is
/// the source tree the build came from.
inline constexpr const char* kBuildTreeMarker = "signalsim-data-dir.txt";

/// The running binary (/proc/self/exe, symbolic links resolved: a link in ~/bin to an installed
/// binary still finds the installation); "" when it cannot be read.
std::filesystem::path running_binary();

/// The first folder at or above `dir` that holds kBuildTreeMarker; "" when there is none.
std::filesystem::path build_tree_above(std::filesystem::path dir);

}  // namespace signalsim
