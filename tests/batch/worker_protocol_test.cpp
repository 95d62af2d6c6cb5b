// The persistent workers' line protocol (batch/worker_protocol.hpp): requests carry any argument
// text, tabs and newlines included, and come back unchanged; replies say the exit code and whether
// the worker ends.
#include <gtest/gtest.h>

#include "batch/worker_protocol.hpp"

namespace signalsim {
namespace {

TEST(WorkerProtocol, RequestRoundTripsAnyText) {
  const std::vector<std::string> args = {"run", "dir with spaces/s.yaml", "--out", "out/runs/0007-x", "--quiet",
                                         "--set", "ego.route=[[in_S, out_W],\t[a\\b]]", "--set", "name=two\nlines\r",
                                         ""};
  const std::string line = encode_worker_request(args);
  ASSERT_EQ(line.back(), '\n');
  EXPECT_EQ(line.find('\n'), line.size() - 1);  // one line, whatever the arguments hold
  const auto back = decode_worker_request(line.substr(0, line.size() - 1));
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(*back, args);
  EXPECT_EQ(encode_worker_request({"run", "a\tb"}), "run\ta\\tb\n");
}

TEST(WorkerProtocol, RefusesBrokenRequests) {
  EXPECT_FALSE(decode_worker_request("").has_value());
  EXPECT_FALSE(decode_worker_request("run\\").has_value());   // an escape cut short
  EXPECT_FALSE(decode_worker_request("run\\x").has_value());  // an unknown escape
}

TEST(WorkerProtocol, Replies) {
  EXPECT_EQ(encode_worker_reply({0, false}), "done 0\n");
  EXPECT_EQ(encode_worker_reply({143, true}), "done 143 last\n");
  const auto last = decode_worker_reply("done 2 last");
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->exit_code, 2);
  EXPECT_TRUE(last->last);
  const auto plain = decode_worker_reply("done 1");
  ASSERT_TRUE(plain.has_value());
  EXPECT_EQ(plain->exit_code, 1);
  EXPECT_FALSE(plain->last);
  for (const char* bad : {"", "done", "done ", "done x", "done 1 first", "done 1last", "Loading net-file ... done"})
    EXPECT_FALSE(decode_worker_reply(bad).has_value()) << bad;
}

}  // namespace
}  // namespace signalsim
