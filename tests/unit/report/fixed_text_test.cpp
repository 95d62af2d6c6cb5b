// fixed() and append_fixed() (report/fixed_text.hpp) against the text printf's "%.*f" gives, the
// way the output files were written before std::to_chars: random doubles of every magnitude, exact
// binary ties, values just off a tie, signed zeros, NaN and infinities, huge values.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "report/fixed_text.hpp"

namespace signalsim {
namespace {

// printf's text, with the files' rule: "-0.0", "-0.00", "-0.000" written without the sign.
std::string printf_text(double v, int decimals) {
  std::vector<char> buffer(400 + static_cast<std::size_t>(decimals > 0 ? decimals : 6));
  std::snprintf(buffer.data(), buffer.size(), "%.*f", decimals, v);
  std::string s = buffer.data();
  if (s == "-0.000" || s == "-0.00" || s == "-0.0") s.erase(0, 1);
  return s;
}

void expect_like_printf(double v, int decimals) {
  const std::string expected = printf_text(v, decimals);
  EXPECT_EQ(fixed(v, decimals), expected) << "value " << std::hexfloat << v << ", " << decimals << " decimals";
  std::string appended = "x,";
  append_fixed(appended, v, decimals);
  EXPECT_EQ(appended, "x," + expected);
}

TEST(FixedText, EdgeCases) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<double> values = {
      0.0, -0.0, 1e-7, -1e-7, 0.0004, -0.0004, 0.0005, -0.0005, 0.0015, 0.0025, 0.005, -0.005, 0.015, 0.025,
      0.125, -0.125, 0.375, 0.625, 2.5, 3.5, -2.5, 0.5, 1.5, 0.0625, 0.03125, 1.0 / 3.0, 2.0 / 3.0, 99.9995, 999.9995,
      1e15, 1e16 + 2, 1e22, 1e23, -1e23, 123456789.0125, 4503599627370495.5, 9007199254740993.0, 1e59, 1e60, 1e300,
      -1e300, std::numeric_limits<double>::max(), -std::numeric_limits<double>::max(),
      std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
      -std::numeric_limits<double>::min(),
      inf, -inf, nan, -nan, 0.1, 0.2, 0.3, 189.6, 208.95, 13.89, -3.2, 1.6, -200.0};
  for (double v : values)
    for (int decimals : {0, 1, 2, 3, 4, 6, 9, 17, -1}) expect_like_printf(v, decimals);
}

TEST(FixedText, NegativeZeroLosesItsSignAtOneToThreeDecimals) {
  EXPECT_EQ(fixed(-0.0, 3), "0.000");
  EXPECT_EQ(fixed(-0.0004, 3), "0.000");
  EXPECT_EQ(fixed(-0.04, 1), "0.0");
  EXPECT_EQ(fixed(-0.004, 2), "0.00");
  EXPECT_EQ(fixed(-0.0005, 3), "-0.001");  // the binary value is just beyond the tie
  EXPECT_EQ(fixed(-0.4, 0), "-0");          // as before: only the three texts above lose it
  EXPECT_EQ(fixed(-0.00004, 4), "-0.0000");
}

TEST(FixedText, TiesRoundToEvenLikePrintf) {
  EXPECT_EQ(fixed(0.125, 2), "0.12");
  EXPECT_EQ(fixed(0.375, 2), "0.38");
  EXPECT_EQ(fixed(2.5, 0), "2");
  EXPECT_EQ(fixed(3.5, 0), "4");
  EXPECT_EQ(fixed(0.0625, 3), "0.062");
}

TEST(FixedText, RandomDoublesOfEveryMagnitude) {
  std::mt19937_64 random(20240516);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-12, 25);
  std::uniform_int_distribution<std::uint64_t> bits;
  for (int i = 0; i < 100000; ++i) {
    const double v = mantissa(random) * std::pow(10.0, exponent(random));
    for (int decimals : {0, 1, 2, 3}) expect_like_printf(v, decimals);
  }
  // Any bit pattern (NaNs with payloads, subnormals, the largest values).
  for (int i = 0; i < 20000; ++i) {
    double v;
    const std::uint64_t b = bits(random);
    std::memcpy(&v, &b, sizeof v);
    expect_like_printf(v, 3);
  }
}

TEST(FixedText, ValuesOnAndNextToMillimetreTies) {
  // k + 0.0005 style values: some are exact binary ties (k/2^n), most are just off one.
  for (int k = -20000; k <= 20000; ++k) {
    const double tie = (k + 0.5) / 1000.0;
    for (double v : {tie, std::nextafter(tie, -1e9), std::nextafter(tie, 1e9), k / 1024.0, k / 8.0})
      for (int decimals : {1, 2, 3}) expect_like_printf(v, decimals);
  }
}

// Most numbers take the quick path (integer rounding of |v| * 10^decimals, below 1e9 and 2^40 scaled);
// those within 1e-3 of a half in the last decimal go to std::to_chars. Both sides of that margin,
// at magnitudes up to the path's limits and every decimal count it takes, must read like printf.
TEST(FixedText, TheQuickPathAtItsMarginsAndLimits) {
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int decimals = 0; decimals <= 9; ++decimals) {
    const double scale = std::pow(10.0, decimals);
    for (double magnitude : {1.0, 1e3, 1e6, 1e8, 9.99e8, 1099511627776.0 / scale}) {
      for (int i = 0; i < 400; ++i) {
        const double k = std::floor(unit(random) * magnitude * scale);
        for (double offset : {0.5, 0.5 - 1.2e-3, 0.5 + 1.2e-3, 0.5 - 0.9e-3, 0.5 + 0.9e-3, 0.0, 0.999999, 0.25}) {
          const double v = (k + offset) / scale;
          expect_like_printf(v, decimals);
          expect_like_printf(-v, decimals);
          expect_like_printf(std::nextafter(v, 0.0), decimals);
        }
      }
    }
  }
  for (double v : {999999999.99949992, 999999999.9995, 1e9, -1e9, 1e9 - 1e-6, 1099.511627776, 1099.5116277759999})
    for (int decimals = 0; decimals <= 9; ++decimals) expect_like_printf(v, decimals);
}

TEST(FixedText, Integers) {
  for (long long v : {0LL, 1LL, -1LL, 7LL, 255LL, -4096LL, std::numeric_limits<long long>::max(),
                      std::numeric_limits<long long>::min()}) {
    std::string out = "a";
    append_integer(out, v);
    EXPECT_EQ(out, "a" + std::to_string(v));
  }
}

}  // namespace
}  // namespace signalsim
