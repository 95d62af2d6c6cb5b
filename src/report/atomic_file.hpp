// Output files are written whole or not at all: the content goes to "<path>.tmp", every write and the
// close are checked (a full disk fails there, not silently in a destructor), and only then the file
// is renamed over `path`. On any failure the temporary file is removed and `path` is left as it was.
#pragma once

#include <string>

namespace signalsim {

/// Throws std::runtime_error "<path>: cannot write: <reason>" (e.g. "No space left on device").
void write_file_atomically(const std::string& path, const std::string& content);

}  // namespace signalsim
