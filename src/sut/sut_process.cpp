// Spawning a line-speaking child and talking to it with deadlines; see sut_process.hpp.
#include "sut/sut_process.hpp"

#include <fstream>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <wordexp.h>

#include "sut/sut_text.hpp"

extern char** environ;

namespace signalsim {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr std::size_t kMaxLine = 64u << 20;  // a reply longer than this is refused
constexpr auto kBriefWait = std::chrono::microseconds(200);  // asked in a loop before sleeping on poll

Clock::time_point deadline_after(double seconds) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// Milliseconds left until `deadline` (0 when past), for poll().
int ms_left(Clock::time_point deadline) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
  return left <= 0 ? 0 : static_cast<int>(std::min<long long>(left + 1, 1 << 30));
}

bool executable_file(const fs::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(path.c_str(), X_OK) == 0;
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

}  // namespace

// SIGPIPE is blocked while any child lives (signalsim runs its steps on one thread): a write to a
// child that has gone fails with EPIPE instead of ending signalsim, without two mask changes a
// message. A SIGPIPE raised meanwhile is consumed before the mask is restored. The hold spans the
// run (the child is launched before SUMO starts): any other write to a closed pipe in that time,
// signalsim's own output included, fails with EPIPE instead, and a process started meanwhile
// (sumo-gui) starts with SIGPIPE blocked, which SUMO's TraCI server ignores anyway; the SUT's own
// process gets the default mask (the posix_spawn attributes).
namespace {

sigset_t sigpipe_alone() {
  sigset_t pipe;
  sigemptyset(&pipe);
  sigaddset(&pipe, SIGPIPE);
  return pipe;
}

bool sigpipe_pending() {
  sigset_t pending;
  sigpending(&pending);
  return sigismember(&pending, SIGPIPE) == 1;
}

}  // namespace

SigpipeHold::SigpipeHold() {
  if (holders_++ > 0) return;
  const sigset_t pipe = sigpipe_alone();
  was_pending_ = sigpipe_pending();
  pthread_sigmask(SIG_BLOCK, &pipe, &old_mask_);
}

SigpipeHold::~SigpipeHold() {
  if (--holders_ > 0) return;
  if (!was_pending_ && sigpipe_pending()) {
    const sigset_t pipe = sigpipe_alone();
    const timespec zero{0, 0};
    sigtimedwait(&pipe, nullptr, &zero);
  }
  pthread_sigmask(SIG_SETMASK, &old_mask_, nullptr);
}

std::vector<std::string> split_command(const std::string& command) {
  wordexp_t words{};
  const int rc = wordexp(command.c_str(), &words, WRDE_NOCMD);
  if (rc != 0) {
    if (rc == WRDE_NOSPACE) wordfree(&words);
    if (rc == WRDE_CMDSUB) throw SutProcessError("command substitution ($(...) or `...`) is not allowed");
    if (rc == WRDE_BADCHAR) throw SutProcessError("a character the shell would interpret (| & ; < > ( ) { } or a newline) is not allowed; run such a command through sh -c '...'");
    if (rc == WRDE_SYNTAX) throw SutProcessError("unbalanced quotes");
    throw SutProcessError("cannot split the command into words");
  }
  std::vector<std::string> argv(words.we_wordv, words.we_wordv + words.we_wordc);
  wordfree(&words);
  if (argv.empty()) throw SutProcessError("the command is empty");
  return argv;
}

std::string find_program(const std::string& word, const std::string& work_dir) {
  if (word.find('/') != std::string::npos) {
    const fs::path path = fs::path(word).is_absolute() ? fs::path(word) : fs::path(work_dir) / word;
    return executable_file(path) ? fs::absolute(path).lexically_normal().string() : std::string();
  }
  const char* env = std::getenv("PATH");
  const std::string dirs = env ? env : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  while (begin <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', begin), dirs.size());
    const fs::path dir = end == begin ? fs::path(".") : fs::path(dirs.substr(begin, end - begin));
    if (executable_file(dir / word)) return fs::absolute(dir / word).lexically_normal().string();
    begin = end + 1;
  }
  return "";
}

