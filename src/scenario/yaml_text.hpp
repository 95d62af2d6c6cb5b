// What yaml-cpp accepts in a YAML file that signalsim refuses, each at its line: a second document
// (yaml-cpp reads the first and drops the rest, even a malformed one), a quoted text whose closing
// quote is missing (yaml-cpp ends it at the end of the file), and control characters (as bytes in the
// file, or written as escapes such as "\e" in a double-quoted text), which would reach the terminal,
// results.csv and folder names as they are.
#pragma once

#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

namespace signalsim {

/// Checks a YAML file's text before it is parsed: a control character (find_control_character,
/// utf8_text.hpp) and a second document (a `---` line after the first document's content, or
/// content after a `...` line). Throws InputError at the line (`what` names the file's kind).
void check_yaml_text(std::string_view text, const std::string& path, const std::string& what);

/// Checks the texts (keys and values) of a parsed YAML tree against the text they were parsed from:
/// a quoted text without its closing quote, a control character in a text. Throws InputError at the
/// text's line.
void check_yaml_texts(const YAML::Node& root, std::string_view text, const std::string& path);

/// Throws InputError (`file`, no line) when a text of `node` holds a control character: for trees
/// made from other text than a file (a `--set` value), where `what` names that text.
void check_yaml_values(const YAML::Node& node, const std::string& file, const std::string& what);

}  // namespace signalsim
