// NetIndexCache (net/net_index_cache.hpp): one index per net and process while the file is
// unchanged; a file of another size or modification time is read again; a bad file is not cached.
#include "net/net_index_cache.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

#include "test_nets.hpp"

namespace signalsim::sumo {
namespace {

using testing::net_path;
using testing::read_all;
using testing::ScratchDir;

TEST(NetIndexCache, OneIndexPerNetWhileTheFileIsUnchanged) {
  NetIndexCache cache;
  const auto a = cache.get(net_path("line.net.xml"));
  const auto b = cache.get(net_path("line.net.xml"));
  EXPECT_EQ(a, b);
  EXPECT_NE(cache.get(net_path("crossing.net.xml")), a);
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(a->path(), net_path("line.net.xml"));
  ASSERT_NE(a->edge("bc"), nullptr);
  EXPECT_EQ(a->edge("bc")->lanes.size(), 2u);
}

TEST(NetIndexCache, AChangedFileIsReadAgain) {
  ScratchDir scratch;
  const std::string path = scratch.write("net.net.xml", read_all(net_path("line.net.xml")));
  NetIndexCache cache;
  const auto first = cache.get(path);
  EXPECT_FALSE(first->lefthand());

  // Another size.
  scratch.write("net.net.xml", read_all(net_path("line_lefthand.net.xml")));
  const auto second = cache.get(path);
  EXPECT_NE(second, first);
  EXPECT_TRUE(second->lefthand());
  EXPECT_FALSE(first->lefthand());  // a run still holding the old index keeps it

  // The same size, another modification time.
  std::string text = read_all(net_path("line.net.xml"));
  const std::size_t at = text.find("speed=\"13.89\"");
  ASSERT_NE(at, std::string::npos);
  scratch.write("net.net.xml", text);
  const auto third = cache.get(path);
  text.replace(at, 13, "speed=\"12.34\"");
  scratch.write("net.net.xml", text);
  std::filesystem::last_write_time(path, std::filesystem::last_write_time(path) + std::chrono::seconds(2));
  const auto fourth = cache.get(path);
  EXPECT_NE(fourth, third);
  EXPECT_DOUBLE_EQ(fourth->lane(":B_1_0")->speed, 12.34);  // the first lane at 13.89
  EXPECT_DOUBLE_EQ(third->lane(":B_1_0")->speed, 13.89);
  EXPECT_EQ(cache.size(), 1u);
}

TEST(NetIndexCache, ABadFileThrowsAsLoadAndIsNotCached) {
  ScratchDir scratch;
  NetIndexCache cache;
  EXPECT_THROW(cache.get(scratch.path("missing.net.xml")), NetError);
  const std::string bad = scratch.write("bad.net.xml", "<net><edge id=\"a\"></net>");
  try {
    cache.get(bad);
    ADD_FAILURE() << "no NetError";
  } catch (const NetError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(bad + ":1: not XML: ", 0), 0u) << e.what();
  }
  EXPECT_EQ(cache.size(), 0u);
}

TEST(NetIndexCache, TheLeastRecentlyUsedNetGoesFirst) {
  NetIndexCache cache(2);
  const auto line = cache.get(net_path("line.net.xml"));
  const auto crossing = cache.get(net_path("crossing.net.xml"));
  EXPECT_EQ(cache.get(net_path("line.net.xml")), line);  // now the most recent
  (void)cache.get(net_path("roundabout.net.xml"));    // crossing goes
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.get(net_path("line.net.xml")), line);
  EXPECT_NE(cache.get(net_path("crossing.net.xml")), crossing);
  EXPECT_NE(crossing->edge("s_in"), nullptr);  // still usable by whoever holds it
}

TEST(NetIndexCache, LoadSharedUsesTheProcessCache) {
  const auto a = NetIndex::load_shared(net_path("line.net.xml"));
  EXPECT_EQ(NetIndex::load_shared(net_path("line.net.xml")), a);
  EXPECT_EQ(NetIndexCache::process().get(net_path("line.net.xml")), a);
}

}  // namespace
}  // namespace signalsim::sumo
