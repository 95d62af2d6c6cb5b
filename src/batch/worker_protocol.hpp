// The line protocol between a batch and its persistent workers (`signalsim worker`, docs/batch.md
// "Persistent workers"):
//
//   batch -> worker, on the worker's stdin: one request per line, the arguments of a `signalsim run`
//     command line (run SCENARIO --out DIR --quiet --set K=V ...), separated by tabs; a backslash,
//     tab, newline or carriage return inside an argument is written \\ \t \n \r
//   worker -> batch, on the worker's file descriptor 3: "done CODE" once the run has ended and its
//     files are written, CODE being the exit code `signalsim run` would have had; "done CODE last"
//     when the worker ends after this run (it was interrupted, or its SUMO cannot start afresh)
//   end of the requests (stdin closed): the worker exits 0
//
// The worker's stderr stays a pipe of its own: everything it writes between two replies belongs to
// the run in between.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace signalsim {

/// The file descriptor a worker replies on.
inline constexpr int kWorkerReplyFd = 3;

/// One request line, with its newline.
std::string encode_worker_request(const std::vector<std::string>& args);
/// The arguments of a request line (without its newline); nullopt for an empty line or a bad escape.
std::optional<std::vector<std::string>> decode_worker_request(const std::string& line);

struct WorkerReply {
  int exit_code = 0;
  bool last = false;  ///< the worker ends after this reply
};

/// "done CODE\n" or "done CODE last\n".
std::string encode_worker_reply(const WorkerReply& reply);
/// A reply line (without its newline); nullopt when it is not one.
std::optional<WorkerReply> decode_worker_reply(const std::string& line);

}  // namespace signalsim
