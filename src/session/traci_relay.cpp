// The relay between libtraci and a SUMO server (traci_relay.hpp): connecting, the relaying thread,
// and why it ended.
#include "session/traci_relay.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>

#include "core/number_parsing.hpp"
#include "session/interruption.hpp"

namespace signalsim::sumo {
namespace {

using Clock = std::chrono::steady_clock;
constexpr int kTickMs = 100;          // how often a wait looks for an interruption
constexpr int kConnectAttempts = 5;   // a refused connection, 0.2 s apart
constexpr std::size_t kReadChunk = 65536;
constexpr double kAcceptSeconds = 10.0;  // for libtraci to connect to the relay, just after it started

// `seconds` from now; no limit (the latest time there is) for 0 or less.
Clock::time_point deadline_after(double seconds) {
  if (!(seconds > 0.0)) return Clock::time_point::max();
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// How long one wait may last before the next look for an interruption or the deadline [ms].
int tick_until(Clock::time_point until) {
  const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now()).count();
  return static_cast<int>(std::clamp<long long>(left, 0, kTickMs));
}

// The relay's end, thrown inside its thread: why (empty: libtraci closed its connection, or the
// relay is being stopped).
struct RelayEnd {
  std::string reason;
};

void set_no_delay(int fd) {
  const int on = 1;
  setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
}

// Waits up to `until` for a non-blocking connect of `fd` to finish; returns its errno (0: connected,
// ETIMEDOUT: not within the time). Throws Interrupted.
int finish_connect(int fd, Clock::time_point until) {
  while (true) {
    throw_if_interrupted();
    if (Clock::now() >= until) return ETIMEDOUT;
    pollfd p{fd, POLLOUT, 0};
    const int r = poll(&p, 1, tick_until(until));
    if (r < 0 && errno != EINTR) return errno;
    if (r <= 0) continue;
    int error = 0;
    socklen_t len = sizeof error;
    getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &len);
    return error;
  }
}

// One connection attempt to each address of `found`; the socket, or -1 with `error` set.
int connect_once(const addrinfo* found, Clock::time_point until, int& error) {
  for (const addrinfo* a = found; a != nullptr; a = a->ai_next) {
    const int fd = socket(a->ai_family, a->ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) {
      error = errno;
      continue;
    }
    error = connect(fd, a->ai_addr, a->ai_addrlen) == 0 ? 0 : errno;
    if (error == EINPROGRESS) {
      try {
        error = finish_connect(fd, until);
      } catch (...) {
        close(fd);
        throw;
      }
    }
    if (error == 0) return fd;
    close(fd);
  }
  return -1;
}

// A connected, non-blocking socket to the server. Throws SumoError, Interrupted.
int connect_to_server(const std::string& host, int port, double timeout) {
  const std::string endpoint = host + ":" + std::to_string(port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  if (getaddrinfo(host.c_str(), std::to_string(port).c_str(), &hints, &found) != 0 || found == nullptr)
    throw SumoError("cannot connect to SUMO at " + endpoint + ": host '" + host + "' not found");
  const Clock::time_point until = deadline_after(timeout);
  int error = 0;
  int fd = -1;
  try {
    for (int attempt = 0; attempt < kConnectAttempts && fd < 0; ++attempt) {
      if (attempt > 0) {
        if (error != ECONNREFUSED) break;  // only a server that does not listen yet may come
        for (int i = 0; i < 2; ++i) {      // 0.2 s, looking for an interruption
          throw_if_interrupted();
          usleep(kTickMs * 1000);
        }
      }
      fd = connect_once(found, until, error);
    }
  } catch (...) {
    freeaddrinfo(found);
    throw;
  }
  freeaddrinfo(found);
  if (fd >= 0) {
    set_no_delay(fd);
    return fd;
  }
  if (error == ETIMEDOUT)
    throw SumoError("cannot connect to SUMO at " + endpoint + ": no answer to the connection within " +
                    short_number(timeout) + " s");
  throw SumoError("cannot connect to SUMO at " + endpoint + ": connection refused or host unreachable (start it with: "
                  "sumo -c FILE.sumocfg --remote-port " + std::to_string(port) + " --num-clients N)");
}

// A socket listening on 127.0.0.1 (a free port) for one connection; sets `port`.
int listen_locally(int& port) {
  const int fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd < 0) throw SumoError(std::string("cannot open a socket for libtraci: ") + std::strerror(errno));
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof addr;
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || listen(fd, 1) != 0 ||
      getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    const std::string reason = std::strerror(errno);
    close(fd);
    throw SumoError("cannot listen on 127.0.0.1 for libtraci: " + reason);
  }
  port = ntohs(addr.sin_port);
  return fd;
}

