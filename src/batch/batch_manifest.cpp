// The batch manifest and the output directory's lock (batch_manifest.hpp).
#include "batch/batch_manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/number_text.hpp"
#include "scenario/input_error.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// The file's bytes; "" for a file that cannot be read (a suite's file that did not load still has a
// manifest line).
std::string bytes_or_empty(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

}  // namespace

std::string batch_manifest(const std::vector<RunSpec>& runs) {
  std::string out = "signalsim batch manifest 1\n";
  for (const RunSpec& run : runs) {
    const std::string bytes = bytes_or_empty(run.scenario);
    std::uint64_t hash = 1469598103934665603ULL;
    for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ULL;
    out += std::to_string(run.index) + "\t" + run.scenario + "\t" +
           format_text("%016llx", static_cast<unsigned long long>(hash));
    for (const std::string& item : run.set) out += "\t" + item;
    out += "\n";
  }
  return out;
}

std::string manifest_path(const std::string& out_dir) { return (fs::path(out_dir) / "batch.manifest").string(); }

OutputLock::OutputLock(const std::string& out_dir) {
  const std::string path = (fs::path(out_dir) / ".lock").string();
  fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0 || flock(fd_, LOCK_EX | LOCK_NB) != 0)
    throw InputError(out_dir, 0, "another signalsim batch is writing to this --out directory");
}

OutputLock::~OutputLock() {
  if (fd_ >= 0) close(fd_);  // releases the lock
}

}  // namespace signalsim