SutProcess::SutProcess(const std::string& program, const std::vector<std::string>& argv, const std::string& work_dir,
                       const std::string& stderr_path) {
  int to_child[2], from_child[2];
  if (pipe2(to_child, O_CLOEXEC) != 0) throw SutProcessError(std::string("cannot make a pipe: ") + std::strerror(errno));
  if (pipe2(from_child, O_CLOEXEC) != 0) {
    ::close(to_child[0]);
    ::close(to_child[1]);
    throw SutProcessError(std::string("cannot make a pipe: ") + std::strerror(errno));
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, to_child[0], 0);
  posix_spawn_file_actions_adddup2(&actions, from_child[1], 1);
  const std::string err = fs::absolute(stderr_path).string();
  stderr_path_ = err;
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addchdir_np(&actions, work_dir.c_str());
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGCHLD, SIGQUIT, SIGHUP}) sigaddset(&defaults, s);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setpgroup(&attr, 0);  // its own group: killing it ends what it started too
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETPGROUP);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const int rc = posix_spawn(&pid_, program.c_str(), &actions, &attr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attr);
  ::close(to_child[0]);
  ::close(from_child[1]);
  in_ = to_child[1];
  out_ = from_child[0];
  if (rc != 0) {
    pid_ = -1;
    close_fd(in_);
    close_fd(out_);
    throw SutProcessError("cannot start " + program + " in " + work_dir + ": " + std::strerror(rc));
  }
  fcntl(in_, F_SETFL, fcntl(in_, F_GETFL) | O_NONBLOCK);
  fcntl(out_, F_SETFL, fcntl(out_, F_GETFL) | O_NONBLOCK);
}

SutProcess::~SutProcess() { kill_and_reap(); }

void SutProcess::kill_and_reap() {
  close_fd(in_);
  close_fd(out_);
  if (pid_ > 0 && !reaped_) {
    ::kill(-pid_, SIGKILL);
    ::kill(pid_, SIGKILL);
    while (::waitpid(pid_, &status_, 0) < 0 && errno == EINTR) {
    }
    reaped_ = true;
  }
}

bool SutProcess::fill(int timeout_ms) {
  if (eof_) return false;
  pollfd p{out_, POLLIN, 0};
  const int ready = ::poll(&p, 1, timeout_ms);
  if (ready < 0 && errno == EINTR) throw SutProcessError("interrupted by a signal while waiting");
  if (ready > 0) read_available();
  return !eof_;
}

bool SutProcess::read_available() {
  if (eof_) return false;
  char chunk[65536];
  const ssize_t n = ::read(out_, chunk, sizeof chunk);
  if (n > 0) {
    buffer_.append(chunk, static_cast<std::size_t>(n));
    if (buffer_.size() > kMaxLine) throw SutProcessError("wrote a line longer than 64 MiB");
    return true;
  }
  if (n == 0 || (errno != EAGAIN && errno != EINTR)) eof_ = true;
  return false;
}

// A reply usually follows within tens of microseconds: asking for it in a short loop spares signalsim
// going to sleep and being woken for each step, which costs more than the reply itself on a VM.
bool SutProcess::await_reply_briefly() {
  const auto until = Clock::now() + kBriefWait;
  do {
    if (read_available() && buffer_.find('\n') != std::string::npos) return true;
  } while (!eof_ && Clock::now() < until);
  return false;
}

// Why the child is gone, and the last line of its stderr (a Python traceback's last line, "can't open
// file ..."): the one line of the run's error says what the SUT said.
std::string SutProcess::ended_how(const char* when) {
  std::string reason = exit_reason() + when;
  std::ifstream in(stderr_path_, std::ios::binary);
  std::string line, last;
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  for (char& c : last)
    if (static_cast<unsigned char>(c) < 0x20) c = ' ';
  if (last.size() > 200) last = last.substr(0, 200) + "...";
  if (!last.empty()) reason += "; its stderr ends: " + last;
  return reason;
}

