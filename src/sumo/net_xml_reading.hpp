// Typed access to the attributes of one .net.xml element, with NetError messages that name the file,
// the element and the attribute: "<path>: lane 's_in_0': attribute 'speed' is not a number: 'fast'".
// Private to net_index.cpp (it exposes pugixml, which signalsim_sumo links privately).
#pragma once

#include <pugixml.hpp>

#include <string>
#include <vector>

#include "core/polyline.hpp"

namespace signalsim::sumo {

class XmlElement {
 public:
  /// `what` names the element in messages, e.g. "lane 's_in_0'" or "connection 'a' -> 'b'".
  XmlElement(const std::string& path, pugi::xml_node node, std::string what);

  /// Attribute text, or `fallback` when the attribute is absent.
  std::string text(const char* name, const std::string& fallback = "") const;
  /// Attribute text; throws NetError when absent or empty.
  std::string required_text(const char* name) const;
  /// Attribute as a finite number, `fallback` when absent; throws NetError when it does not parse.
  double number(const char* name, double fallback) const;
  double required_number(const char* name) const;
  int integer(const char* name, int fallback) const;
  int required_integer(const char* name) const;
  /// SUMO booleans: true/false, 1/0, yes/no, on/off, x/- (any case); `fallback` when absent.
  bool boolean(const char* name, bool fallback) const;
  /// Blank-separated list ("a b  c" -> {a, b, c}); empty when absent.
  std::vector<std::string> list(const char* name) const;
  /// SUMO shape "x,y x,y ..." (each point may carry a third coordinate z, which is dropped).
  /// Throws NetError when absent, empty or malformed.
  Polyline shape(const char* name) const;

  [[noreturn]] void fail(const std::string& reason) const;

 private:
  const std::string& path_;
  pugi::xml_node node_;
  std::string what_;
};

/// "<kind> '<id>'" for messages; "<kind> without id" when `id` is empty.
std::string describe(const char* kind, const std::string& id);

}  // namespace signalsim::sumo
