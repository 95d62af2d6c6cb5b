// Numbers as signalsim writes them (number_text.hpp). Fixed-point text is printf's "%.*f": the
// files' usual numbers by integer rounding where that is provably exact, everything else with
// std::to_chars.
#include "core/number_text.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <system_error>

namespace signalsim {
namespace {

// "-0.0", "-0.00", "-0.000": a negative value that rounds to zero (only these three, as the files
// have always been written).
bool is_negative_zero_text(const char* text, std::size_t size, int decimals) {
  if (decimals < 1 || decimals > 3 || size != static_cast<std::size_t>(decimals) + 3) return false;
  if (std::memcmp(text, "-0.", 3) != 0) return false;
  for (std::size_t i = 3; i < size; ++i)
    if (text[i] != '0') return false;
  return true;
}

constexpr double kPowersOfTen[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
constexpr std::uint64_t kIntegerPowersOfTen[] = {1,         10,         100,         1000,
                                                  10000,     100000,     1000000,     10000000,
                                                  100000000, 1000000000};

// The output files' numbers (|v| below 1e9, at most 9 decimals) the quick way, or false to leave
// `v` to std::to_chars. The product |v| * 10^decimals is rounded once (10^decimals is exact); below
// 2^40 it is off the exact value by at most half its ulp, 2^-13 of a unit in the last decimal. So
// rounding it to the nearest integer gives the correctly rounded digits unless it lies within that of
// a half: products within 1e-3 of one are left to std::to_chars, which also rounds exact ties to
// even. Writes the text std::to_chars writes into `text` (at least 32 chars); returns its end, or
// nullptr when it leaves `v` to std::to_chars.
char* quick_fixed(char* text, double v, int decimals) {
  if (decimals > 9 || !(std::fabs(v) < 1e9)) return nullptr;  // also NaN and the infinities
  const double scaled = std::fabs(v) * kPowersOfTen[decimals];
  if (scaled >= 1099511627776.0) return nullptr;  // 2^40
  const double whole = std::floor(scaled);
  const double fraction = scaled - whole;  // exact
  if (std::fabs(fraction - 0.5) < 1e-3) return nullptr;
  const std::uint64_t rounded = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
  char* at = text;
  if (std::signbit(v)) *at++ = '-';
  at = std::to_chars(at, text + 32, rounded / kIntegerPowersOfTen[decimals]).ptr;
  if (decimals > 0) {
    *at++ = '.';
    std::uint64_t rest = rounded % kIntegerPowersOfTen[decimals];
    for (int i = decimals - 1; i >= 0; --i) {
      at[i] = static_cast<char>('0' + rest % 10);
      rest /= 10;
    }
    at += decimals;
  }
  return at;
}

void append_fixed_text(std::string& out, double v, int decimals) {
  if (decimals < 0) decimals = 6;  // printf: a negative precision is taken as omitted
  char small[64];
  if (const char* quick_end = quick_fixed(small, v, decimals)) {
    const std::size_t size = static_cast<std::size_t>(quick_end - small);
    if (is_negative_zero_text(small, size, decimals)) out.append(small + 1, size - 1);
    else out.append(small, size);
    return;
  }
  auto [end, error] = std::to_chars(small, small + sizeof small, v, std::chars_format::fixed, decimals);
  if (error == std::errc()) {
    const std::size_t size = static_cast<std::size_t>(end - small);
    if (is_negative_zero_text(small, size, decimals)) out.append(small + 1, size - 1);
    else out.append(small, size);
    return;
  }
  // Up to 309 digits before the point (DBL_MAX), a sign, the point and the decimals.
  const std::size_t at = out.size();
  out.resize(at + 312 + static_cast<std::size_t>(decimals));
  const auto wide = std::to_chars(out.data() + at, out.data() + out.size(), v, std::chars_format::fixed, decimals);
  out.resize(static_cast<std::size_t>(wide.ptr - out.data()));
}

}  // namespace

std::string fixed(double v, int decimals) {
  std::string out;
  append_fixed_text(out, v, decimals);
  return out;
}

void append_fixed(std::string& out, double v, int decimals) { append_fixed_text(out, v, decimals); }

double as_written(double v, int decimals) {
  const std::string text = fixed(v, decimals);
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

double rounded(double v, int decimals) {
  const double scale = decimals >= 0 && decimals <= 9 ? kPowersOfTen[decimals] : std::pow(10.0, decimals);
  const double r = std::round(v * scale) / scale;
  return r == 0.0 ? 0.0 : r;  // no "-0"
}

std::string rounded_fixed(double v, int decimals) { return fixed(rounded(v, decimals), decimals); }

void append_integer(std::string& out, long long v) {
  char text[24];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  out.append(text, static_cast<std::size_t>(end - text));
}

}  // namespace signalsim
