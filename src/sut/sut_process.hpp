// A child process spoken to in lines (docs/decider.md "JSON lines"): the command split into words,
// its program found, spawned in its working directory with its stdin and stdout on pipes and its
// stderr into a file, lines written and read with a deadline, and always killed and reaped. Faults
// throw SutProcessError with the reason only ("no reply within 5 s"); the adapter names SUT and step.
#pragma once

#include <csignal>
#include <string>
#include <sys/types.h>
#include <vector>

#include <stdexcept>

namespace signalsim {

class SutProcessError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Shell-like word splitting of a command (wordexp with WRDE_NOCMD: quotes, backslashes, $VAR and ~
/// are expanded; command substitution is refused). Throws SutProcessError with the reason.
std::vector<std::string> split_command(const std::string& command);

/// The program a command's first word names: a word with a '/' is a path relative to `work_dir`;
/// else the first executable file of that name on PATH. "" when there is none.
std::string find_program(const std::string& word, const std::string& work_dir);

/// SIGPIPE blocked on signalsim's (one) thread while any holder lives; see sut_process.cpp.
class SigpipeHold {
 public:
  SigpipeHold();
  ~SigpipeHold();
  SigpipeHold(const SigpipeHold&) = delete;
  SigpipeHold& operator=(const SigpipeHold&) = delete;

 private:
  static inline int holders_ = 0;
  static inline bool was_pending_ = false;
  static inline sigset_t old_mask_{};
};

class SutProcess {
 public:
  /// Spawns `program` (found by find_program) with `argv` in `work_dir`; its stderr is written to
  /// `stderr_path` (truncated). Throws SutProcessError.
  SutProcess(const std::string& program, const std::vector<std::string>& argv, const std::string& work_dir,
             const std::string& stderr_path);
  ~SutProcess();  // kills (the whole process group) and reaps the child
  SutProcess(const SutProcess&) = delete;
  SutProcess& operator=(const SutProcess&) = delete;

  /// Writes `line` (ending in '\n') whole within `timeout` [s]; throws if the child is gone or
  /// does not read it. Output the child writes meanwhile is kept for read_line.
  void write(const std::string& line, double timeout);
  /// The next line the child writes (without its '\n'), within `timeout` [s].
  std::string read_line(double timeout);
  /// Whether the child has written anything not yet read (what has arrived by now: no waiting).
  bool has_unread_output();
  /// Whether what has been read holds more than the lines taken (no system call).
  bool has_buffered_output() const { return !buffer_.empty(); }
  /// After the last message: closes the child's stdin and waits `timeout` [s] for it to exit (then
  /// kills it). Returns what it wrote after the last reply (normally ""). Throws when it exited
  /// with a non-zero status or by a signal.
  std::string close(double timeout);

 private:
  bool fill(int timeout_ms);  // waits up to timeout_ms for output and reads it into buffer_; false on EOF
  bool read_available();     // reads what has arrived, without waiting; false when nothing had
  bool await_reply_briefly();  // read_available in a short busy loop: true once a line is complete
  bool quick_replies_ = true;  // the last reply came within the short loop's time (read_line)
  std::string exit_reason();  // why the child is gone ("exited with status 3", "killed by signal 11")
  std::string ended_how(const char* when);  // the same, `when`, and the last line the child wrote to its stderr file
  std::string stderr_path_;
  void kill_and_reap();

  SigpipeHold sigpipe_;  // held before the constructor spawns the child, released after it is reaped
  pid_t pid_ = -1;
  int in_ = -1;   // the child's stdin (our writing end)
  int out_ = -1;  // the child's stdout (our reading end)
  bool eof_ = false;
  std::string buffer_;
  int status_ = 0;
  bool reaped_ = false;
};

}  // namespace signalsim
