// Numbers as signalsim writes them: the one home of number text for every output file, message and
// generated scenario. Two roundings live here, each kept where its files have always used it:
//   fixed / as_written    correctly rounded from the binary value (printf's "%.*f"): timeline.csv,
//                         events.csv, summary.json's plain numbers, results.csv
//   rounded / rounded_fixed  the value scaled by 10^decimals rounded half away from zero: the metric
//                         values (1 mm / 1 ms) and the generator's scenario files
// They differ only on (near-)ties, e.g. 0.0625 to 3 decimals: 0.062 (fixed) against 0.063 (rounded).
// No text here is negative zero: a value that rounds to zero is written the same on every platform.
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace signalsim {

/// `v` with `decimals` decimals exactly as printf("%.*f", decimals, v) writes it (correctly rounded
/// from the binary value, ties to even; "nan", "-nan", "inf", "-inf"; a negative `decimals` means 6),
/// except that "-0.0", "-0.00" and "-0.000" lose their sign. Written with std::to_chars (the timeline
/// writes about 14 numbers a step; printf's format parsing was a third of an ego-only step).
std::string fixed(double v, int decimals);

/// The same text appended to `out`, without a temporary string.
void append_fixed(std::string& out, double v, int decimals);

/// `v` in decimal, appended to `out` (std::to_string's text).
void append_integer(std::string& out, long long v);

/// The double nearest to fixed(v, decimals): a number of summary.json as its text has `decimals`
/// decimals (nlohmann::json then writes the shortest text of that double).
double as_written(double v, int decimals);

/// `v` rounded half away from zero to `decimals` decimals (0..9): round(v * 10^decimals) /
/// 10^decimals, never -0. The metrics' 1 mm / 1 ms rounding is rounded(v, 3).
double rounded(double v, int decimals);

/// fixed(rounded(v, decimals), decimals): the generator's numbers ("28.9", "0.30", "14").
std::string rounded_fixed(double v, int decimals);

/// printf-style text into a std::string, of any length (messages, names, table rows).
template <typename... Args>
std::string format_text(const char* fmt, Args... args) {
  char small[256];
  const int n = std::snprintf(small, sizeof small, fmt, args...);
  if (n < 0) return {};
  if (static_cast<std::size_t>(n) < sizeof small) return std::string(small, static_cast<std::size_t>(n));
  std::vector<char> big(static_cast<std::size_t>(n) + 1);
  std::snprintf(big.data(), big.size(), fmt, args...);
  return std::string(big.data(), static_cast<std::size_t>(n));
}

}  // namespace signalsim
