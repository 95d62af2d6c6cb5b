// One child process of a batch (child_supervisor.hpp watches them): started in a process group of
// its own (the batch stops it as a whole) that dies with the batch (PR_SET_PDEATHSIG), stdin and
// stdout on /dev/null unless the caller hands it descriptors, its stderr into a pipe read without
// blocking (at most 64 KiB kept). The value owns the process: unless reaped, it is killed
// (SIGKILL to its group) and reaped when the value ends. Also: a program run in the foreground
// (run_foreground), this program's path, a signal's name.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

struct pollfd;

namespace signalsim {

/// A descriptor the child gets: `target` in the child is a copy of the parent's `source`.
struct ChildFd {
  int target = -1;
  int source = -1;
};

struct ChildStart {
  std::vector<std::string> argv;  ///< argv[0] is the program path
  std::vector<ChildFd> fds;       ///< besides stdin/stdout (/dev/null) and stderr (the pipe); may replace stdin
  /// Run in the fork instead of exec'ing argv (the caller makes sure this process has one thread):
  /// every descriptor above the highest target is closed, SIGINT/SIGTERM/SIGALRM back at their
  /// default, then exit(entry()).
  int (*entry)() = nullptr;
};

class ChildProcess {
 public:
  ChildProcess() = default;
  /// Starts it. Throws std::runtime_error ("cannot create a pipe: ...", "cannot fork: ...").
  static ChildProcess start(const ChildStart& how);
  ~ChildProcess();
  ChildProcess(ChildProcess&& other) noexcept;
  ChildProcess& operator=(ChildProcess&& other) noexcept;
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }

  /// Adds its stderr pipe to `fds` (POLLIN) while it is open.
  void add_poll_fd(std::vector<pollfd>& fds) const;
  /// Reads what its stderr pipe holds now; closes the pipe at its end.
  void read_stderr();
  /// What it wrote on stderr since the last call.
  std::string take_stderr();
  /// Its stderr reached its end: it has ended or is ending.
  bool stderr_closed() const { return err_fd_ < 0; }

  /// Sends `signal` to its process group (not once it is reaped).
  void signal_group(int signal);
  /// Reaps it (waitpid); true once it has ended. wait_status() is then valid.
  bool reap(bool block);
  bool reaped() const { return reaped_; }
  int wait_status() const { return status_; }

 private:
  void release();

  pid_t pid_ = -1;
  int err_fd_ = -1;  // read end of its stderr pipe; -1 once closed
  bool reaped_ = false;
  int status_ = 0;
  std::string err_;
};

/// Runs a program in the foreground (inherits stdin, stdout, stderr and the process group) and
/// waits. Returns its exit code, or 128 + signal; 127 when it cannot be started.
int run_foreground(const std::vector<std::string>& argv);

/// This program's own executable (/proc/self/exe).
std::string self_executable();

/// Closes `fd` when it is open and sets it to -1.
void close_fd(int& fd);

/// "SIGKILL", "SIGSEGV", ... or "signal N".
std::string signal_name(int signal);

}  // namespace signalsim
