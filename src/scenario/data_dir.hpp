// Where signalsim's run-time data is (config/ with the country presets and Autoware's defaults,
// signalsim-plot and its python modules, the bundled scenarios and nets): found relative to the running
// binary, never through a path of the build tree compiled in. docs/install.md explains the order.
#pragma once

#include <string>

namespace signalsim {

/// The outcome of the search: `path` when found, else where it went wrong and why (one line each).
struct DataDirLookup {
  std::string path;    ///< the data directory, e.g. "/opt/signalsim/share/signalsim"; "" when none
  std::string where;   ///< what was wrong: "SIGNALSIM_DATA_DIR=/x", the marker file, or the binary
  std::string reason;  ///< why none was found, naming what was tried and SIGNALSIM_DATA_DIR
};

/// Searches, in this order, and takes the first that holds config/countries/:
///   1. $SIGNALSIM_DATA_DIR when set and not empty (nothing else is tried when it is wrong);
///   2. the installed layout: <dir of /proc/self/exe>/../share/signalsim (the relative path is
///      SIGNALSIM_INSTALL_DATA_FROM_BIN, set by cmake/install.cmake beside the install rules);
///   3. a build tree: the first folder at or above the binary's folder holding the marker
///      signalsim-data-dir.txt (written by CMake into the build folder), whose one line is the
///      source tree the binary was built from.
/// Searched once per process; later calls return the same result.
const DataDirLookup& find_data_dir();

/// find_data_dir().path. Throws InputError(where, reason) when none was found.
const std::string& data_dir();

}  // namespace signalsim
