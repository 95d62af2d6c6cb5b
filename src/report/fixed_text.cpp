// Fixed-point text with std::to_chars, the same text as printf's "%.*f" (fixed_text.hpp).
#include "report/fixed_text.hpp"

#include <charconv>
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

void append_fixed_text(std::string& out, double v, int decimals) {
  if (decimals < 0) decimals = 6;  // printf: a negative precision is taken as omitted
  char small[64];
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

void append_integer(std::string& out, long long v) {
  char text[24];
  const auto end = std::to_chars(text, text + sizeof text, v).ptr;
  out.append(text, static_cast<std::size_t>(end - text));
}

}  // namespace signalsim
