// TraCI framing checks (traci_framing.hpp): the length prefix, a server's answer, one message from a
// byte stream.
#include "session/traci_framing.hpp"

#include <algorithm>
#include <cstdio>

namespace signalsim::sumo {
namespace {

constexpr std::size_t kLengthBytes = 4;
constexpr std::size_t kStatusBytes = 7;  // length, id, result, the text's 4-byte length
constexpr std::size_t kReserveAtMost = 65536;
constexpr int kResultOk = 0x00, kResultNotImplemented = 0x01, kResultError = 0xff;

// A 4-byte big-endian int at `at` (the caller checked that it is there), signed as libtraci reads it.
std::int32_t read_int(std::span<const std::uint8_t> bytes, std::size_t at) {
  const std::uint32_t v = (std::uint32_t{bytes[at]} << 24) | (std::uint32_t{bytes[at + 1]} << 16) |
                          (std::uint32_t{bytes[at + 2]} << 8) | std::uint32_t{bytes[at + 3]};
  return static_cast<std::int32_t>(v);
}

std::string hex(int byte) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02x", byte & 0xff);
  return text;
}

std::string size_text(std::size_t bytes) {
  if (bytes % (std::size_t{1} << 20) == 0) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// Where a command starts, as a byte of the whole message (its length prefix counted).
std::string at_byte(std::size_t body_offset) { return " at byte " + std::to_string(body_offset + kLengthBytes); }

// Why the commands from `pos` on do not fill `body` exactly; "" when they do. Counts them.
std::string check_commands(std::span<const std::uint8_t> body, std::size_t pos, std::int64_t& count) {
  count = 0;
  while (pos < body.size()) {
    const std::size_t left = body.size() - pos;
    std::int64_t length = body[pos];
    if (length == 0) {
      if (left < 5) return "a command" + at_byte(pos) + " whose 4-byte length runs past the message's end";
      length = read_int(body, pos + 1);
      if (length < 6)
        return "a command of length " + std::to_string(length) + at_byte(pos) + " (at least 6 with a 4-byte length)";
    } else if (length < 2) {
      return "a command of length 1" + at_byte(pos) + " (at least 2: its length and its id)";
    }
    if (static_cast<std::uint64_t>(length) > left)
      return "a command of " + std::to_string(length) + " bytes" + at_byte(pos) + ", past the message's end";
    pos += static_cast<std::size_t>(length);
    ++count;
  }
  return "";
}

}  // namespace

std::string check_message_length(std::int64_t total, std::size_t max_message) {
  if (total <= static_cast<std::int64_t>(kLengthBytes))
    return "a message length of " + std::to_string(total) +
           " bytes (a TraCI message has at least 5: its 4-byte length and a command)";
  if (static_cast<std::uint64_t>(total) > max_message)
    return "a message length of " + std::to_string(total) + " bytes, more than the " + size_text(max_message) +
           " signalsim accepts";
  return "";
}

int first_command_id(std::span<const std::uint8_t> body) {
  if (body.empty()) return -1;
  if (body[0] != 0) return body.size() >= 2 ? body[1] : -1;
  return body.size() >= 6 ? body[5] : -1;
}

std::string check_answer(int request_command, std::span<const std::uint8_t> body) {
  if (body.size() < kStatusBytes)
    return "an answer of " + std::to_string(body.size()) + " bytes, too short for TraCI's status command (7 bytes)";
  const int id = body[1];
  const int result = body[2];
  if (id != request_command) return "a status of command " + hex(id) + " in answer to command " + hex(request_command);
  if (result != kResultOk && result != kResultNotImplemented && result != kResultError)
    return "a status with result code " + hex(result) + ", which TraCI does not have";
  const std::int64_t text = read_int(body, 3);
  if (text < 0 || static_cast<std::uint64_t>(text) > body.size() - kStatusBytes)
    return "a status text of " + std::to_string(text) + " bytes, beyond the message's end";
  if (result != kResultOk) return "";  // libtraci reports the server's text and reads no further
  std::size_t pos = kStatusBytes + static_cast<std::size_t>(text);
  std::int64_t announced = -1;
  if (request_command == kTraciSimulationStep) {
    if (body.size() - pos < 4) return "an answer to a simulation step without its count of subscription results";
    announced = read_int(body, pos);
    if (announced < 0) return "an answer to a simulation step with " + std::to_string(announced) + " subscription results";
    pos += 4;
  }
  std::int64_t commands = 0;
  if (std::string why = check_commands(body, pos, commands); !why.empty()) return why;
  if (announced >= 0 && commands != announced)
    return "an answer to a simulation step announcing " + std::to_string(announced) + " subscription results but holding " +
           std::to_string(commands);
  return "";
}

std::size_t MessageAssembler::wanted() const {
  if (complete_ || refused_) return 0;
  if (bytes_.size() < kLengthBytes) return kLengthBytes - bytes_.size();
  return total_ - bytes_.size();
}

std::string MessageAssembler::take(const std::uint8_t* data, std::size_t n) {
  if (n > wanted()) {
    refused_ = true;
    return "more bytes than the message holds";
  }
  bytes_.insert(bytes_.end(), data, data + n);
  if (total_ == 0 && bytes_.size() == kLengthBytes) {
    const std::int64_t total = read_int(bytes_, 0);
    if (std::string why = check_message_length(total, max_message_); !why.empty()) {
      refused_ = true;
      return why;
    }
    total_ = static_cast<std::size_t>(total);
    bytes_.reserve(std::min(total_, kReserveAtMost));  // grows with what arrives, not with what is announced
  }
  complete_ = total_ != 0 && bytes_.size() == total_;
  return "";
}

std::span<const std::uint8_t> MessageAssembler::body() const {
  if (bytes_.size() <= kLengthBytes) return {};
  return std::span<const std::uint8_t>(bytes_).subspan(kLengthBytes);
}

void MessageAssembler::clear() {
  bytes_.clear();
  total_ = 0;
  complete_ = false;
  refused_ = false;
}

}  // namespace signalsim::sumo
