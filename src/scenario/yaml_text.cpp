// The checks of yaml_text.hpp: a second document, an unterminated quoted text, control characters.
#include "scenario/yaml_text.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "scenario/input_error.hpp"
#include "scenario/utf8_text.hpp"

namespace signalsim {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// Whether `line` is the marker `marker` ("---" or "..."), alone or followed by a blank.
bool is_marker(std::string_view line, std::string_view marker) {
  return line.starts_with(marker) && (line.size() == marker.size() || line[marker.size()] == ' ' ||
                                      line[marker.size()] == '\t' || line[marker.size()] == '\r');
}

// Whether `line` holds something of a document: not blank, not only a comment, not a directive (%YAML).
bool has_content(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t\r");
  return first != std::string_view::npos && line[first] != '#' && !(first == 0 && line[0] == '%');
}

// The line (1-based) where a second document starts, if any: a `---` line once the first document
// has content (a file may open with `---`), or content after a `...` line.
std::optional<int> second_document_line(std::string_view text) {
  bool content = false, ended = false;
  int number = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++number;
    if (is_marker(line, "---")) {
      if (content || ended) return number;
      content = has_content(line.substr(3));
      continue;
    }
    if (is_marker(line, "...")) {
      ended = content || ended;
      continue;
    }
    if (has_content(line)) {
      if (ended) return number;
      content = true;
    }
  }
  return std::nullopt;
}

// Whether the quoted text opening at `open` (its quote) is closed before the end of `text`.
bool quote_closed(std::string_view text, std::size_t open) {
  const char quote = text[open];
  for (std::size_t i = open + 1; i < text.size(); ++i) {
    if (quote == '"' && text[i] == '\\') {
      ++i;  // an escape: the next character is its
      continue;
    }
    if (text[i] != quote) continue;
    if (quote == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
      ++i;  // '' is a quote inside single quotes
      continue;
    }
    return true;
  }
  return false;
}

// A control character in a text of the tree (after YAML's escapes), as the reason of a message.
std::optional<std::string> control_in(const std::string& scalar) {
  const auto found = find_control_character(scalar, false);
  if (!found) return std::nullopt;
  char code[16];
  std::snprintf(code, sizeof code, "U+%04X", found->code);
  return std::string("a text holds a control character (") + code + "); texts may hold tabs and line breaks only";
}

void walk_texts(const YAML::Node& node, std::string_view text, std::size_t base, const std::string& path) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      walk_texts(entry.first, text, base, path);
      walk_texts(entry.second, text, base, path);
    }
    return;
  }
  if (node.IsSequence()) {
    for (const YAML::Node& item : node) walk_texts(item, text, base, path);
    return;
  }
  if (!node.IsScalar()) return;
  const int line = node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
  // yaml-cpp's mark is the byte offset after a byte order mark; a quoted text starts at its quote.
  const std::size_t at = base + static_cast<std::size_t>(std::max(node.Mark().pos, 0));
  if (node.Tag() == "!" && at < text.size() && (text[at] == '"' || text[at] == '\'') && !quote_closed(text, at))
    throw InputError(path, line, std::string("malformed YAML: the quoted text opened here has no closing ") +
                                     (text[at] == '"' ? "\"" : "'"));
  if (const auto reason = control_in(node.Scalar())) throw InputError(path, line, *reason);
}

}  // namespace

void check_yaml_text(std::string_view text, const std::string& path, const std::string& what) {
  if (const auto found = find_control_character(text, true))
    throw InputError(path, found->line, describe_control_character(text, *found) +
                                            "; texts may hold tabs and line breaks only");
  if (const auto line = second_document_line(text))
    throw InputError(path, *line, "a second YAML document starts here; a " + what + " holds one document");
}

void check_yaml_texts(const YAML::Node& root, std::string_view text, const std::string& path) {
  walk_texts(root, text, text.starts_with(kByteOrderMark) ? kByteOrderMark.size() : 0, path);
}

void check_yaml_values(const YAML::Node& node, const std::string& file, const std::string& what) {
  if (node.IsMap()) {
    for (const auto& entry : node) {
      check_yaml_values(entry.first, file, what);
      check_yaml_values(entry.second, file, what);
    }
  } else if (node.IsSequence()) {
    for (const YAML::Node& item : node) check_yaml_values(item, file, what);
  } else if (node.IsScalar()) {
    if (const auto reason = control_in(node.Scalar())) throw InputError(file, 0, what + ": " + *reason);
  }
}

}  // namespace signalsim
