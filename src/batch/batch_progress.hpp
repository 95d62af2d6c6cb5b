// The batch's progress output: on a terminal one updating line ("[12/40] 1 failed, 0 errors, ETA
// 0:07") with every run that did not pass kept on screen above it; otherwise one plain line per
// finished run. Nothing with --quiet.
#pragma once

#include <chrono>
#include <cstddef>
#include <string>

#include "batch/results_table.hpp"
#include "batch/run_spec.hpp"

namespace signalsim {

class BatchProgress {
 public:
  BatchProgress(std::size_t total, bool quiet);

  /// A run finished with this row.
  void finished(const RunSpec& run, const ResultRow& row);
  /// Called often while waiting: redraws the terminal line about twice a second.
  void tick();
  /// Text appended to the terminal line (e.g. a cluster's pending and running tasks); "" for none.
  void set_extra(std::string extra) { extra_ = std::move(extra); }
  /// The batch ended: the last line is drawn and ended.
  void end();

 private:
  using Clock = std::chrono::steady_clock;
  void draw();

  std::size_t total_, done_ = 0, failed_ = 0, errors_ = 0;
  bool quiet_, tty_, drawn_ = false;
  std::string extra_;
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_draw_ = Clock::now();
};

/// "0:07", "1:02:03".
std::string duration_text(double seconds);

}  // namespace signalsim
