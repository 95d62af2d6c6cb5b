#include "batch/results_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "report/atomic_file.hpp"

namespace signalsim {

namespace {
constexpr std::size_t kMinReserve = 64 * 1024;
}

ResultsFile::ResultsFile(std::string path)
    : path_(std::move(path)),
      reserve_path_((std::filesystem::path(path_).parent_path() / ".results.reserve").string()) {}

ResultsFile::~ResultsFile() { release(); }

void ResultsFile::release() {
  ::unlink(reserve_path_.c_str());
  reserved_ = 0;
}

void ResultsFile::reserve(std::size_t bytes) {
  if (bytes <= reserved_) return;
  const int fd = ::open(reserve_path_.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) return;  // best effort: without a reserve the rewrite simply has no fallback
  const bool ok = ::posix_fallocate(fd, 0, static_cast<off_t>(bytes)) == 0;
  ::close(fd);
  if (ok) reserved_ = bytes;
  else release();
}

bool ResultsFile::write(const std::string& content) {
  const std::size_t wanted = std::max(kMinReserve, 2 * content.size());
  for (int attempt = 0; attempt < 2; ++attempt) {
    try {
      write_file_atomically(path_, content);
      error_.clear();
      reserve(wanted);
      return true;
    } catch (const std::exception& e) {
      error_ = e.what();
      if (reserved_ == 0) return false;
      release();  // give the held-back space to this rewrite
    }
  }
  return false;
}

}  // namespace signalsim
