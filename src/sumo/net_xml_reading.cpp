#include "sumo/net_xml_reading.hpp"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <utility>

#include "sumo/net_index.hpp"
#include "sumo/number_parsing.hpp"

namespace signalsim::sumo {
namespace {

std::string lower(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::vector<std::string> split_blanks(std::string_view text) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i])) != 0) ++i;
    std::size_t j = i;
    while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j])) == 0) ++j;
    if (j > i) out.emplace_back(text.substr(i, j - i));
    i = j;
  }
  return out;
}

}  // namespace

std::string describe(const char* kind, const std::string& id) {
  return id.empty() ? std::string(kind) + " without id" : std::string(kind) + " '" + id + "'";
}

XmlElement::XmlElement(const std::string& path, pugi::xml_node node, std::string what)
    : path_(path), node_(node), what_(std::move(what)) {}

void XmlElement::fail(const std::string& reason) const { throw NetError(path_ + ": " + what_ + ": " + reason); }

std::string XmlElement::text(const char* name, const std::string& fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  return a ? std::string(a.value()) : fallback;
}

std::string XmlElement::required_text(const char* name) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a || *a.value() == '\0') fail(std::string("attribute '") + name + "' is missing");
  return a.value();
}

double XmlElement::number(const char* name, double fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a) return fallback;
  const auto value = parse_double(a.value());
  if (!value) fail(std::string("attribute '") + name + "' is not a number: '" + a.value() + "'");
  return *value;
}

double XmlElement::required_number(const char* name) const {
  if (!node_.attribute(name)) fail(std::string("attribute '") + name + "' is missing");
  return number(name, 0.0);
}

int XmlElement::integer(const char* name, int fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a) return fallback;
  const auto value = parse_int(a.value());
  if (!value) fail(std::string("attribute '") + name + "' is not an integer: '" + a.value() + "'");
  return *value;
}

int XmlElement::required_integer(const char* name) const {
  if (!node_.attribute(name)) fail(std::string("attribute '") + name + "' is missing");
  return integer(name, 0);
}

bool XmlElement::boolean(const char* name, bool fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a) return fallback;
  const std::string v = lower(a.value());
  if (v == "true" || v == "1" || v == "yes" || v == "on" || v == "x") return true;
  if (v == "false" || v == "0" || v == "no" || v == "off" || v == "-") return false;
  fail(std::string("attribute '") + name + "' is not a boolean: '" + a.value() + "'");
}

std::vector<std::string> XmlElement::list(const char* name) const { return split_blanks(text(name)); }

Polyline XmlElement::shape(const char* name) const {
  const pugi::xml_attribute a = node_.attribute(name);
  const std::vector<std::string> tokens = split_blanks(a ? a.value() : "");
  if (tokens.empty()) fail(std::string("has no ") + name);
  std::vector<Vec2> points;
  points.reserve(tokens.size());
  for (const std::string& token : tokens) {
    // "x,y" or "x,y,z"
    std::vector<std::string_view> parts;
    std::string_view rest = token;
    for (;;) {
      const std::size_t comma = rest.find(',');
      parts.push_back(rest.substr(0, comma));
      if (comma == std::string_view::npos) break;
      rest.remove_prefix(comma + 1);
    }
    const auto x = parts.size() >= 2 ? parse_double(parts[0]) : std::nullopt;
    const auto y = parts.size() >= 2 ? parse_double(parts[1]) : std::nullopt;
    const bool z_ok = parts.size() == 2 || (parts.size() == 3 && parse_double(parts[2]).has_value());
    if (!x || !y || !z_ok) fail(std::string("attribute '") + name + "' has a malformed point: '" + token + "'");
    points.push_back({*x, *y});
  }
  return Polyline(std::move(points));
}

}  // namespace signalsim::sumo
