// libFuzzer target: the bytes a TraCI server may send, read as the relay reads them
// (src/session/traci_framing.hpp, traci_relay.hpp): a MessageAssembler takes the stream at most
// wanted() bytes at a time, and each whole message is judged by check_answer. Nothing here throws
// (an exception is a finding).
// Input: byte 0 the request's command id, byte 1 the largest message (0: kMaxTraciMessage, else
// 16 bytes per unit: the "too long" refusal is reached), byte 2 seeds the chunk sizes; the rest is
// what the server sends.
// Invariants asserted:
//   - the assembler never holds more than the largest message, asks for at least one byte until it
//     has a message or refused a prefix, and asks for nothing after a refusal;
//   - a whole message is at least 5 bytes and at most the largest, and its length prefix says so;
//   - read in chunks of fuzzed sizes, the stream gives the same messages, the same verdicts and the
//     same refusal as read one byte at a time (where a read ends never changes a judgement);
//   - an accepted answer starts with a status of the request's command; first_command_id is -1 or
//     a byte.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "session/traci_framing.hpp"

using namespace signalsim::sumo;

namespace {

struct StreamReading {
  std::vector<std::vector<std::uint8_t>> messages;
  std::vector<std::string> verdicts;  // check_answer of each message
  std::string refusal;                // why a length prefix was refused, "" when none was
};

bool same(const StreamReading& a, const StreamReading& b) {
  return a.messages == b.messages && a.verdicts == b.verdicts && a.refusal == b.refusal;
}

std::int64_t prefix_of(const std::vector<std::uint8_t>& m) {
  const std::uint32_t v = (std::uint32_t{m[0]} << 24) | (std::uint32_t{m[1]} << 16) | (std::uint32_t{m[2]} << 8) | m[3];
  return static_cast<std::int32_t>(v);
}

// Reads `stream` as the relay does; `chunk` gives the most bytes one read returns (>= 1).
template <class Chunk>
StreamReading read_stream(const std::vector<std::uint8_t>& stream, int command, std::size_t max_message, Chunk chunk) {
  StreamReading r;
  MessageAssembler m(max_message);
  std::size_t at = 0;
  while (at < stream.size()) {
    const std::size_t wanted = m.wanted();
    FUZZ_ASSERT(wanted > 0);
    const std::size_t n = std::min({wanted, chunk(), stream.size() - at});
    const std::string why = m.take(stream.data() + at, n);
    at += n;
    FUZZ_ASSERT(m.bytes().size() <= std::max<std::size_t>(max_message, 4));
    if (!why.empty()) {
      FUZZ_ASSERT(m.wanted() == 0 && !m.complete());
      FUZZ_ASSERT(!check_message_length(prefix_of(m.bytes()), max_message).empty());
      r.refusal = why;
      break;
    }
    if (!m.complete()) continue;
    const std::vector<std::uint8_t>& message = m.bytes();
    FUZZ_ASSERT(message.size() >= 5 && message.size() <= max_message);
    FUZZ_ASSERT(prefix_of(message) == static_cast<std::int64_t>(message.size()));
    FUZZ_ASSERT(m.wanted() == 0);
    const auto body = m.body();
    const int id = first_command_id(body);
    FUZZ_ASSERT(id >= -1 && id <= 0xff);
    std::string verdict = check_answer(command, body);
    if (verdict.empty()) FUZZ_ASSERT(body.size() >= 7 && body[1] == command);
    r.messages.push_back(message);
    r.verdicts.push_back(std::move(verdict));
    m.clear();
  }
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const int command = data[0];
  const std::size_t max_message = data[1] == 0 ? kMaxTraciMessage : std::size_t{data[1]} * 16;
  std::uint32_t state = data[2] * 2654435761u + 1;  // the chunk sizes' seed
  const std::vector<std::uint8_t> stream(data + 3, data + size);

  const StreamReading bytewise = read_stream(stream, command, max_message, [] { return std::size_t{1}; });
  const StreamReading chunked = read_stream(stream, command, max_message, [&state] {
    state = state * 1103515245u + 12345u;  // sizes 1..300: within and across prefixes and bodies
    return std::size_t{1} + (state >> 16) % 300;
  });
  FUZZ_ASSERT(same(bytewise, chunked));
  const StreamReading whole = read_stream(stream, command, max_message, [] { return std::size_t{1} << 30; });
  FUZZ_ASSERT(same(bytewise, whole));
  return 0;
}
