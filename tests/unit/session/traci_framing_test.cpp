// TraCI's framing checks (session/traci_framing.hpp): a server's length prefix, one message from a
// byte stream, and the answers SUMO 1.15 writes (built here byte by byte as its TraCIServer does).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "session/traci_framing.hpp"

namespace signalsim::sumo {
namespace {

using Bytes = std::vector<std::uint8_t>;

void put_int(Bytes& b, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v);
  b.insert(b.end(), {static_cast<std::uint8_t>(u >> 24), static_cast<std::uint8_t>(u >> 16),
                     static_cast<std::uint8_t>(u >> 8), static_cast<std::uint8_t>(u)});
}

void put_string(Bytes& b, const std::string& s) {
  put_int(b, static_cast<std::int32_t>(s.size()));
  b.insert(b.end(), s.begin(), s.end());
}

// A status command as SUMO's TraCIServer::writeStatusCmd writes it: its length byte wraps at 256.
Bytes status(int command, int result, const std::string& text = "") {
  Bytes b = {static_cast<std::uint8_t>((7 + text.size()) & 0xff), static_cast<std::uint8_t>(command),
             static_cast<std::uint8_t>(result)};
  put_string(b, text);
  return b;
}

// SUMO's answer to getVersion: the status, then the version command (API 20, "SUMO 1.15.0").
Bytes version_answer() {
  Bytes b = status(0x00, 0x00);
  Bytes version = {0x00};
  put_int(version, 20);
  put_string(version, "SUMO 1.15.0");
  b.push_back(static_cast<std::uint8_t>(1 + version.size()));
  b.insert(b.end(), version.begin(), version.end());
  return b;
}

// A command with the 4-byte length form (0, length, id, payload), as SUMO writes subscription results.
Bytes long_command(int id, std::size_t payload) {
  Bytes b = {0x00};
  put_int(b, static_cast<std::int32_t>(6 + payload));
  b.push_back(static_cast<std::uint8_t>(id));
  b.insert(b.end(), payload, 0x2a);
  return b;
}

Bytes step_answer(std::int32_t announced, const std::vector<Bytes>& results) {
  Bytes b = status(kTraciSimulationStep, 0x00);
  put_int(b, announced);
  for (const Bytes& r : results) b.insert(b.end(), r.begin(), r.end());
  return b;
}

TEST(TraciFraming, LengthPrefixesSumoAssertsOnOrCannotHoldAreRefused) {
  EXPECT_NE(check_message_length(0, kMaxTraciMessage).find("a message length of 0 bytes"), std::string::npos);
  EXPECT_NE(check_message_length(4, kMaxTraciMessage), "");
  EXPECT_NE(check_message_length(-1, kMaxTraciMessage).find("a message length of -1 bytes"), std::string::npos);
  EXPECT_NE(check_message_length(0x7ffffff0, kMaxTraciMessage).find("more than the 16 MiB signalsim accepts"),
            std::string::npos);
  EXPECT_EQ(check_message_length(5, kMaxTraciMessage), "");
  EXPECT_EQ(check_message_length(static_cast<std::int64_t>(kMaxTraciMessage), kMaxTraciMessage), "");
  EXPECT_NE(check_message_length(static_cast<std::int64_t>(kMaxTraciMessage) + 1, kMaxTraciMessage), "");
}

TEST(TraciFraming, AssemblerRefusesFourZeroBytesAndAsksForNothingMore) {
  MessageAssembler m;
  const Bytes zeros(4, 0);
  EXPECT_EQ(m.wanted(), 4u);
  EXPECT_NE(m.take(zeros.data(), 4), "");
  EXPECT_EQ(m.wanted(), 0u);
  EXPECT_FALSE(m.complete());
}

TEST(TraciFraming, AssemblerChecksAHugePrefixBeforeAnyOfItsBody) {
  MessageAssembler m;
  const Bytes huge = {0x7f, 0xff, 0xff, 0xf0, 0x01};
  EXPECT_EQ(m.take(huge.data(), 3), "");
  EXPECT_EQ(m.wanted(), 1u) << "never more than the prefix before it is checked";
  EXPECT_NE(m.take(huge.data() + 3, 1).find("2147483632 bytes"), std::string::npos);
  EXPECT_NE(m.take(huge.data() + 4, 1), "") << "bytes beyond wanted() are refused";
}

TEST(TraciFraming, AssemblerBuildsTheSameMessageFromSingleBytes) {
  Bytes message;
  const Bytes body = version_answer();
  put_int(message, static_cast<std::int32_t>(4 + body.size()));
  message.insert(message.end(), body.begin(), body.end());
  message.push_back(0x99);  // the start of the next message: never read into
  MessageAssembler m;
  std::size_t at = 0;
  while (m.wanted() > 0) EXPECT_EQ(m.take(&message[at++], 1), "");
  ASSERT_TRUE(m.complete());
  EXPECT_EQ(at, message.size() - 1);
  EXPECT_EQ(Bytes(m.body().begin(), m.body().end()), body);
  m.clear();
  EXPECT_EQ(m.wanted(), 4u);
}

TEST(TraciFraming, SumosAnswersAreAccepted) {
  EXPECT_EQ(check_answer(0x00, version_answer()), "");
  EXPECT_EQ(check_answer(kTraciSimulationStep, step_answer(0, {})), "");
  EXPECT_EQ(check_answer(kTraciSimulationStep, step_answer(2, {long_command(0xe4, 40), long_command(0xeb, 3)})), "");
  EXPECT_EQ(check_answer(0x03, status(0x03, 0x00)), "") << "setOrder: the status alone";
  // An error text of 300 bytes: SUMO writes its length byte as 307 mod 256; libtraci reads the text.
  EXPECT_EQ(check_answer(0xa4, status(0xa4, 0xff, std::string(300, 'e'))), "");
  Bytes error_then_anything = status(0xa4, 0xff, "no such vehicle");
  error_then_anything.push_back(0x01);
  EXPECT_EQ(check_answer(0xa4, error_then_anything), "") << "libtraci reads nothing after an error status";
}

TEST(TraciFraming, AnswersLibtraciCouldNotReadAreRefusedWithTheReason) {
  EXPECT_NE(check_answer(0x00, Bytes{0x07, 0x00, 0x00}).find("too short"), std::string::npos);
  EXPECT_NE(check_answer(0x03, status(0x00, 0x00)).find("a status of command 0x00 in answer to command 0x03"),
            std::string::npos);
  EXPECT_NE(check_answer(0x03, status(0x03, 0x37)).find("result code 0x37"), std::string::npos);
  Bytes long_text = status(0x03, 0x00);
  long_text[6] = 50;  // a text of 50 bytes in a message that has none
  EXPECT_NE(check_answer(0x03, long_text).find("a status text of 50 bytes"), std::string::npos);
  Bytes short_command = status(0x00, 0x00);
  short_command.insert(short_command.end(), {0x01, 0x00});
  EXPECT_NE(check_answer(0x00, short_command).find("a command of length 1 at byte 11"), std::string::npos);
  Bytes past_end = status(0x00, 0x00);
  past_end.insert(past_end.end(), {0x09, 0x00, 0x01});
  EXPECT_NE(check_answer(0x00, past_end).find("past the message's end"), std::string::npos);
  Bytes tiny_long = status(0x00, 0x00);
  put_int(tiny_long, 0);  // 0, then 4-byte length 0... too short for its own header
  tiny_long.push_back(0x00);
  EXPECT_NE(check_answer(0x00, tiny_long), "");
  EXPECT_NE(check_answer(kTraciSimulationStep, step_answer(2, {long_command(0xe4, 4)})).find("announcing 2"),
            std::string::npos);
  EXPECT_NE(check_answer(kTraciSimulationStep, step_answer(-1, {})).find("-1 subscription results"), std::string::npos);
  EXPECT_NE(check_answer(kTraciSimulationStep, status(kTraciSimulationStep, 0x00)).find("without its count"),
            std::string::npos);
}

TEST(TraciFraming, FirstCommandIdReadsBothLengthForms) {
  EXPECT_EQ(first_command_id(Bytes{0x02, 0x00}), 0x00);
  EXPECT_EQ(first_command_id(Bytes{0x0a, 0x02}), 0x02);
  EXPECT_EQ(first_command_id(long_command(0xd4, 10)), 0xd4);
  EXPECT_EQ(first_command_id(Bytes{}), -1);
  EXPECT_EQ(first_command_id(Bytes{0x00, 0x00, 0x00}), -1);
}

}  // namespace
}  // namespace signalsim::sumo
