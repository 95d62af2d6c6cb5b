// Numbers as signalsim writes them (core/number_text.hpp). fixed() and append_fixed() against the
// text printf's "%.*f" gives: random doubles of every magnitude, exact binary ties, values just off a
// tie, signed zeros, NaN and infinities, huge values. as_written(), rounded(), rounded_fixed() and
// format_text() against what they promise, and the one place their roundings part.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "core/number_text.hpp"

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

TEST(AsWritten, IsTheValueItsTextReadsBackAs) {
  EXPECT_EQ(as_written(1.23456, 3), 1.235);
  EXPECT_EQ(as_written(-0.0004, 3), 0.0);
  EXPECT_FALSE(std::signbit(as_written(-0.0004, 3)));  // no -0 in summary.json
  EXPECT_EQ(as_written(215.68, 3), 215.68);
  EXPECT_EQ(as_written(0.0625, 3), 0.062);  // the text's rounding: ties to even
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> value(-1e6, 1e6);
  for (int i = 0; i < 20000; ++i) {
    const double v = value(random);
    EXPECT_EQ(as_written(v, 3), std::strtod(fixed(v, 3).c_str(), nullptr)) << std::hexfloat << v;
  }
}

TEST(Rounded, RoundsTheScaledValueHalfAwayFromZero) {
  EXPECT_EQ(rounded(1.23456, 3), 1.235);
  EXPECT_EQ(rounded(0.0625, 3), 0.063);  // where it parts from as_written: the scaled value 62.5 is a tie
  EXPECT_EQ(rounded(-0.0625, 3), -0.063);
  EXPECT_EQ(rounded(2.5, 0), 3.0);
  EXPECT_EQ(rounded(0.15, 1), 0.2);  // 0.15 * 10 rounds to the tie 1.5 in binary
  EXPECT_FALSE(std::signbit(rounded(-0.0004, 3)));
  EXPECT_FALSE(std::signbit(rounded(-0.04, 1)));
  for (int k = -5000; k <= 5000; ++k) {  // the metrics' 1 mm rule, as it always read
    const double v = k / 1024.0 + 0.00049;
    const double r = std::round(v * 1000.0) / 1000.0;
    EXPECT_EQ(rounded(v, 3), r == 0.0 ? 0.0 : r);
  }
}

TEST(RoundedFixed, WritesTheRoundedValueWithItsDecimals) {
  EXPECT_EQ(rounded_fixed(28.94, 1), "28.9");
  EXPECT_EQ(rounded_fixed(0.3, 2), "0.30");
  EXPECT_EQ(rounded_fixed(13.5, 0), "14");
  EXPECT_EQ(rounded_fixed(0.15, 1), "0.2");  // fixed(0.15, 1) is "0.1"
  EXPECT_EQ(fixed(0.15, 1), "0.1");
  EXPECT_EQ(rounded_fixed(-0.04, 1), "0.0");
  EXPECT_EQ(rounded_fixed(-3.25, 1), "-3.3");
  EXPECT_EQ(rounded_fixed(13.889, 2), "13.89");
}

TEST(FormatText, IsPrintfsTextOfAnyLength) {
  EXPECT_EQ(format_text("%.2f m", 3.14159), "3.14 m");
  EXPECT_EQ(format_text("%9.3f s %s", 1.5, "x"), "    1.500 s x");
  EXPECT_EQ(format_text("%04zu-", std::size_t{7}), "0007-");
  const std::string long_name(600, 'n');
  EXPECT_EQ(format_text("<%s>", long_name.c_str()), "<" + long_name + ">");  // beyond the stack buffer
  EXPECT_EQ(format_text("none"), "none");
}

}  // namespace
}  // namespace signalsim
