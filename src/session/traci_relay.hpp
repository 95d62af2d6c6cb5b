// TraciRelay: the only path between libtraci and a TraCI server (--connect, --gui). libtraci
// connects to the relay on 127.0.0.1, the relay to the server; a thread of its own forwards each of
// signalsim's requests as it is, and each answer only once it has read it whole and checked it
// (traci_framing.hpp). So libtraci, which trusts what it reads, never sees:
//   - bytes that are not TraCI (a length prefix SUMO's socket code asserts on or allocates 2 GiB for,
//     a status it cannot read): the relay ends the connection with the reason;
//   - a server that does not answer: each answer must arrive within the timeout, when there is one
//     (a stopped or frozen server; also one that accepts connections but never speaks TraCI);
//   - a wait that outlives SIGINT or SIGTERM (interruption.hpp): the relay looks every 0.1 s and
//     ends the connection at once.
// Whatever ended the connection, the relay closes both sockets: libtraci's waiting call fails at
// once, and so does every later one (a hand-back on a frozen server costs no more time); failure()
// says why. When libtraci closes its connection (Simulation::close), the relay closes the server's:
// the server sees this client leave. At most one message (kMaxTraciMessage) is held at a time.
#pragma once

#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>
#include <thread>

#include "session/sumo_session.hpp"  // SumoError
#include "session/traci_framing.hpp"

namespace signalsim::sumo {

/// The relay's limits (--traci-timeout, docs/sumo.md).
struct RelayLimits {
  /// [s] for the server to accept the connection, take a request, and answer it; 0: no limit (the
  /// --gui default: a user may pause sumo-gui)
  double timeout = 30.0;
  std::size_t max_message = kMaxTraciMessage;  ///< [bytes] the longest answer taken
};

class TraciRelay {
 public:
  /// Connects to the server at host:port (a refused connection is tried 5 times over a second: a
  /// server just started may not listen yet), listens on 127.0.0.1 for libtraci, and starts
  /// relaying. Throws SumoError "cannot connect to SUMO at HOST:PORT: ..." (host not found,
  /// refused or unreachable, no answer within the timeout), Interrupted after SIGINT/SIGTERM.
  TraciRelay(const std::string& host, int port, RelayLimits limits);
  /// Stops the thread and closes both connections.
  ~TraciRelay();
  TraciRelay(const TraciRelay&) = delete;
  TraciRelay& operator=(const TraciRelay&) = delete;

  /// The 127.0.0.1 port libtraci connects to (one connection is taken).
  int client_port() const { return client_port_; }
  /// Why the relay ended the connection (bytes that are not TraCI, no answer within the timeout, the
  /// server closing it, an interruption), one line naming HOST:PORT; "" while it relays or after
  /// libtraci closed its connection.
  std::string failure() const;

 private:
  void run() noexcept;
  void accept_client();
  int relay_request();
  void relay_answer(int request_command);
  int wait_readable(int first, int second, std::chrono::steady_clock::time_point until,
                    const std::string& timeout_reason) const;
  void send_all(int fd, const std::vector<std::uint8_t>& bytes, const std::string& timeout_reason) const;
  std::string not_traci(const std::string& why) const;
  std::string no_answer() const;

  std::string endpoint_;  // HOST:PORT, for the messages
  RelayLimits limits_;
  int server_ = -1;
  int listener_ = -1;
  int client_ = -1;
  int wake_[2] = {-1, -1};  // a byte written to wake_[1] stops the thread
  int client_port_ = 0;
  bool answered_ = false;  // the server has answered once (the handshake is over)
  mutable std::mutex mutex_;
  std::string failure_;
  std::thread thread_;
};

}  // namespace signalsim::sumo