void close_fd(int& fd) {
  if (fd >= 0) close(fd);
  fd = -1;
}

}  // namespace

TraciRelay::TraciRelay(const std::string& host, int port, RelayLimits limits)
    : endpoint_(host + ":" + std::to_string(port)), limits_(limits) {
  server_ = connect_to_server(host, port, limits_.timeout);
  try {
    listener_ = listen_locally(client_port_);
    if (pipe2(wake_, O_CLOEXEC | O_NONBLOCK) != 0) throw SumoError(std::string("pipe: ") + std::strerror(errno));
  } catch (...) {
    close_fd(server_);
    close_fd(listener_);
    throw;
  }
  // Signals go to the other threads: SIGINT and SIGTERM must interrupt libtraci's blocking call in
  // the caller's thread (interruption.hpp), and the relay looks for them itself.
  sigset_t all, previous;
  sigfillset(&all);
  pthread_sigmask(SIG_BLOCK, &all, &previous);
  thread_ = std::thread([this] { run(); });
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

TraciRelay::~TraciRelay() {
  const char stop = 1;
  (void)!write(wake_[1], &stop, 1);
  if (thread_.joinable()) thread_.join();
  close_fd(client_);
  close_fd(server_);
  close_fd(listener_);
  close_fd(wake_[0]);
  close_fd(wake_[1]);
}

std::string TraciRelay::failure() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return failure_;
}

void TraciRelay::run() noexcept {
  std::string reason;
  try {
    accept_client();
    while (true) relay_answer(relay_request());
  } catch (const RelayEnd& end) {
    reason = end.reason;
  } catch (const std::exception& e) {  // memory for a message
    reason = "the connection to SUMO at " + endpoint_ + " failed: " + e.what();
  }
  if (!reason.empty()) {
    const std::lock_guard<std::mutex> lock(mutex_);
    failure_ = reason;
  }
  // libtraci's waiting call (and every later one) fails at once; the server sees this client leave.
  if (client_ >= 0) shutdown(client_, SHUT_RDWR);
  close_fd(client_);
  close_fd(server_);
}

void TraciRelay::accept_client() {
  wait_readable(listener_, -1, deadline_after(kAcceptSeconds),
                "libtraci did not connect to its relay within " + short_number(kAcceptSeconds) + " s");
  client_ = accept4(listener_, nullptr, nullptr, SOCK_NONBLOCK | SOCK_CLOEXEC);
  if (client_ < 0) throw RelayEnd{std::string("libtraci could not connect to its relay: ") + std::strerror(errno)};
  set_no_delay(client_);
  close_fd(listener_);
}

// Reads one request of libtraci and forwards it; returns its first command's id.
int TraciRelay::relay_request() {
  MessageAssembler request(limits_.max_message);
  std::uint8_t buffer[kReadChunk];
  bool drained = true;  // read what is there before waiting again (a message comes in one piece)
  while (!request.complete()) {
    if (drained) wait_readable(client_, -1, Clock::time_point::max(), "");
    const ssize_t n = recv(client_, buffer, std::min(request.wanted(), sizeof buffer), 0);
    drained = n < 0 && errno == EAGAIN;
    if (n == 0 && request.bytes().empty()) throw RelayEnd{""};  // libtraci closed its connection
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n <= 0) throw RelayEnd{"libtraci's connection to its relay broke off"};
    if (std::string why = request.take(buffer, static_cast<std::size_t>(n)); !why.empty())
      throw RelayEnd{"libtraci sent a request the relay cannot read: " + why};
  }
  const int command = first_command_id(request.body());
  if (command < 0) throw RelayEnd{"libtraci sent a request without a command"};
  send_all(server_, request.bytes(), no_answer());
  return command;
}

