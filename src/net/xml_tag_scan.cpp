// scan_start_tags and the attribute readers (see the header). The character classes and what is an
// error follow pugixml 1.13's parser (name characters, whitespace before each attribute, '=' and a
// quoted value, an end tag naming the open element), so that a text scanned here is one pugixml
// parses, with the same elements.
#include "net/xml_tag_scan.hpp"

#include <pugixml.hpp>

#include <array>
#include <cstring>
#include <vector>

namespace signalsim::sumo {
namespace {

enum CharClass : unsigned char { kSpace = 1, kNameStart = 2, kNameChar = 4 };

constexpr std::array<unsigned char, 256> make_classes() {
  std::array<unsigned char, 256> classes{};
  for (int c = 0; c < 256; ++c) {
    const bool start = c >= 0x80 || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == ':';
    const bool name = start || (c >= '0' && c <= '9') || c == '-' || c == '.';
    const bool space = c == ' ' || c == '\t' || c == '\n' || c == '\r';
    classes[static_cast<std::size_t>(c)] =
        static_cast<unsigned char>((space ? kSpace : 0) | (start ? kNameStart : 0) | (name ? kNameChar : 0));
  }
  return classes;
}

constexpr std::array<unsigned char, 256> kClasses = make_classes();

bool has(char c, CharClass k) { return (kClasses[static_cast<unsigned char>(c)] & k) != 0; }
bool is_space(char c) { return has(c, kSpace); }
bool is_name_start(char c) { return has(c, kNameStart); }
bool is_name_char(char c) { return has(c, kNameChar); }

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

/// One attribute of a tag's raw attribute text.
struct Attribute {
  std::string_view name, value;
};

/// Reads the attribute at `at` of `text` (after optional whitespace); false at the end of the
/// attributes or on a syntax error (`error` says which).
bool next_attribute(std::string_view text, std::size_t& at, Attribute& out, bool& error) {
  while (at < text.size() && is_space(text[at])) ++at;
  if (at == text.size()) return false;
  if (!is_name_start(text[at])) return error = true, false;
  const std::size_t name_begin = at;
  while (at < text.size() && is_name_char(text[at])) ++at;
  out.name = text.substr(name_begin, at - name_begin);
  while (at < text.size() && is_space(text[at])) ++at;
  if (at == text.size() || text[at] != '=') return error = true, false;
  ++at;
  while (at < text.size() && is_space(text[at])) ++at;
  if (at == text.size() || (text[at] != '"' && text[at] != '\'')) return error = true, false;
  const char quote = text[at++];
  const std::size_t close = text.find(quote, at);
  if (close == std::string_view::npos) return error = true, false;
  out.value = text.substr(at, close - at);
  at = close + 1;
  // pugixml wants whitespace (or the tag's end, which is not in `text`) after a value.
  if (at < text.size() && !is_space(text[at])) return error = true, false;
  return true;
}

/// The encoding an XML declaration names is UTF-8 or none (pugixml then reads UTF-8 as is).
bool declares_utf8(std::string_view declaration) {
  const StartTag tag{"xml", declaration, 0, 0};
  const auto encoding = raw_attribute(tag, "encoding");
  return !encoding || iequals(*encoding, "utf-8") || iequals(*encoding, "utf8");
}

class Scanner {
 public:
  Scanner(std::string_view text, StartTagVisitor& visitor) : text_(text), visitor_(visitor) {}

  bool run() {
    if (text_.find('\0') != std::string_view::npos) return false;  // pugixml stops at it
    // A byte order mark, or UTF-16/32 without one (a NUL, above): pugixml converts, offsets move.
    if (text_.size() >= 2 && (static_cast<unsigned char>(text_[0]) >= 0xef)) return false;
    while (true) {
      const std::size_t lt = text_.find('<', at_);
      if (lt == std::string_view::npos) break;
      at_ = lt + 1;
      if (at_ == text_.size()) return false;
      const char c = text_[at_];
      bool ok = true;
      if (c == '?') ok = instruction(lt);
      else if (c == '!') ok = exclamation();
      else if (c == '/') ok = end_tag();
      else ok = start_tag(lt);
      if (!ok) return false;
    }
    return root_done_ && open_.empty();
  }

 private:
  bool skip_past(std::string_view end) {
    const std::size_t found = text_.find(end, at_);
    if (found == std::string_view::npos) return false;
    at_ = found + end.size();
    return true;
  }

