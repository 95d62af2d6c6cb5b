// The running binary and the build tree above it; see program_location.hpp.
#include "core/program_location.hpp"

#include <system_error>

namespace signalsim {
namespace fs = std::filesystem;

fs::path running_binary() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::path() : exe;
}

fs::path build_tree_above(fs::path dir) {
  std::error_code ec;
  for (; !dir.empty(); dir = dir.parent_path()) {
    if (fs::is_regular_file(dir / kBuildTreeMarker, ec)) return dir;
    if (dir == dir.root_path()) break;
  }
  return {};
}

}  // namespace signalsim
