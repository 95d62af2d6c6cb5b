// The source tree's files as tests read them: a path below the source tree (the target defines
// SIGNALSIM_SOURCE_DIR) and a file's bytes. Shared by the step and integration tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace signalsim {

/// `relative` below the source tree.
inline std::string source_path(const std::string& relative) {
  return std::string(SIGNALSIM_SOURCE_DIR) + "/" + relative;
}

/// The bytes of `path` ("" when it cannot be read).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace signalsim
