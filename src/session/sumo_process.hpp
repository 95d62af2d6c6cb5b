// A SUMO program signalsim starts itself (sumo-gui for --gui): spawned with its output in a file,
// watched, and stopped by its PID. Plus a free TCP port on 127.0.0.1 for its TraCI server. POSIX only.
#pragma once

#include <string>
#include <sys/types.h>
#include <vector>

namespace signalsim::sumo {

/// A free TCP port on 127.0.0.1 (bound to port 0 and released: another program could take it in
/// between, which the caller sees as a failed start). Throws std::runtime_error.
int free_local_port();

class SumoProcess {
 public:
  /// Starts argv[0] (looked up in PATH) with argv, its stdout and stderr appended to `output_file`.
  /// Throws std::runtime_error when it cannot be started.
  SumoProcess(const std::vector<std::string>& argv, const std::string& output_file);
  /// Stops it if it still runs: SIGTERM, then SIGKILL after 2 s.
  ~SumoProcess();
  SumoProcess(const SumoProcess&) = delete;
  SumoProcess& operator=(const SumoProcess&) = delete;

  pid_t pid() const { return pid_; }
  /// Whether it still runs (reaps it when it ended).
  bool running();
  /// Its exit code (-1 while running or when killed by a signal).
  int exit_code() const { return exit_code_; }
  /// Waits up to `seconds` for it to end by itself; true when it did.
  bool wait_for_exit(double seconds);
  /// What it wrote so far (its output file), at most the last 64 kB.
  std::string output() const;

 private:
  pid_t pid_ = -1;
  int exit_code_ = -1;
  bool ended_ = false;
  std::string output_file_;
};

}  // namespace signalsim::sumo
