// The line a crash inside a plugin leaves; see plugin_crash_note.hpp. The handler only formats into
// a stack buffer and calls write(2), sigaction(2) and raise(3) (async-signal-safe).
#include "sut/plugin_crash_note.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstring>

namespace signalsim {
namespace {

constexpr int kSignals[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
struct sigaction g_previous[sizeof kSignals / sizeof kSignals[0]];
volatile sig_atomic_t g_installed = 0;
const char* volatile g_who = nullptr;
volatile double g_time = -1.0;
volatile int g_stderr = -1;  // a copy of the stderr of before SUMO started; -1: fd 2

const char* signal_name(int sig) {
  switch (sig) {
    case SIGSEGV: return "SIGSEGV";
    case SIGBUS: return "SIGBUS";
    case SIGFPE: return "SIGFPE";
    case SIGILL: return "SIGILL";
    case SIGABRT: return "SIGABRT";
    default: return "a signal";
  }
}

void append(char* buf, std::size_t& at, std::size_t size, const char* text) {
  for (; *text && at + 1 < size; ++text) buf[at++] = *text;
}

// "12.30": the time with two decimals, without printf.
void append_time(char* buf, std::size_t& at, std::size_t size, double t) {
  long long hundredths = std::llround(t * 100.0);
  char digits[32];
  int n = 0;
  do {
    digits[n++] = static_cast<char>('0' + hundredths % 10);
    hundredths /= 10;
    if (n == 2) digits[n++] = '.';
  } while (hundredths > 0 || n < 4);
  while (n > 0 && at + 1 < size) buf[at++] = digits[--n];
}

void on_fatal(int sig) {
  char line[640];
  std::size_t at = 0;
  if (const char* who = g_who) {
    append(line, at, sizeof line, "signalsim: ");
    append(line, at, sizeof line, who);
    append(line, at, sizeof line, " crashed (");
    append(line, at, sizeof line, signal_name(sig));
    append(line, at, sizeof line, ")");
    if (g_time >= 0.0) {
      append(line, at, sizeof line, " at t=");
      append_time(line, at, sizeof line, g_time);
      append(line, at, sizeof line, " s");
    } else {
      append(line, at, sizeof line, " at the start");
    }
    line[at++] = '\n';
    (void)!write(g_stderr >= 0 ? g_stderr : STDERR_FILENO, line, at);
  }
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i)
    if (kSignals[i] == sig) sigaction(sig, &g_previous[i], nullptr);
  raise(sig);
}

void install() {
  if (g_installed) return;
  struct sigaction action {};
  action.sa_handler = on_fatal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_NODEFER;
  for (std::size_t i = 0; i < sizeof kSignals / sizeof kSignals[0]; ++i) sigaction(kSignals[i], &action, &g_previous[i]);
  g_installed = 1;
}

}  // namespace

void keep_stderr_for_crash_notes() {
  const int copy = fcntl(STDERR_FILENO, F_DUPFD_CLOEXEC, 10);
  const int previous = g_stderr;
  g_stderr = copy;
  if (previous >= 0) close(previous);
}

PluginCallGuard::PluginCallGuard(const char* who, double time) {
  install();
  g_time = time;
  g_who = who;
}

PluginCallGuard::~PluginCallGuard() { g_who = nullptr; }

}  // namespace signalsim
