// The one line a crash inside a plugin leaves on stderr: while signalsim calls into a C ABI plugin,
// a fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) first writes "signalsim: decider
// lib:PATH crashed (SIGSEGV) at t=12.30 s", then the process dies of the signal as it would have
// (the handler before ours, if any, runs next). A batch keeps a worker's stderr in the run's error row.
#pragma once

namespace signalsim {

/// The stderr the crash line goes to: the process's stderr now (an embedded SUMO later sends fd 2 to
/// a capture file of its own while it runs). Call before SUMO starts; each call replaces the last.
void keep_stderr_for_crash_notes();

/// Marks a call into a plugin for as long as it lives: `who` ("decider lib:d.so", must outlive the
/// guard) at simulation time `time` [s] (negative: at the start). Installs the handlers once.
class PluginCallGuard {
 public:
  PluginCallGuard(const char* who, double time);
  ~PluginCallGuard();
  PluginCallGuard(const PluginCallGuard&) = delete;
  PluginCallGuard& operator=(const PluginCallGuard&) = delete;
};

}  // namespace signalsim
