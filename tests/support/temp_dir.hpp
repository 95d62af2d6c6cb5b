// A scratch folder of its own for a test (unique, so tests may run in parallel), removed at the end.
// Shared by the unit tests of net/ and scenario/ (tests/unit/net, tests/unit/scenario).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace signalsim {

class TempDir {
 public:
  explicit TempDir(const std::string& tag) {
    std::string pattern = (std::filesystem::temp_directory_path() / ("signalsim-" + tag + "-XXXXXX")).string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  /// Writes `text` to `name` in the folder; returns its path.
  std::string file(const std::string& name, const std::string& text) const {
    const std::string p = (std::filesystem::path(path_) / name).string();
    std::ofstream(p) << text;
    return p;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace signalsim
