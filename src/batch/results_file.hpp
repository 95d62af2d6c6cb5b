// OUT/results.csv on a disk that may fill up while the batch runs. Each rewrite goes through
// write_file_atomically (a failed one leaves the previous complete file and no .tmp); beside it a
// reserve file (OUT/.results.reserve, about twice the table's size, at least 64 kB) holds space
// back: when a rewrite fails, the reserve is given up and the rewrite tried again, so the rows
// finished until the disk filled still reach results.csv. The reserve is removed at the end.
#pragma once

#include <string>

namespace signalsim {

class ResultsFile {
 public:
  explicit ResultsFile(std::string path);
  ~ResultsFile();
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;

  /// Rewrites the file with `content`; false (see error()) when even the reserve did not make room.
  bool write(const std::string& content);
  /// The last failure: "<path>: cannot write: No space left on device"; empty after a success.
  const std::string& error() const { return error_; }

 private:
  void reserve(std::size_t bytes);
  void release();
  std::string path_;
  std::string reserve_path_;
  std::size_t reserved_ = 0;
  std::string error_;
};

}  // namespace signalsim
