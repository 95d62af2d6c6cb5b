// The child's side of starting a batch's worker process, between fork and exec: shared by
// process_pool (one process per run) and worker_process (persistent workers). Only
// async-signal-safe calls until exec: the parent may hold locks another of its threads took.
#pragma once

#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstring>

namespace signalsim {

/// The child leads a process group of its own (the batch stops it as a whole) and dies with the
/// batch; a parent that is already gone (`parent` is the pid before fork) ends it at once.
inline void join_own_group_tied_to(pid_t parent) {
  setpgid(0, 0);
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // never outlive the batch
  if (getppid() != parent) _exit(127);
}

/// execv(args[0], args); when that fails, "signalsim: cannot start worker: PROGRAM" on stderr and
/// exit code 127.
[[noreturn]] inline void exec_worker_or_exit(char* const* args) {
  execv(args[0], args);
  const char* msg = "signalsim: cannot start worker: ";
  (void)!write(STDERR_FILENO, msg, std::strlen(msg));
  (void)!write(STDERR_FILENO, args[0], std::strlen(args[0]));
  (void)!write(STDERR_FILENO, "\n", 1);
  _exit(127);
}

}  // namespace signalsim
