// The generator's documented random algorithm: std::mt19937_64 outputs, unbiased index by rejection.
#include "generate/rng.hpp"

#include <cstdint>
#include <random>
#include <set>

#include <gtest/gtest.h>

namespace signalsim::generate {
namespace {

TEST(Rng, EngineIsTheStandardsMt19937_64) {
  // [rand.predef]: the 10000th output of a default-constructed mt19937_64 (seed 5489).
  Rng rng(5489);
  for (int i = 1; i < 10000; ++i) rng.next();
  EXPECT_EQ(rng.next(), 9981545732273789042ULL);
}

TEST(Rng, IndexIsTheOutputModuloNWhenNoDrawIsRejected) {
  // 2^64 mod 10 = 6: only the 6 largest outputs are rejected, so these draws are plain x mod 10.
  Rng rng(42);
  std::mt19937_64 reference(42);
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(rng.index(10), reference() % 10) << "draw " << i;
}

TEST(Rng, IndexRejectsTheOutputsThatWouldBias) {
  // n = 2^63 + 1: outputs above 2^63 are rejected (2^64 mod n = 2^63 - 1), the first accepted
  // output x <= 2^63 is returned as x mod n = x.
  const std::uint64_t n = (1ULL << 63) + 1;
  Rng rng(7);
  std::mt19937_64 reference(7);
  for (int i = 0; i < 50; ++i) {
    std::uint64_t x = reference();
    while (x > (1ULL << 63)) x = reference();
    ASSERT_EQ(rng.index(static_cast<std::size_t>(n)), x) << "draw " << i;
  }
}

TEST(Rng, BetweenStaysInItsBoundsAndReachesBoth) {
  Rng rng(1);
  std::set<long long> seen;
  for (int i = 0; i < 2000; ++i) {
    const long long v = rng.between(300, 305);
    ASSERT_GE(v, 300);
    ASSERT_LE(v, 305);
    seen.insert(v);
  }
  EXPECT_EQ(seen.size(), 6u);
  EXPECT_EQ(rng.between(5, 5), 5);
}

TEST(Rng, SameSeedSameSequence) {
  Rng a(123), b(123), c(124);
  bool differs = false;
  for (int i = 0; i < 100; ++i) {
    const std::size_t x = a.index(1000);
    ASSERT_EQ(x, b.index(1000));
    differs |= x != c.index(1000);
  }
  EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace signalsim::generate
