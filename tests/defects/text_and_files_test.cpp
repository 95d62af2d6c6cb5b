// SUMO-free parts of the defect regressions: the UTF-8 check of loaded text and the output
// files written whole or not at all on a full disk (/dev/full fails every write with ENOSPC).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "report/atomic_file.hpp"
#include "scenario/input_error.hpp"
#include "scenario/utf8_text.hpp"
#include "scenario/yaml_fields.hpp"

namespace signalsim {
namespace {
namespace fs = std::filesystem;

TEST(Utf8Text, AcceptsUtf8) {
  EXPECT_FALSE(find_invalid_utf8(""));
  EXPECT_FALSE(find_invalid_utf8("plain ascii\nline 2\n"));
  EXPECT_FALSE(find_invalid_utf8("caf\xc3\xa9 \xe4\xba\xa4\xe5\xb7\xae \xf0\x9f\x9a\xa6"));  // 2, 3, 4 bytes
  EXPECT_FALSE(find_invalid_utf8("\xef\xbb\xbfname: x"));                                  // a BOM
  EXPECT_FALSE(find_invalid_utf8("\xf4\x8f\xbf\xbf"));                                     // U+10FFFF
}

TEST(Utf8Text, FindsTheFirstBadByteAndItsLine) {
  const std::string text = "name: ok\nscenario: caf\xe9\n";
  const auto bad = find_invalid_utf8(text);
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->line, 2);
  EXPECT_EQ(bad->byte, 0xE9);
  EXPECT_EQ(bad->offset, text.find('\xe9'));
  EXPECT_EQ(describe_invalid_utf8(text, *bad), "invalid UTF-8 (byte 0xE9 at column 14)");
  for (const char* invalid : {"\xc0\xaf", "\xe0\x80\xaf", "\xed\xa0\x80", "\xf4\x90\x80\x80", "\xf5\x80\x80\x80",
                              "\x80", "\xc3", "\xe4\xba", "\xc3(", "\xff"})
    EXPECT_TRUE(find_invalid_utf8(invalid)) << "accepted: " << testing::PrintToString(std::string(invalid));
}

TEST(Utf8Text, LoadYamlFileNamesTheLine) {
  const fs::path file = fs::temp_directory_path() / ("signalsim_utf8_" + std::to_string(getpid()) + ".yaml");
  std::ofstream(file) << "a: 1\n# comment\nname: \"caf\xe9\"\n";
  try {
    (void)load_yaml_file(file.string(), "scenario file");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), file.string() + ":3: invalid UTF-8 (byte 0xE9 at column 11); save the file as UTF-8");
  }
  fs::remove(file);
}

class AtomicFile : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("signalsim_atomic_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  static std::string read(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  fs::path dir_;
};

TEST_F(AtomicFile, WritesAndReplaces) {
  const fs::path path = dir_ / "results.csv";
  write_file_atomically(path.string(), "a\n");
  write_file_atomically(path.string(), "b\n");
  EXPECT_EQ(read(path), "b\n");
  EXPECT_FALSE(fs::exists(dir_ / "results.csv.tmp"));
}

TEST_F(AtomicFile, FullDiskKeepsTheOldFileAndRemovesTheTemporary) {
  const fs::path path = dir_ / "summary.json";
  write_file_atomically(path.string(), "old\n");
  // Small content too: it used to sit in the stream's buffer until a destructor's unchecked flush.
  for (const std::string& content : {std::string("{}\n"), std::string(100000, 'x')}) {
    fs::create_symlink("/dev/full", dir_ / "summary.json.tmp");
    try {
      write_file_atomically(path.string(), content);
      ADD_FAILURE() << "a write to /dev/full succeeded";
    } catch (const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), path.string() + ": cannot write: No space left on device");
    }
    EXPECT_FALSE(fs::exists(fs::symlink_status(dir_ / "summary.json.tmp"))) << "the temporary file was left";
    EXPECT_EQ(read(path), "old\n");
  }
}

TEST_F(AtomicFile, UnwritableDirectoryNamesTheFile) {
  const fs::path path = dir_ / "missing" / "x.csv";
  try {
    write_file_atomically(path.string(), "x");
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": cannot write: No such file or directory");
  }
}

}  // namespace
}  // namespace signalsim
