// SutProcess and the command's words: spawning in a directory, a line each way, the faults (an
// early exit, a crash, a timeout, a write to a child that is gone) as errors with their reason.
#include "sut/sut_process.hpp"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <unistd.h>

namespace signalsim {
namespace {

namespace fs = std::filesystem;

std::string process_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SutProcessError& e) {
    return e.what();
  }
  return "";
}

struct Dir {
  fs::path path = fs::temp_directory_path() / ("sut_exec_test_" + std::to_string(::getpid()));
  Dir() { fs::create_directories(path); }
  ~Dir() { fs::remove_all(path); }
  std::string err() const { return (path / "err.txt").string(); }
};

SutProcess sh(const Dir& dir, const std::string& script) {
  return SutProcess(find_program("sh", "."), {"sh", "-c", script}, dir.path.string(), dir.err());
}

TEST(SplitCommand, QuotesAndVariablesLikeAShell) {
  ::setenv("SUT_EXEC_TEST_VAR", "v a", 1);
  EXPECT_EQ(split_command("python3 'my dir/d.py' \"$SUT_EXEC_TEST_VAR\" a\\ b"),
            (std::vector<std::string>{"python3", "my dir/d.py", "v a", "a b"}));
  EXPECT_NE(process_error_of([] { split_command("python3 $(rm -rf x)"); }).find("command substitution"), std::string::npos);
  EXPECT_NE(process_error_of([] { split_command("a | b"); }).find("sh -c"), std::string::npos);
  EXPECT_EQ(process_error_of([] { split_command("'unbalanced"); }), "unbalanced quotes");
}

TEST(FindProgram, OnPathOrRelativeToTheWorkingDirectory) {
  EXPECT_EQ(fs::path(find_program("sh", ".")).filename(), "sh");
  EXPECT_EQ(find_program("no_such_program_signalsim", "."), "");
  Dir dir;
  std::ofstream(dir.path / "tool.sh") << "#!/bin/sh\n";
  EXPECT_EQ(find_program("./tool.sh", dir.path.string()), "");  // not executable
  fs::permissions(dir.path / "tool.sh", fs::perms::owner_all);
  EXPECT_EQ(find_program("./tool.sh", dir.path.string()), (dir.path / "tool.sh").lexically_normal().string());
}

TEST(SutProcess, ALineEachWayInItsDirectoryStderrToTheFile) {
  Dir dir;
  SutProcess p = sh(dir, "read line; echo \"$line $(pwd)\"; echo oops >&2; read bye; exit 0");
  p.write("hi\n", 5.0);
  EXPECT_EQ(p.read_line(5.0), "hi " + fs::canonical(dir.path).string());
  p.write("bye\n", 5.0);
  EXPECT_EQ(p.close(5.0), "");
  std::stringstream err;
  err << std::ifstream(dir.err()).rdbuf();
  EXPECT_EQ(err.str(), "oops\n");
}

TEST(SutProcess, FaultsSayWhy) {
  Dir dir;
  {
    SutProcess p = sh(dir, "read line; exit 3");
    p.write("x\n", 5.0);
    EXPECT_EQ(process_error_of([&] { p.read_line(5.0); }), "exited with status 3 before replying");
  }
  {
    SutProcess p = sh(dir, "read line; kill -SEGV $$");
    p.write("x\n", 5.0);
    EXPECT_EQ(process_error_of([&] { p.read_line(5.0); }), "killed by signal 11 (SIGSEGV) before replying");
  }
  {
    SutProcess p = sh(dir, "read line; sleep 30");
    p.write("x\n", 5.0);
    EXPECT_EQ(process_error_of([&] { p.read_line(0.2); }), "no reply within 0.2 s");
  }  // killed and reaped here, the sleep with it (its process group)
  {
    SutProcess p = sh(dir, "exit 4");
    const std::string big(1 << 20, 'x');  // more than a pipe holds: the write meets the closed end
    EXPECT_EQ(process_error_of([&] { p.write(big + "\n", 5.0); }), "exited with status 4 before reading the message");
  }
  {
    SutProcess p = sh(dir, "sleep 30");
    const std::string big(1 << 20, 'x');
    EXPECT_EQ(process_error_of([&] { p.write(big + "\n", 0.2); }), "did not read its input within 0.2 s");
  }
  {
    SutProcess p = sh(dir, "echo one; echo two; read line");
    EXPECT_EQ(p.read_line(5.0), "one");
    EXPECT_TRUE(p.has_unread_output() || p.read_line(5.0) == "two");
  }
  {
    SutProcess p = sh(dir, "read line; exit 1");
    EXPECT_EQ(process_error_of([&] { p.write("bye\n", 5.0), p.close(5.0); }), "exited with status 1 after bye");
  }
}

}  // namespace
}  // namespace signalsim
