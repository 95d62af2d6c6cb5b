// `signalsim worker` (hidden): a persistent worker of `batch`, `sweep`, `check` and `compare`
// (batch/worker_pool.hpp). It reads `signalsim run` command lines on stdin, one a line
// (batch/worker_protocol.hpp), runs each with the `run` command itself - parsed by a fresh copy of
// its command line, so nothing of one run's options reaches the next - and replies "done CODE" on
// file descriptor 3 once the run's files are written. Between runs it puts back what a fresh process
// would have fresh: the notes printed, the working directory. libsumo is closed at the end of each
// run (session/session_embedded.cpp) and starts again with the next; after a run whose SUMO failed to
// start the worker ends (sumo::embedded_sumo_reusable), and the batch starts another. SIGINT/SIGTERM
// stop the run under way as they stop `run` (its reply says 130 or 143) and end the worker. The
// batch commands usually fork into serve() rather than exec this command (worker_process.hpp).
#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "app/command.hpp"
#include "batch/worker_process.hpp"
#include "batch/worker_protocol.hpp"
#include "scenario/notes.hpp"
#include "session/interruption.hpp"
#include "session/sumo_session.hpp"

namespace signalsim::app {
namespace {
namespace fs = std::filesystem;

// The next line of stdin (without its newline); nullopt at the end or when a signal interrupts the read.
std::optional<std::string> read_request(int fd, std::string& buffer) {
  while (true) {
    if (const auto end = buffer.find('\n'); end != std::string::npos) {
      std::string line = buffer.substr(0, end);
      buffer.erase(0, end + 1);
      return line;
    }
    char chunk[4096];
    const ssize_t n = read(fd, chunk, sizeof chunk);
    if (n > 0) {
      buffer.append(chunk, static_cast<std::size_t>(n));
      continue;
    }
    if (n < 0 && errno == EINTR && !sumo::interruption_requested()) continue;
    return std::nullopt;  // end of the requests, a read error, or a signal
  }
}

bool write_reply(const WorkerReply& done) {
  const std::string reply = encode_worker_reply(done);
  for (std::size_t at = 0; at < reply.size();) {
    const ssize_t n = write(kWorkerReplyFd, reply.data() + at, reply.size() - at);
    if (n > 0) at += static_cast<std::size_t>(n);
    else if (n < 0 && errno == EINTR) continue;
    else return false;
  }
  return true;
}

// One request: `signalsim run ...` through the run command's own parser and function.
int run_request(const std::vector<std::string>& args) {
  if (args.empty() || args.front() != "run")
    return report_bad_input("worker: a request that is not a `signalsim run` command line");
  CLI::App app{"signalsim worker run"};
  app.require_subcommand(1);
  const Command run = add_run_command(app);
  std::vector<const char*> argv = {"signalsim"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    return report_bad_input(std::string("worker: ") + e.what());
  }
  return run.run();
}

int serve() {
  if (fcntl(kWorkerReplyFd, F_GETFD) < 0)
    return report_bad_input("worker: batch, sweep, check and compare start their workers themselves "
                            "(file descriptor 3, for the replies, is not open)");
  fcntl(kWorkerReplyFd, F_SETFD, FD_CLOEXEC);  // not for the programs a run starts (signalsim-plot)
  sumo::install_interruption_handlers();        // also between runs: SIGTERM ends the worker cleanly
  // The requests move to a descriptor of their own, closed on exec, and stdin becomes /dev/null as
  // in a process of its own (--isolate): a program a run starts (a TraCI sumo, signalsim-plot) must not
  // hold the request pipe open (the batch would not see this worker die) nor read its requests.
  const int requests = fcntl(STDIN_FILENO, F_DUPFD_CLOEXEC, 10);
  const int null = open("/dev/null", O_RDONLY | O_CLOEXEC);
  if (requests < 0 || null < 0 || dup2(null, STDIN_FILENO) < 0)
    return report_bad_input("worker: cannot move the request pipe off stdin");
  close(null);
  std::error_code error;
  const fs::path start_dir = fs::current_path(error);
  std::string buffer;
  while (const std::optional<std::string> line = read_request(requests, buffer)) {
    if (sumo::interruption_requested()) break;
    const auto args = decode_worker_request(*line);
    if (!args) return report_bad_input("worker: a request line that is not tab-separated arguments");
    forget_printed_notes();
    set_notes_enabled(true);
    const int code = run_request(*args);
    std::fflush(nullptr);
    std::cerr.flush();
    // Interrupted, the worker ends; after a failed SUMO start too, since the next run would not
    // start as in a fresh process: the batch gives the next run a new worker.
    const bool interrupted = sumo::interruption_requested();
    const bool last = interrupted || !sumo::embedded_sumo_reusable();
    if (!write_reply({code, last})) return code;  // the batch has gone
    if (last) return interrupted ? 128 + sumo::interruption_signal() : 0;
    if (fs::current_path(error) != start_dir) fs::current_path(start_dir, error);
  }
  const int signal = sumo::interruption_signal();
  return signal ? 128 + signal : 0;
}

// Before the first worker is forked: libsumo's module, which the forked workers then share. A module
// that cannot be loaded is each run's error (its worker tries again and says why), not the batch's.
void load_sumo_for_workers() {
  try {
    sumo::load_embedded_backend();
  } catch (const sumo::SumoError&) {
  }
}

}  // namespace

Command add_worker_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("worker", "A persistent worker of batch, sweep, check and compare (internal)");
  sub->group("");  // hidden from --help: the batch commands start it
  set_worker_entry(&serve, &load_sumo_for_workers);  // the batch commands fork into it (batch/worker_process.hpp)
  return {sub, [] { return serve(); }};
}

}  // namespace signalsim::app
