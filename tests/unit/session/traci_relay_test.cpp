// The TraCI relay (session/traci_relay.hpp) between a plain socket standing in for libtraci and a
// server on 127.0.0.1 run by the test in a thread: a well-formed answer is forwarded as it is; bytes
// that are not TraCI, a server that does not answer and a server that goes away end the connection
// (the client reads end of file) with the reason; a client that leaves closes the server's
// connection.
#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <functional>
#include <string>
#include <thread>
#include <vector>

#include "session/traci_relay.hpp"

namespace signalsim::sumo {
namespace {

using RelayBytes = std::vector<std::uint8_t>;

// getVersion (command 0x00) as libtraci sends it.
const RelayBytes kVersionRequest = {0x00, 0x00, 0x00, 0x06, 0x02, 0x00};
// SUMO's answer to it: the status (OK, no text) and the version command (API 20, "SUMO 1.15.0").
const RelayBytes kVersionAnswer = {0x00, 0x00, 0x00, 0x20, 0x07, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x15, 0x00,
                                   0x00, 0x00, 0x00, 0x14, 0x00, 0x00, 0x00, 0x0b, 'S',  'U',  'M',  'O',  ' ',
                                   '1',  '.',  '1',  '5',  '.',  '0'};

// Reads exactly n bytes (false on end of file or error).
bool read_exactly(int fd, std::uint8_t* into, std::size_t n) {
  while (n > 0) {
    const ssize_t r = recv(fd, into, n, 0);
    if (r <= 0) return false;
    into += r;
    n -= static_cast<std::size_t>(r);
  }
  return true;
}

// A TCP server on 127.0.0.1 taking one connection, on which `behaviour` runs in a thread of its own.
// `stop` is set when the test ends (a behaviour that waits forever waits for it).
class RelayTestServer {
 public:
  using Behaviour = std::function<void(int fd, const std::atomic<bool>& stop)>;
  explicit RelayTestServer(Behaviour behaviour) {
    listener_ = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    bind(listener_, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    listen(listener_, 1);
    getsockname(listener_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    thread_ = std::thread([this, behaviour] {
      const int fd = accept(listener_, nullptr, nullptr);
      if (fd < 0) return;
      behaviour(fd, stop_);
      close(fd);
    });
  }
  ~RelayTestServer() {
    stop_ = true;
    shutdown(listener_, SHUT_RDWR);  // an accept() still waiting returns
    thread_.join();
    close(listener_);
  }
  int port() const { return port_; }

 private:
  int listener_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Reads one request (its length prefix and the rest); false when the peer left.
bool read_request(int fd) {
  std::uint8_t prefix[4];
  if (!read_exactly(fd, prefix, 4)) return false;
  std::vector<std::uint8_t> rest((std::size_t{prefix[2]} << 8 | prefix[3]) - 4);
  return read_exactly(fd, rest.data(), rest.size());
}

// Waits until the peer closes the connection or the test ends.
void wait_for_end(int fd, const std::atomic<bool>& stop) {
  while (!stop) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 50) > 0) {
      std::uint8_t byte;
      if (recv(fd, &byte, 1, 0) <= 0) return;
    }
  }
}

// Answers each request with `answer`, `answers` times, then waits without answering.
RelayTestServer::Behaviour answer_then_wait(RelayBytes answer, int answers) {
  return [answer, answers](int fd, const std::atomic<bool>& stop) {
    for (int i = 0; i < answers; ++i) {
      if (!read_request(fd)) return;
      send(fd, answer.data(), answer.size(), MSG_NOSIGNAL);
    }
    wait_for_end(fd, stop);
  };
}

// libtraci's side: a blocking socket to the relay (reads give up after 20 s: a failing test ends).
int connect_client(int port) {
  const int fd = socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  addr.sin_port = htons(static_cast<std::uint16_t>(port));
  timeval limit{20, 0};
  setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit);
  EXPECT_EQ(connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  return fd;
}

// Sends getVersion and reads whatever comes back until the relay closes the connection.
RelayBytes exchange_until_closed(int fd) {
  send(fd, kVersionRequest.data(), kVersionRequest.size(), MSG_NOSIGNAL);
  RelayBytes got;
  std::uint8_t buffer[256];
  ssize_t n;
  while ((n = recv(fd, buffer, sizeof buffer, 0)) > 0) got.insert(got.end(), buffer, buffer + n);
  EXPECT_TRUE(n == 0 || errno == ECONNRESET) << "the relay closed the connection (not a receive timeout)";
  return got;
}

// A relay to `server` whose client sends getVersion and reads to the end: what the relay said.
std::string relay_failure_after(const RelayTestServer& server, double timeout, RelayBytes* forwarded = nullptr) {
  TraciRelay relay("127.0.0.1", server.port(), RelayLimits{timeout, kMaxTraciMessage});
  const int client = connect_client(relay.client_port());
  const RelayBytes got = exchange_until_closed(client);
  if (forwarded) *forwarded = got;
  close(client);
  return relay.failure();
}

TEST(TraciRelay, ForwardsAWellFormedAnswerAsItIs) {
  RelayTestServer server(answer_then_wait(kVersionAnswer, 1));
  TraciRelay relay("127.0.0.1", server.port(), RelayLimits{10.0, kMaxTraciMessage});
  const int client = connect_client(relay.client_port());
  send(client, kVersionRequest.data(), kVersionRequest.size(), MSG_NOSIGNAL);
  RelayBytes got(kVersionAnswer.size());
  ASSERT_TRUE(read_exactly(client, got.data(), got.size()));
  EXPECT_EQ(got, kVersionAnswer);
  EXPECT_EQ(relay.failure(), "");
  close(client);
}

TEST(TraciRelay, FourZeroBytesEndTheConnectionWithTheReason) {
  RelayTestServer server(answer_then_wait({0, 0, 0, 0}, 1));
  RelayBytes forwarded;
  const std::string why = relay_failure_after(server, 10.0, &forwarded);
  EXPECT_TRUE(forwarded.empty()) << "libtraci never sees the bytes";
  EXPECT_NE(why.find("something at 127.0.0.1:" + std::to_string(server.port()) +
                     " is not a TraCI server: it sent a message length of 0 bytes"),
            std::string::npos)
      << why;
}

TEST(TraciRelay, AHugeLengthPrefixEndsTheConnectionWithoutWaitingForItsBody) {
  // The server sends the prefix only and then waits: the relay must not wait for 2 GiB.
  RelayTestServer server(answer_then_wait({0x7f, 0xff, 0xff, 0xf0}, 1));
  const std::string why = relay_failure_after(server, 10.0);
  EXPECT_NE(why.find("a message length of 2147483632 bytes, more than the 16 MiB signalsim accepts"), std::string::npos)
      << why;
}

TEST(TraciRelay, AnAnswerWithAnUnknownResultCodeIsRefused) {
  RelayTestServer server(answer_then_wait({0x00, 0x00, 0x00, 0x0b, 0x07, 0x00, 0x37, 0x00, 0x00, 0x00, 0x00}, 1));
  EXPECT_NE(relay_failure_after(server, 10.0).find("result code 0x37"), std::string::npos);
}

TEST(TraciRelay, AServerThatNeverAnswersTimesOut) {
  RelayTestServer server(answer_then_wait({}, 0));
  const std::string why = relay_failure_after(server, 0.3);
  EXPECT_NE(why.find("accepted the connection but did not answer TraCI within 0.3 s"), std::string::npos) << why;
}

TEST(TraciRelay, AServerThatStopsAnsweringAfterTheHandshakeTimesOut) {
  RelayTestServer server(answer_then_wait(kVersionAnswer, 1));
  TraciRelay relay("127.0.0.1", server.port(), RelayLimits{0.3, kMaxTraciMessage});
  const int client = connect_client(relay.client_port());
  send(client, kVersionRequest.data(), kVersionRequest.size(), MSG_NOSIGNAL);
  RelayBytes first(kVersionAnswer.size());
  ASSERT_TRUE(read_exactly(client, first.data(), first.size()));
  EXPECT_TRUE(exchange_until_closed(client).empty());
  EXPECT_NE(relay.failure().find("SUMO at 127.0.0.1:" + std::to_string(server.port()) + " did not answer within 0.3 s"),
            std::string::npos)
      << relay.failure();
  close(client);
}

TEST(TraciRelay, AServerThatClosesBeforeAnsweringIsALostConnection) {
  RelayTestServer server([](int fd, const std::atomic<bool>&) { read_request(fd); });
  EXPECT_NE(relay_failure_after(server, 10.0).find("failed or was lost: it closed the connection before answering"),
            std::string::npos);
}

TEST(TraciRelay, AClientThatLeavesClosesTheServersConnection) {
  std::atomic<bool> server_saw_the_end{false};
  {
    RelayTestServer server([&](int fd, const std::atomic<bool>& stop) {
      std::uint8_t byte;
      pollfd p{fd, POLLIN, 0};
      while (!stop)
        if (poll(&p, 1, 50) > 0) {
          server_saw_the_end = recv(fd, &byte, 1, 0) == 0;
          return;
        }
    });
    TraciRelay relay("127.0.0.1", server.port(), RelayLimits{10.0, kMaxTraciMessage});
    close(connect_client(relay.client_port()));
    for (int i = 0; i < 200 && !server_saw_the_end; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    EXPECT_EQ(relay.failure(), "");
  }
  EXPECT_TRUE(server_saw_the_end);
}

TEST(TraciRelay, NothingListeningIsARefusedConnection) {
  int port = 0;
  {
    RelayTestServer probe([](int, const std::atomic<bool>&) {});
    port = probe.port();
  }  // closed: nothing listens on it now
  try {
    TraciRelay relay("127.0.0.1", port, RelayLimits{10.0, kMaxTraciMessage});
    FAIL() << "connected to a closed port";
  } catch (const SumoError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot connect to SUMO at 127.0.0.1:" + std::to_string(port) +
                                         ": connection refused or host unreachable"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signalsim::sumo