// Reads the server's answer to `request_command`, checks it, and hands it to libtraci.
void TraciRelay::relay_answer(int request_command) {
  MessageAssembler answer(limits_.max_message);
  std::uint8_t buffer[kReadChunk];
  const Clock::time_point until = deadline_after(limits_.timeout);
  const std::string lost = "the connection to SUMO at " + endpoint_ + " failed or was lost: ";
  bool drained = true;
  while (!answer.complete()) {
    if (drained && wait_readable(server_, client_, until, no_answer()) == client_) {
      // libtraci never sends before it has its answer; it closed its connection, or gave up waiting.
      std::uint8_t byte = 0;
      if (recv(client_, &byte, 1, MSG_PEEK) == 0) throw RelayEnd{""};
      throw RelayEnd{"libtraci sent a request before SUMO at " + endpoint_ + " had answered the last one"};
    }
    const ssize_t n = recv(server_, buffer, std::min(answer.wanted(), sizeof buffer), 0);
    drained = n < 0 && errno == EAGAIN;
    if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
    if (n < 0) throw RelayEnd{lost + std::strerror(errno)};
    if (n == 0)
      throw RelayEnd{lost + (answer.bytes().empty() ? "it closed the connection before answering"
                                                    : "it closed the connection in the middle of an answer")};
    if (std::string why = answer.take(buffer, static_cast<std::size_t>(n)); !why.empty())
      throw RelayEnd{not_traci(why)};
  }
  if (std::string why = check_answer(request_command, answer.body()); !why.empty()) throw RelayEnd{not_traci(why)};
  answered_ = true;
  send_all(client_, answer.bytes(), "libtraci did not take SUMO's answer within " + short_number(limits_.timeout) + " s");
}

// Waits until `first` (or `second`, when >= 0) is readable and returns it; throws
// RelayEnd{timeout_reason} at `until` (Clock::time_point::max(): no limit), RelayEnd when the relay
// is stopped or a SIGINT/SIGTERM arrived.
int TraciRelay::wait_readable(int first, int second, Clock::time_point until, const std::string& timeout_reason) const {
  while (true) {
    pollfd p[3] = {{wake_[0], POLLIN, 0}, {first, POLLIN, 0}, {second, POLLIN, 0}};
    const int r = poll(p, second >= 0 ? 3 : 2, tick_until(until));
    if (r < 0 && errno != EINTR) throw RelayEnd{std::string("the relay's poll failed: ") + std::strerror(errno)};
    if (p[0].revents != 0) throw RelayEnd{""};
    if (interruption_requested()) throw RelayEnd{"interrupted"};
    if (r > 0 && p[1].revents != 0) return first;
    if (r > 0 && second >= 0 && p[2].revents != 0) return second;
    if (Clock::now() >= until) throw RelayEnd{timeout_reason};
  }
}

// Sends all of `bytes` to `fd` within the timeout (throws RelayEnd{timeout_reason} after it).
void TraciRelay::send_all(int fd, const std::vector<std::uint8_t>& bytes, const std::string& timeout_reason) const {
  const Clock::time_point until = deadline_after(limits_.timeout);
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = send(fd, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EINTR)
      throw RelayEnd{(fd == server_ ? "the connection to SUMO at " + endpoint_ + " failed or was lost: "
                                    : std::string("libtraci's connection to its relay broke off: ")) +
                     std::strerror(errno)};
    if (Clock::now() >= until) throw RelayEnd{timeout_reason};
    pollfd p[2] = {{wake_[0], POLLIN, 0}, {fd, POLLOUT, 0}};
    poll(p, 2, kTickMs);
    if (p[0].revents != 0) throw RelayEnd{""};
    if (interruption_requested()) throw RelayEnd{"interrupted"};
  }
}

std::string TraciRelay::not_traci(const std::string& why) const {
  if (answered_) return "SUMO at " + endpoint_ + " sent a message that is not TraCI: " + why;
  return "something at " + endpoint_ + " is not a TraCI server: it sent " + why +
         " (is it a SUMO started with --remote-port?)";
}

std::string TraciRelay::no_answer() const {
  const std::string seconds = short_number(limits_.timeout) + " s";
  if (answered_)
    return "SUMO at " + endpoint_ + " did not answer within " + seconds +
           " (is it stopped or frozen? --traci-timeout sets the limit)";
  return "something at " + endpoint_ + " accepted the connection but did not answer TraCI within " + seconds +
         " (is it a SUMO started with --remote-port? --traci-timeout sets the limit)";
}

}  // namespace signalsim::sumo
