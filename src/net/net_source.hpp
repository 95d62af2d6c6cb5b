// NetSource: a net file's text kept in memory, and where each element is in it, so that NetIndex
// reads an element's values only when a lookup first needs them (net_index.hpp: the run of a route
// on a city net reads its few hundred elements, not the 200 000 of the file).
//
// For a whole reading the text is parsed in place into a document. On demand no document is built
// (it would be twice the size of the text): scan() reads the start tags (xml_tag_scan.hpp), which
// checks the structure of the whole text, keeping only ids (an element's `id`, a connection's
// `from` and `via`, lane ids) and where each element's stretch of the text is; an element is parsed
// from its stretch when it is read. A text the tag scan declines is read whole. The groups the scan
// builds are what one lookup must read for its answer to be the one a reading of the whole file
// gives (see net_on_demand.cpp):
//   - every <edge> with one id (a repeated id is a defect of the later ones),
//   - every <junction> with one id,
//   - every <connection> with one `from` (its defects go against its from-lane or from-edge),
//   - for a lane id, the edges that define it (a lane id repeated on another edge is a defect): the
//     edge its id names ("<edge>_<index>", as netconvert writes every lane id), found without a
//     table, and the few edges defining a lane id that does not name them,
//   - for an internal lane id, the from-edges of the connections with it as `via`.
// The groups of one edge id share one table entry (EdgeEntry).
// Private to the net loader (it exposes pugixml, which signalsim_sumo links privately).
#pragma once

#include <pugixml.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace signalsim::sumo {

class NetSource;

/// The offset of the first definition of a repeated id. Repeated ids are rare (SUMO refuses them),
/// so the table of first definitions is built only at the first one: one pass over the document
/// (parsed for it when there is none), and the load stays linear however many ids repeat.
class FirstDefinitions {
 public:
  explicit FirstDefinitions(const NetSource& source) : source_(source) {}
  std::ptrdiff_t of(const std::string& kind, const std::string& key);

 private:
  void build(pugi::xml_node root);
  const NetSource& source_;
  bool built_ = false;
  std::unordered_map<std::string, std::ptrdiff_t> first_;
};

/// Elements of one kind and key, in file order, and whether they have been read.
struct ElementGroup {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::uint32_t head = kNone;  ///< into NetSource's element list
  std::uint32_t tail = kNone;
  bool read = false;
};

/// A few ids, nearly always one (no allocation then).
struct IdList {
  std::string_view first;
  std::vector<std::string_view> more;
  void add(std::string_view id);
  template <typename F>
  void each(F&& f) const {
    if (!first.empty()) f(first);
    for (std::string_view id : more) f(id);
  }
};

/// The connections through one internal lane, by from-edge: nearly always one (no allocation then).
struct ViaList {
  struct Via {
    std::string_view lane, from_edge;
  };
  Via first;
  std::vector<Via> more;
  void add(std::string_view lane, std::string_view from_edge);
  template <typename F>
  void each_from_edge(std::string_view lane, F&& f) const {
    if (first.lane == lane) f(first.from_edge);
    for (const Via& v : more)
      if (v.lane == lane) f(v.from_edge);
  }
};

/// What is known of one edge id: its <edge>s, the <connection>s from it, and the connections
/// through the lanes it names ("<id>_<k>"): one table entry, as a lookup usually needs all three.
struct EdgeEntry {
  ElementGroup edge;
  ElementGroup connections;
  ViaList vias;
};

/// Copies of the ids the scan keeps that are not in the text as written (decoded attribute values),
/// in blocks that never move.
class IdStore {
 public:
  std::string_view keep(std::string_view text);

 private:
  std::vector<std::unique_ptr<char[]>> blocks_;
  std::size_t used_ = 0, size_ = 0;
};

/// One element parsed again from its stretch of the text.
class ParsedElement {
 public:
  ParsedElement(const std::string& text, std::size_t begin, std::size_t end);
  pugi::xml_node node() const { return doc_.first_child(); }

 private:
  pugi::xml_document doc_;
};

class NetSource {
 public:
  explicit NetSource(std::string bytes) : text_(std::move(bytes)) {}
  NetSource(const NetSource&) = delete;
  NetSource& operator=(const NetSource&) = delete;

  /// A whole reading: parses the text in place (so it changes) into a document.
  pugi::xml_parse_result parse_in_place();
  /// The document's root (after parse_in_place).
  pugi::xml_node root() const { return root_; }
  /// The file's text as read (on demand; parsed in place, and so changed, for a whole reading).
  const std::string& text() const { return text_; }
  /// The text, taken out (a scan declined it: it is read whole).
  std::string take_text() && { return std::move(text_); }

  /// On demand: records where every <edge>, <junction>, <connection>, <tlLogic> and <roundabout>
  /// is (ids only, nothing else read), and the root's name and `lefthand`. False when the tag scan
  /// declines the text: then it must be read whole.
  bool scan();
  /// The root element's name, its `lefthand` attribute (nullopt: none) and where its start tag
  /// begins, after scan.
  std::string root_name;
  std::optional<std::string> root_lefthand;
  std::size_t root_offset = 0;

