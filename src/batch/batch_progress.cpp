// The batch's progress line (batch_progress.hpp).
#include "batch/batch_progress.hpp"

#include <unistd.h>

#include <cstdio>

#include "batch/run_rows.hpp"
#include "core/number_text.hpp"

namespace signalsim {

std::string duration_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  if (s >= 3600) return format_text("%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  return format_text("%ld:%02ld", s / 60, s % 60);
}

BatchProgress::BatchProgress(std::size_t total, bool quiet)
    : total_(total), quiet_(quiet), tty_(isatty(STDOUT_FILENO) == 1) {}

void BatchProgress::finished(const RunSpec& run, const ResultRow& row) {
  ++done_;
  const std::string status = row.cells.at("status");
  failed_ += status == "failed";
  errors_ += status == "error";
  if (quiet_) return;
  std::string line = format_text("[%zu/%zu] ", done_, total_) + describe_run(run) + ": " + status;
  if (status == "error") line += ": " + row.cells.at("error");
  else line += " (" + row.cells.at("wall_time") + " s)";
  if (!tty_) {
    std::printf("%s\n", line.c_str());
    std::fflush(stdout);
    return;
  }
  if (status != "passed") std::printf("\r\033[K%s\n", line.c_str());  // keep failures (and notices) on screen
  draw();
}

void BatchProgress::tick() {
  if (!quiet_ && tty_ && Clock::now() - last_draw_ > std::chrono::milliseconds(500)) draw();
}

void BatchProgress::end() {
  if (!quiet_ && tty_ && drawn_) {
    draw();
    std::printf("\n");
    std::fflush(stdout);
  }
}

void BatchProgress::draw() {
  const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
  std::string eta = "--:--";
  if (done_ > 0) eta = duration_text(elapsed / static_cast<double>(done_) * static_cast<double>(total_ - done_));
  std::printf("\r\033[K[%zu/%zu] %zu failed, %zu error%s, ETA %s%s%s", done_, total_, failed_, errors_,
              errors_ == 1 ? "" : "s", eta.c_str(), extra_.empty() ? "" : ", ", extra_.c_str());
  std::fflush(stdout);
  drawn_ = true;
  last_draw_ = Clock::now();
}

}  // namespace signalsim
