// SIGINT/SIGTERM as a flag while a batch's runs are under way (interrupt_guard.hpp).
#include "batch/interrupt_guard.hpp"

namespace signalsim {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;
int g_depth = 0;  // guards alive (one thread: the batch's)
extern "C" void on_interrupt(int) { g_interrupted = 1; }

}  // namespace

InterruptGuard::InterruptGuard() {
  if (g_depth++ == 0) g_interrupted = 0;
  struct sigaction sa {};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, &old_int_);
  sigaction(SIGTERM, &sa, &old_term_);
  struct sigaction ignore {};
  ignore.sa_handler = SIG_IGN;
  sigemptyset(&ignore.sa_mask);
  sigaction(SIGPIPE, &ignore, &old_pipe_);
  // SIGCHLD at its default: inherited as ignored (nohup, some CI runners), the kernel would reap the
  // workers itself and waitpid could not tell a crash (SIGSEGV) from a clean end.
  struct sigaction child {};
  child.sa_handler = SIG_DFL;
  sigemptyset(&child.sa_mask);
  sigaction(SIGCHLD, &child, &old_chld_);
}

InterruptGuard::~InterruptGuard() {
  --g_depth;
  sigaction(SIGINT, &old_int_, nullptr);
  sigaction(SIGTERM, &old_term_, nullptr);
  sigaction(SIGPIPE, &old_pipe_, nullptr);
  sigaction(SIGCHLD, &old_chld_, nullptr);
}

bool InterruptGuard::interrupted() { return g_interrupted != 0; }

void InterruptGuard::throw_if_interrupted() {
  if (interrupted()) throw BatchInterrupted();
}

}  // namespace signalsim
