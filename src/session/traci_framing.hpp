// The framing of TraCI messages (SUMO's tcpip::Storage over TCP), checked before libtraci reads a
// server's answer. No sockets here: TraciRelay (traci_relay.hpp) reads the bytes, this file judges them.
//
// TraCI's framing, as SUMO 1.15 writes and libtraci reads it:
//   message  = total length (4 bytes, big-endian, counting itself) + commands
//   command  = length (1 byte, counting itself, the id and the payload; or 0 and then 4 bytes that
//              count the 0, themselves, the id and the payload) + id (1 byte) + payload
//   answer   = a status command first (its id is the request's command id; payload: result 0x00 OK,
//              0x01 not implemented or 0xFF error, then a string: 4-byte length + bytes), then the
//              result commands; the answer to a simulation step (0x02) has a 4-byte count of
//              subscription results after the status, then that many commands.
// SUMO writes a status's length byte as (7 + text length) mod 256, and libtraci reads the status
// by its string's own length: so does check_answer.
//
// Why: libtraci trusts a message's length. SUMO 1.15's tcpip::Socket::receiveExact asserts that it
// is more than 4 (a server sending four zero bytes aborts signalsim) and allocates whatever it says
// (0x7ffffff0: 2 GiB) before reading it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace signalsim::sumo {

/// The largest TraCI message signalsim takes from a server, its 4-byte length included [bytes]. The
/// largest answers a run asks for (a light's programs, a lane's vehicles) are kilobytes.
inline constexpr std::size_t kMaxTraciMessage = std::size_t{16} << 20;

/// TraCI's simulation step command (its answer carries the subscription results).
inline constexpr int kTraciSimulationStep = 0x02;

/// Why a message whose 4-byte length prefix reads `total` (as libtraci reads it: a signed int)
/// cannot be a TraCI message of at most `max_message` bytes; "" when it can.
std::string check_message_length(std::int64_t total, std::size_t max_message);

/// The id of the first command of a message body (without its 4-byte length), -1 when the body
/// does not hold one.
int first_command_id(std::span<const std::uint8_t> body);

/// Why `body` (a message without its 4-byte length) is not an answer to a request whose command id
/// is `request_command`; "" when it is one. Checked: the status command (its id, a known result
/// code, its text inside the message) and, after a successful status, that the commands (after the
/// subscription count for a step) fill the message exactly. An error or "not implemented" status
/// is an answer whatever follows it: libtraci reports its text and reads no further.
std::string check_answer(int request_command, std::span<const std::uint8_t> body);

/// Collects one message from a byte stream: the caller reads at most wanted() bytes at a time (so
/// it never reads into the next message and never holds more than the message's length) and hands
/// them to take(). The length prefix is checked as soon as it is complete.
class MessageAssembler {
 public:
  explicit MessageAssembler(std::size_t max_message = kMaxTraciMessage) : max_message_(max_message) {}

  /// How many bytes the current message still needs (4 for the length prefix at first); 0 once it
  /// is complete or the prefix was refused.
  std::size_t wanted() const;
  /// Takes `n` <= wanted() bytes. Returns why the length prefix cannot start a message
  /// (check_message_length) once it is complete and bad, else "". Bytes beyond wanted() are refused
  /// with a reason too.
  std::string take(const std::uint8_t* data, std::size_t n);
  /// Whether a whole message (its length prefix checked) is here.
  bool complete() const { return complete_; }
  /// The message read so far, its length prefix included (whole once complete()).
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  /// The message without its length prefix, once complete().
  std::span<const std::uint8_t> body() const;
  /// Forgets the message: ready for the next one.
  void clear();

 private:
  std::size_t max_message_;
  std::vector<std::uint8_t> bytes_;
  std::size_t total_ = 0;  // the checked length prefix, 0 until it is read
  bool complete_ = false;
  bool refused_ = false;
};

}  // namespace signalsim::sumo
