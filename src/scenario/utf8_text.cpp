#include "scenario/utf8_text.hpp"

#include <cstdio>

namespace signalsim {

std::optional<Utf8Problem> find_invalid_utf8(std::string_view text) {
  int line = 1;
  std::size_t i = 0;
  const std::size_t n = text.size();
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  while (i < n) {
    const unsigned char c = byte(i);
    if (c < 0x80) {
      line += c == '\n';
      ++i;
      continue;
    }
    // The length of the sequence and the range of its second byte (RFC 3629 table).
    std::size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;
    if (c >= 0xC2 && c <= 0xDF) length = 2;
    else if (c == 0xE0) length = 3, low = 0xA0;
    else if (c >= 0xE1 && c <= 0xEC) length = 3;
    else if (c == 0xED) length = 3, high = 0x9F;  // no surrogates
    else if (c >= 0xEE && c <= 0xEF) length = 3;
    else if (c == 0xF0) length = 4, low = 0x90;
    else if (c >= 0xF1 && c <= 0xF3) length = 4;
    else if (c == 0xF4) length = 4, high = 0x8F;  // at most U+10FFFF
    bool ok = length > 0 && i + length <= n;
    for (std::size_t k = 1; ok && k < length; ++k) {
      const unsigned char next = byte(i + k);
      ok = k == 1 ? next >= low && next <= high : next >= 0x80 && next <= 0xBF;
    }
    if (!ok) return Utf8Problem{i, line, c};
    i += length;
  }
  return std::nullopt;
}

namespace {

// The 1-based column (in bytes) of `offset` in its line.
std::size_t column_of(std::string_view text, std::size_t offset) {
  const std::size_t line_start = text.rfind('\n', offset == 0 ? 0 : offset - 1);
  return offset - (line_start == std::string_view::npos || offset == 0 ? 0 : line_start + 1) + 1;
}

}  // namespace

std::string describe_invalid_utf8(std::string_view text, const Utf8Problem& problem) {
  const std::size_t column = column_of(text, problem.offset);
  char buf[96];
  std::snprintf(buf, sizeof buf, "invalid UTF-8 (byte 0x%02X at column %zu)",
                static_cast<unsigned>(problem.byte), column);
  return buf;
}

std::optional<ControlCharacter> find_control_character(std::string_view text, bool carriage_return_allowed) {
  int line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n') {
      ++line;
      continue;
    }
    if (c == '\t' || (c == '\r' && carriage_return_allowed)) continue;
    if (c < 0x20 || c == 0x7F) return ControlCharacter{i, line, c};
    // C1 in UTF-8: 0xC2 then 0x80 to 0x9F.
    if (c == 0xC2 && i + 1 < text.size()) {
      const auto next = static_cast<unsigned char>(text[i + 1]);
      if (next >= 0x80 && next <= 0x9F) return ControlCharacter{i, line, next};
    }
  }
  return std::nullopt;
}

std::string describe_control_character(std::string_view text, const ControlCharacter& found) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "a control character (U+%04X at column %zu)", found.code, column_of(text, found.offset));
  return buf;
}

std::string name_problem(std::string_view name, bool names_a_folder) {
  if (name.find_first_not_of(" \t\n") == std::string_view::npos) return "the name is empty";
  if (!names_a_folder) return "";
  if (name.find('/') != std::string_view::npos || name == "." || name == "..")
    return "'" + std::string(name) + "' is not a folder name (it names the output folder out/<name>: no '/', not . or ..)";
  return "";
}

}  // namespace signalsim
