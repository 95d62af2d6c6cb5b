// What ties an output directory to one batch: OUT/batch.manifest (every run's scenario, the file's
// size and modification time and its --set items; --resume keeps earlier rows only when it is unchanged) and the lock
// that keeps a second batch out of the same --out while one writes there.
#pragma once

#include <string>
#include <vector>

#include "batch/run_spec.hpp"

namespace signalsim {

/// The manifest text: one line per run (index, scenario, "SIZE:MTIME_NS" of the scenario file from
/// stat, "-" when it has none, every --set), after a "signalsim batch manifest 2" line. No file is
/// read: a changed file shows as another size or modification time (an edit that keeps both, within
/// the file system's time resolution, is not seen; a file touched without a change is).
std::string batch_manifest(const std::vector<RunSpec>& runs);

/// What differs between an earlier manifest and this batch's, for a refusal: the first run whose
/// scenario, file stamp or --set values differ ("run 3 (a/b.yaml): the file changed (size or
/// modification time)"), a different number of runs, or an earlier manifest version. "" when equal.
std::string manifest_difference(const std::string& earlier, const std::string& now);

/// OUT/batch.manifest
std::string manifest_path(const std::string& out_dir);

/// flock on OUT/.lock for as long as it lives; throws InputError when another batch holds it.
class OutputLock {
 public:
  explicit OutputLock(const std::string& out_dir);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  int fd_ = -1;
};

}  // namespace signalsim
