// Text read from the user's files and command line must be UTF-8: summary.json and the other outputs
// are JSON/CSV in UTF-8, and a byte that is not would only fail when they are written, after the run.
// Nor may it hold control characters, which would reach the terminal, results.csv and folder names as
// they are. Checked when a file is loaded, so the message names the file and the line.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace signalsim {

/// Where `text` stops being UTF-8: the offset of the first byte of the bad sequence, its line (1-based)
/// and that byte. Overlong forms, surrogates and code points above U+10FFFF are not UTF-8.
struct Utf8Problem {
  std::size_t offset = 0;
  int line = 1;
  unsigned char byte = 0;
};
std::optional<Utf8Problem> find_invalid_utf8(std::string_view text);

/// "invalid UTF-8 (byte 0xE9 at column 11)" for messages (the column counts bytes).
std::string describe_invalid_utf8(std::string_view text, const Utf8Problem& problem);

/// A control character of `text`: C0 but tab and line feed (and carriage return where
/// `carriage_return_allowed`: a file's CRLF line ends), DEL, and C1 (U+0080 to U+009F, written as two
/// bytes in UTF-8). Its offset, line (1-based) and code point.
struct ControlCharacter {
  std::size_t offset = 0;
  int line = 1;
  unsigned code = 0;
};
std::optional<ControlCharacter> find_control_character(std::string_view text, bool carriage_return_allowed);

/// "a control character (U+001B at column 7)" for messages (the column counts bytes).
std::string describe_control_character(std::string_view text, const ControlCharacter& found);

/// What is wrong with a name a user gives (a scenario's or a sweep's `name`), "" when nothing: it may
/// not be empty or blank. A name that `names_a_folder` (a sweep's: its default output folder
/// out/<name>) is one folder name: no '/' and not "." or "..", so the output stays in out/.
std::string name_problem(std::string_view name, bool names_a_folder);

}  // namespace signalsim