  bool instruction(std::size_t lt) {
    ++at_;
    if (at_ == text_.size() || !is_name_start(text_[at_])) return false;
    const std::size_t name_begin = at_;
    while (at_ < text_.size() && is_name_char(text_[at_])) ++at_;
    const std::string_view target = text_.substr(name_begin, at_ - name_begin);
    const std::size_t body = at_;
    if (!skip_past("?>")) return false;
    if (iequals(target, "xml")) {  // the declaration: first in the text, and UTF-8
      if (lt != 0) return false;
      return declares_utf8(text_.substr(body, at_ - 2 - body));
    }
    return true;
  }

  bool exclamation() {
    const std::string_view rest = text_.substr(at_);
    if (rest.starts_with("!--")) {
      at_ += 3;
      return skip_past("-->");
    }
    if (rest.starts_with("![CDATA[") && !open_.empty()) {
      at_ += 8;
      return skip_past("]]>");
    }
    return false;  // a DOCTYPE (or an error): parsed whole
  }

  bool end_tag() {
    ++at_;
    const std::size_t name_begin = at_;
    while (at_ < text_.size() && is_name_char(text_[at_])) ++at_;
    const std::string_view name = text_.substr(name_begin, at_ - name_begin);
    while (at_ < text_.size() && is_space(text_[at_])) ++at_;
    if (at_ == text_.size() || text_[at_] != '>' || open_.empty() || open_.back() != name) return false;
    ++at_;
    open_.pop_back();
    if (open_.empty()) root_done_ = true;
    return true;
  }

  bool start_tag(std::size_t lt) {
    if (!is_name_start(text_[at_])) return false;
    const std::size_t name_begin = at_;
    while (at_ < text_.size() && is_name_char(text_[at_])) ++at_;
    StartTag tag;
    tag.name = text_.substr(name_begin, at_ - name_begin);
    tag.begin = lt;
    // The tag ends at the first '>' outside a quoted value.
    const std::size_t attributes_begin = at_;
    std::size_t close = at_;
    while (true) {
      if (close == text_.size()) return false;
      const char c = text_[close];
      if (c == '>') break;
      if (c == '<') return false;
      if (c == '"' || c == '\'') {
        close = text_.find(c, close + 1);
        if (close == std::string_view::npos) return false;
      }
      ++close;
    }
    const bool self_closing = text_[close - 1] == '/' && close - 1 >= attributes_begin;
    tag.attributes = text_.substr(attributes_begin, close - attributes_begin - (self_closing ? 1 : 0));
    if (!tag.attributes.empty() && !is_space(tag.attributes.front())) return false;  // "<a/b>", "<a"x"
    std::size_t cursor = 0;
    Attribute attribute;
    bool error = false;
    while (next_attribute(tag.attributes, cursor, attribute, error)) {
    }
    if (error) return false;
    at_ = close + 1;
    tag.depth = static_cast<int>(open_.size());
    if (!root_done_ && tag.depth <= 2) visitor_.start(tag);
    if (!self_closing) open_.push_back(tag.name);
    else if (open_.empty()) root_done_ = true;
    return true;
  }

  std::string_view text_;
  StartTagVisitor& visitor_;
  std::size_t at_ = 0;
  std::vector<std::string_view> open_;  // the names of the open elements
  bool root_done_ = false;  // the first root element is closed (later ones are not visited)
};

}  // namespace

bool scan_start_tags(std::string_view text, StartTagVisitor& visitor) { return Scanner(text, visitor).run(); }

std::optional<std::string_view> raw_attribute(const StartTag& tag, std::string_view name) {
  std::size_t at = 0;
  Attribute attribute;
  bool error = false;
  while (next_attribute(tag.attributes, at, attribute, error))
    if (attribute.name == name) return attribute.value;
  return std::nullopt;
}

std::string_view attribute_value(const StartTag& tag, std::string_view name, std::string& scratch) {
  const auto raw = raw_attribute(tag, name);
  if (!raw) return {};
  if (raw->find_first_of("&\t\n\r") == std::string_view::npos) return *raw;
  // Entities or whitespace to convert: pugixml's own reading of the tag alone.
  std::string tag_text = "<";
  tag_text.append(tag.name).append(tag.attributes).append("/>");
  pugi::xml_document doc;
  doc.load_buffer(tag_text.data(), tag_text.size(), pugi::parse_default, pugi::encoding_utf8);
  const std::string name_text(name);
  scratch = doc.first_child().attribute(name_text.c_str()).value();
  return scratch;
}

}  // namespace signalsim::sumo
