// Typed access to the attributes of one .net.xml element. A value that cannot be read is not an
// exception: it is recorded in a DefectLog against the element (named in the message, e.g.
// "lane 's_in_0': attribute 'speed' is not a number: 'fast'") and the getter returns its fallback.
// Private to the net loader (it exposes pugixml, which signalsim_sumo links privately).
#pragma once

#include <pugixml.hpp>

#include <cstddef>
#include <deque>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/polyline.hpp"
#include "net/net_index.hpp"

namespace signalsim::sumo {

/// The element a defect is recorded against: its kind and id. No owner: listed only.
using DefectOwner = std::optional<std::pair<NetElement, std::string>>;

/// The defects of one net as its elements are read (all at load, or each element the first time a
/// lookup needs it, net_index.hpp): each gets its line when it is recorded.
class DefectLog {
 public:
  DefectLog() = default;
  /// `newlines`: the sorted offsets of the text's '\n' (see newline_offsets).
  explicit DefectLog(std::vector<std::size_t> newlines) : newlines_(std::move(newlines)), have_newlines_(true) {}
  /// The newlines are found in `text` (which must stay as it is) when the first defect comes: a net
  /// without defects never needs them.
  explicit DefectLog(const std::string* text) : text_(text) {}

  /// `offset`: of the element in the buffer; `earlier`: of a first definition (a repeated id), or -1.
  void add(const DefectOwner& owner, std::string element, std::string reason, std::ptrdiff_t offset,
           bool affects_routes = true, std::ptrdiff_t earlier = -1);

  /// The first defect in file order recorded against this element that affects routes, or null.
  const NetDefect* first_against(NetElement kind, const std::string& id) const;
  /// Every defect recorded, in file order (of equal offsets, in the order recorded).
  std::vector<NetDefect> in_file_order() const;
  /// No more defects come (the whole net is read): the line index is freed.
  void seal() {
    newlines_ = {};
    text_ = nullptr;
  }

  /// The offset in the text of offset 0 of the nodes being read: an element parsed again on its
  /// own (NetSource) has offsets from its start.
  void set_fragment_base(std::ptrdiff_t base) { fragment_base_ = base; }
  std::ptrdiff_t fragment_base() const { return fragment_base_; }

 private:
  int line_of(std::ptrdiff_t offset) const;

  struct Recorded {
    NetDefect defect;
    std::ptrdiff_t offset = 0;
  };
  mutable std::vector<std::size_t> newlines_;
  mutable bool have_newlines_ = false;
  const std::string* text_ = nullptr;
  std::ptrdiff_t fragment_base_ = 0;
  std::deque<Recorded> recorded_;                                 // in the order recorded
  std::unordered_map<std::string, std::size_t> first_against_;  // defect_key -> the first in file order
};

class XmlElement {
 public:
  /// `what` names the element in messages, e.g. "lane 's_in_0'" or "connection 'a' -> 'b'";
  /// defects go to `log` against `owner`.
  XmlElement(pugi::xml_node node, std::string what, DefectOwner owner, DefectLog& log);

  /// Attribute text, or `fallback` when the attribute is absent.
  std::string text(const char* name, const std::string& fallback = "") const;
  /// Attribute text; absent or empty: a defect, nullopt.
  std::optional<std::string> required_text(const char* name) const;
  /// Attribute as a finite number, `fallback` when absent; a defect (and `fallback`) when it does not parse.
  double number(const char* name, double fallback) const;
  /// The same, and absent is a defect too (nullopt).
  std::optional<double> required_number(const char* name) const;
  int integer(const char* name, int fallback) const;
  std::optional<int> required_integer(const char* name) const;
  /// Blank-separated list ("a b  c" -> {a, b, c}); empty when absent.
  std::vector<std::string> list(const char* name) const;
  /// SUMO shape "x,y x,y ..." (each point may carry a third coordinate z, which is dropped), at
  /// least two points. A defect (nullopt) when absent, empty or malformed.
  std::optional<Polyline> shape(const char* name) const;

  /// Records `reason` against this element.
  void defect(const std::string& reason, bool affects_routes = true, std::ptrdiff_t earlier = -1) const;
  /// The element's offset in the text.
  std::ptrdiff_t offset() const { return node_.offset_debug() + log_->fragment_base(); }
  const std::string& what() const { return what_; }

 private:
  pugi::xml_node node_;
  std::string what_;
  DefectOwner owner_;
  DefectLog* log_;
};

/// The offsets of every '\n' in `text`, in order (taken before pugixml may parse it in place).
std::vector<std::size_t> newline_offsets(const std::string& text);

/// "<kind> '<id>'" for messages; "<kind> without id" when `id` is empty.
std::string describe(const char* kind, const std::string& id);

/// SUMO booleans: true/false, 1/0, yes/no, on/off, x/- (any case); nullopt otherwise.
std::optional<bool> parse_sumo_bool(const std::string& text);

}  // namespace signalsim::sumo
