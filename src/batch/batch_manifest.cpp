// The batch manifest and the output directory's lock (batch_manifest.hpp).
#include "batch/batch_manifest.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <vector>

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

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; std::getline(in, field, '\t');) fields.push_back(field);
  return fields;
}

// What differs between two lines of the same run index: "run I (FILE): ..."
std::string run_difference(const std::vector<std::string>& was, const std::vector<std::string>& is) {
  const std::string run = "run " + is[0] + " (" + is[1] + "): ";
  if (was.size() < 3 || was[1] != is[1]) return run + "another scenario file than " + (was.size() > 1 ? was[1] : "?");
  if (was[2] != is[2])
    return run + (is[2] == "-" ? "the file is gone" : "the file changed (size or modification time)");
  return run + "other --set values";
}

}  // namespace

std::string manifest_difference(const std::string& earlier, const std::string& now) {
  if (earlier == now) return "";
  const std::vector<std::string> was = lines_of(earlier), is = lines_of(now);
  if (was.empty() || is.empty() || was[0] != is[0]) return "the manifest there is of another signalsim version";
  for (std::size_t i = 1; i < std::min(was.size(), is.size()); ++i)
    if (was[i] != is[i]) return run_difference(fields_of(was[i]), fields_of(is[i]));
  return "the batch there had " + std::to_string(was.size() - 1) + " runs, this one " + std::to_string(is.size() - 1);
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