  /// Keys are views into the text or the IdStore. An entry may have no <edge> (connections from an edge the
  /// net lacks): see `edge_count`.
  std::unordered_map<std::string_view, EdgeEntry> edges;
  std::unordered_map<std::string_view, ElementGroup> junctions;
  /// Elements without the id they are grouped by: read only with the whole net (listed defects).
  ElementGroup edges_without_id, junctions_without_id, connections_without_from;
  /// Edge ids with an <edge> element.
  std::size_t edge_count = 0;
  /// Calls `f(node, base)` for the <tlLogic> and <roundabout> elements in file order (read at
  /// load), each parsed from its stretch (`base` as for each_element).
  template <typename F>
  void each_light_or_roundabout(F&& f) const {
    for (const auto& [begin, end] : lights_and_roundabouts_) {
      const ParsedElement parsed(text_, begin, end);
      f(parsed.node(), static_cast<std::ptrdiff_t>(begin));
    }
  }

  /// The entry of an edge with an <edge> element, or null.
  EdgeEntry* edge_entry(std::string_view id);
  /// The group of connections from `edge_id`, or null.
  ElementGroup* connections_from(std::string_view edge_id);

  /// Calls `f(edge_id)` for each (first) edge with a lane `lane_id`, in no particular order.
  template <typename F>
  void each_edge_defining(std::string_view lane_id, F&& f) {
    if (const std::string_view named = edge_named_by(lane_id); !named.empty()) f(named);
    if (const auto other = lanes_elsewhere_.find(lane_id); other != lanes_elsewhere_.end()) other->second.each(f);
  }
  /// Calls `f(from_edge_id)` for the connections with `via` = `lane_id`, in no particular order.
  template <typename F>
  void each_from_edge_via(std::string_view lane_id, F&& f) {
    if (const ViaList* vias = via_list(lane_id, false)) vias->each_from_edge(lane_id, f);
  }
  /// The lane ids of a group's first <edge>, in file order.
  std::vector<std::string> lane_ids(const ElementGroup& group) const;

  enum class Kind : std::uint8_t { Edge, Junction, Connection };
  /// Calls `f(kind, group)` for the group of every scanned element, in file order (a group once
  /// per element of it).
  template <typename F>
  void each_element_group(F&& f) {
    for (std::size_t i = 0; i < elements_.size(); ++i) f(elements_[i].kind, *elements_[i].group);
  }
  /// Calls `f(node, base)` for the elements of a group in file order, each parsed again: `base` is
  /// the offset in the text of the node's offset_debug() 0.
  template <typename F>
  void each_element(const ElementGroup& group, F&& f) const {
    for (std::uint32_t i = group.head; i != ElementGroup::kNone; i = elements_[i].next) {
      const ParsedElement parsed(text_, elements_[i].begin, elements_[i].end);
      f(parsed.node(), static_cast<std::ptrdiff_t>(elements_[i].begin));
    }
  }
  /// The offset of a group's first element (its place in the file).
  std::ptrdiff_t offset_of(const ElementGroup& group) const {
    return static_cast<std::ptrdiff_t>(elements_[group.head].begin) + 1;  // its name, as offset_debug()
  }

  FirstDefinitions first_definitions{*this};

 private:
  struct Element {
    std::size_t begin = 0, end = 0;  // its stretch of the text: from its '<' to the next element's
    std::uint32_t next = ElementGroup::kNone;  // the next element of its group
    Kind kind = Kind::Edge;
    ElementGroup* group = nullptr;  // the maps' values do not move
  };
  class TagVisitor;
  void add(Kind kind, ElementGroup& group, std::size_t begin);
  /// The edge a lane id names ("<edge>_<suffix without '_'>") when that edge has such a lane, or "".
  std::string_view edge_named_by(std::string_view lane_id);
  /// Where the connections through `lane_id` are listed: the entry of the edge it names, else a
  /// table of its own.
  ViaList* via_list(std::string_view lane_id, bool create);

  std::string text_;  // the file's text; parsed in place (whole reading) or kept as it is (on demand)
  pugi::xml_document doc_;  // a whole reading's
  pugi::xml_node root_;
  std::vector<std::pair<std::size_t, std::size_t>> lights_and_roundabouts_;  // their stretches
  IdStore ids_;
  std::vector<Element> elements_;
  /// Lane id -> the edges with a lane of that id that it does not name (a hand-written net's).
  std::unordered_map<std::string_view, IdList> lanes_elsewhere_;
  /// Internal lane ids without '_' (they name no edge): the connections through them.
  std::unordered_map<std::string_view, ViaList> vias_elsewhere_;

  friend class FirstDefinitions;
};

}  // namespace signalsim::sumo
