#include "core/number_parsing.hpp"

#include <iomanip>
#include <sstream>

#include <charconv>
#include <cmath>
#include <system_error>

namespace signalsim {
namespace {

std::string_view trim_for_number(std::string_view text) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && blank(text.back())) text.remove_suffix(1);
  // std::from_chars rejects a leading '+', which SUMO's own parser accepts.
  if (text.size() > 1 && text.front() == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  return text;
}

template <typename T>
std::optional<T> parse_whole(std::string_view text) {
  text = trim_for_number(text);
  if (text.empty()) return std::nullopt;
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc{} || ptr != end) return std::nullopt;
  return value;
}

}  // namespace

std::optional<double> parse_double(std::string_view text) {
  auto value = parse_whole<double>(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::optional<int> parse_int(std::string_view text) { return parse_whole<int>(text); }

std::string exact_number(double v) {
  std::ostringstream out;
  out << std::setprecision(17) << v;
  return out.str();
}

std::string short_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

}  // namespace signalsim