std::string SutProcess::exit_reason() {
  if (!reaped_ && pid_ > 0) {  // its stdout or stdin closed: it is normally exiting; give it a second
    const auto deadline = deadline_after(1.0);
    for (;;) {
      const pid_t r = ::waitpid(pid_, &status_, WNOHANG);
      if (r == pid_ || (r < 0 && errno == ECHILD)) {
        reaped_ = r == pid_;
        if (r < 0) return "ended";
        break;
      }
      if (Clock::now() > deadline) return "closed its standard output";
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
  }
  if (WIFEXITED(status_)) return "exited with status " + std::to_string(WEXITSTATUS(status_));
  if (WIFSIGNALED(status_)) {
    const int s = WTERMSIG(status_);
    const char* name = sigabbrev_np(s);
    return "killed by signal " + std::to_string(s) + (name ? std::string(" (SIG") + name + ")" : std::string());
  }
  return "ended";
}

void SutProcess::write(const std::string& line, double timeout) {
  const auto deadline = deadline_after(timeout);
  std::size_t done = 0;
  // A pipe has room for a message the child is waiting for: written at once, no poll first.
  if (const ssize_t n = ::write(in_, line.data(), line.size()); n > 0) done = static_cast<std::size_t>(n);
  else if (n < 0 && errno == EPIPE) throw SutProcessError(ended_how(" before reading the message"));
  while (done < line.size()) {
    pollfd p[2] = {{in_, POLLOUT, 0}, {out_, POLLIN, 0}};
    const int ready = ::poll(p, eof_ ? 1 : 2, ms_left(deadline));
    if (ready == 0) throw SutProcessError("did not read its input within " + seconds_text(timeout) + " s");
    if (ready < 0 && errno == EINTR) throw SutProcessError("interrupted by a signal while waiting");
    if (ready < 0) continue;
    if (!eof_ && (p[1].revents & (POLLIN | POLLHUP))) fill(0);  // keep its output, never block it
    if (!(p[0].revents & (POLLOUT | POLLERR | POLLHUP))) continue;
    const ssize_t n = ::write(in_, line.data() + done, line.size() - done);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (errno == EPIPE) {
      throw SutProcessError(ended_how(" before reading the message"));
    } else if (errno != EAGAIN && errno != EINTR) {
      throw SutProcessError(std::string("cannot write to it: ") + std::strerror(errno));
    }
  }
}

// The short loop runs only while replies come within it: a SUT that takes longer (or a machine whose
// cores are all busy, `batch --jobs` with exec SUTs) gets its reply waited for on poll alone, and the
// loop comes back once a reply is quick again.
std::string SutProcess::read_line(double timeout) {
  const auto asked = Clock::now();
  const auto deadline = deadline_after(timeout);
  bool spin = quick_replies_;
  for (;;) {
    const std::size_t nl = buffer_.find('\n');
    if (nl != std::string::npos) {
      std::string line = buffer_.substr(0, nl);
      buffer_.erase(0, nl + 1);
      if (!line.empty() && line.back() == '\r') line.pop_back();
      quick_replies_ = Clock::now() - asked <= kBriefWait;
      return line;
    }
    if (eof_) throw SutProcessError(ended_how(" before replying"));
    if (Clock::now() >= deadline) throw SutProcessError("no reply within " + seconds_text(timeout) + " s");
    if (!(spin && await_reply_briefly())) fill(ms_left(deadline));
    spin = false;  // once a step
  }
}

bool SutProcess::has_unread_output() {
  if (buffer_.empty()) read_available();
  return !buffer_.empty();
}

std::string SutProcess::close(double timeout) {
  close_fd(in_);
  const auto deadline = deadline_after(timeout);
  while (!eof_ && Clock::now() < deadline) fill(ms_left(deadline));
  while (!reaped_ && Clock::now() < deadline) {
    const pid_t r = ::waitpid(pid_, &status_, WNOHANG);
    if (r == pid_ || (r < 0 && errno == ECHILD)) {
      reaped_ = true;
      if (r < 0) status_ = 0;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  std::string rest = std::move(buffer_);
  buffer_.clear();
  if (!reaped_) {  // still running after the timeout: ended, not a fault of the run
    kill_and_reap();
    return rest;
  }
  close_fd(out_);
  if (!WIFEXITED(status_) || WEXITSTATUS(status_) != 0) throw SutProcessError(ended_how(" after bye"));
  return rest;
}

}  // namespace signalsim
