// The batch manifest and the output directory's lock (batch_manifest.hpp).
#include "batch/batch_manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <map>

#include "scenario/input_error.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// The file's size and modification time [ns] as "SIZE:MTIME"; "-" for a file that cannot be stat'ed.
// Read from the file system's metadata: the parent never reads a scenario's contents.
std::string file_stamp(const std::string& path) {
  struct stat st {};
  if (stat(path.c_str(), &st) != 0) return "-";
  const long long ns = static_cast<long long>(st.st_mtim.tv_sec) * 1000000000LL + st.st_mtim.tv_nsec;
  return std::to_string(static_cast<long long>(st.st_size)) + ":" + std::to_string(ns);
}

}  // namespace

std::string batch_manifest(const std::vector<RunSpec>& runs) {
  std::string out = "signalsim batch manifest 2\n";
  std::map<std::string, std::string> stamps;  // a scenario file is stat'ed once, however many runs it has
  for (const RunSpec& run : runs) {
    auto [it, fresh] = stamps.try_emplace(run.scenario);
    if (fresh) it->second = file_stamp(run.scenario);
    out += std::to_string(run.index) + "\t" + run.scenario + "\t" + it->second;
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
