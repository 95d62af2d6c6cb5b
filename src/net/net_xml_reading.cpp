#include "net/net_xml_reading.hpp"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <numeric>
#include <string_view>

#include "core/number_parsing.hpp"

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

std::string missing(const char* name) { return std::string("attribute '") + name + "' is missing"; }

}  // namespace

std::string describe(const char* kind, const std::string& id) {
  return id.empty() ? std::string(kind) + " without id" : std::string(kind) + " '" + id + "'";
}

std::optional<bool> parse_sumo_bool(const std::string& text) {
  const std::string v = lower(text);
  if (v == "true" || v == "1" || v == "yes" || v == "on" || v == "x") return true;
  if (v == "false" || v == "0" || v == "no" || v == "off" || v == "-") return false;
  return std::nullopt;
}

// ---- DefectLog ------------------------------------------------------------------------------------

void DefectLog::add(const DefectOwner& owner, std::string element, std::string reason, std::ptrdiff_t offset,
                    bool affects_routes, std::ptrdiff_t earlier) {
  Recorded r;
  r.defect.element = std::move(element);
  r.defect.reason = std::move(reason);
  r.defect.affects_routes = affects_routes;
  r.defect.line = line_of(offset);
  if (earlier >= 0) r.defect.reason += " (first defined at line " + std::to_string(line_of(earlier)) + ")";
  r.offset = offset;
  recorded_.push_back(std::move(r));
  if (!owner || !affects_routes) return;
  // Elements may be read out of file order (on demand): the first is the one with the lowest
  // offset; of one element's defects, the first recorded.
  const auto [it, fresh] = first_against_.emplace(defect_key(owner->first, owner->second), recorded_.size() - 1);
  if (!fresh && offset < recorded_[it->second].offset) it->second = recorded_.size() - 1;
}

const NetDefect* DefectLog::first_against(NetElement kind, const std::string& id) const {
  if (first_against_.empty()) return nullptr;
  const auto it = first_against_.find(defect_key(kind, id));
  return it == first_against_.end() ? nullptr : &recorded_[it->second].defect;
}

std::vector<NetDefect> DefectLog::in_file_order() const {
  std::vector<std::size_t> order(recorded_.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return recorded_[a].offset < recorded_[b].offset; });
  std::vector<NetDefect> out;
  out.reserve(order.size());
  for (std::size_t i : order) out.push_back(recorded_[i].defect);
  return out;
}

// 1 + the newlines before the offset; 0 when pugixml gave no offset.
int DefectLog::line_of(std::ptrdiff_t offset) const {
  if (offset < 0) return 0;
  if (!have_newlines_ && text_ != nullptr) {
    newlines_ = newline_offsets(*text_);
    have_newlines_ = true;
  }
  return 1 + static_cast<int>(std::lower_bound(newlines_.begin(), newlines_.end(), static_cast<std::size_t>(offset)) -
                              newlines_.begin());
}

std::vector<std::size_t> newline_offsets(const std::string& text) {
  std::vector<std::size_t> out;
  for (const char* p = text.data(); (p = static_cast<const char*>(std::memchr(p, '\n', text.data() + text.size() - p)));
       ++p)
    out.push_back(static_cast<std::size_t>(p - text.data()));
  return out;
}

// ---- XmlElement -----------------------------------------------------------------------------------

XmlElement::XmlElement(pugi::xml_node node, std::string what, DefectOwner owner, DefectLog& log)
    : node_(node), what_(std::move(what)), owner_(std::move(owner)), log_(&log) {}

void XmlElement::defect(const std::string& reason, bool affects_routes, std::ptrdiff_t earlier) const {
  log_->add(owner_, what_, reason, offset(), affects_routes, earlier);
}

std::string XmlElement::text(const char* name, const std::string& fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  return a ? std::string(a.value()) : fallback;
}

std::optional<std::string> XmlElement::required_text(const char* name) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a || *a.value() == '\0') {
    defect(missing(name));
    return std::nullopt;
  }
  return std::string(a.value());
}

double XmlElement::number(const char* name, double fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a) return fallback;
  const auto value = parse_double(a.value());
  if (!value) {
    defect(std::string("attribute '") + name + "' is not a number: '" + a.value() + "'");
    return fallback;
  }
  return *value;
}

std::optional<double> XmlElement::required_number(const char* name) const {
  if (!node_.attribute(name)) {
    defect(missing(name));
    return std::nullopt;
  }
  const pugi::xml_attribute a = node_.attribute(name);
  const auto value = parse_double(a.value());
  if (!value) defect(std::string("attribute '") + name + "' is not a number: '" + a.value() + "'");
  return value;
}

int XmlElement::integer(const char* name, int fallback) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a) return fallback;
  const auto value = parse_int(a.value());
  if (!value) {
    defect(std::string("attribute '") + name + "' is not an integer: '" + a.value() + "'");
    return fallback;
  }
  return *value;
}

std::optional<int> XmlElement::required_integer(const char* name) const {
  const pugi::xml_attribute a = node_.attribute(name);
  if (!a) {
    defect(missing(name));
    return std::nullopt;
  }
  const auto value = parse_int(a.value());
  if (!value) defect(std::string("attribute '") + name + "' is not an integer: '" + a.value() + "'");
  return value;
}

std::vector<std::string> XmlElement::list(const char* name) const { return split_blanks(text(name)); }

std::optional<Polyline> XmlElement::shape(const char* name) const {
  const pugi::xml_attribute a = node_.attribute(name);
  const std::vector<std::string> tokens = split_blanks(a ? a.value() : "");
  if (tokens.empty()) {
    defect(std::string("has no ") + name);
    return std::nullopt;
  }
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
    if (!x || !y || !z_ok) {
      defect(std::string("attribute '") + name + "' has a malformed point: '" + token + "'");
      return std::nullopt;
    }
    points.push_back({*x, *y});
  }
  if (points.size() < 2) {
    defect(std::string("attribute '") + name + "' has one point; a lane needs two");
    return std::nullopt;
  }
  return Polyline(std::move(points));
}

}  // namespace signalsim::sumo
