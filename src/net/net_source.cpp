// NetSource: the net's text, its document for a whole reading, and where its elements are (see the
// header).
#include "net/net_source.hpp"

#include "net/xml_tag_scan.hpp"

#include <algorithm>
#include <cstring>
#include <functional>
#include <utility>

namespace signalsim::sumo {
namespace {

/// Whether `lane_id` is "<edge_id>_<suffix without '_'>".
bool names_edge(std::string_view lane_id, std::string_view edge_id) {
  return lane_id.size() > edge_id.size() && lane_id.rfind('_') == edge_id.size() && lane_id.starts_with(edge_id);
}

}  // namespace

// ---- FirstDefinitions -------------------------------------------------------------------------------

std::ptrdiff_t FirstDefinitions::of(const std::string& kind, const std::string& key) {
  if (!built_) {
    if (source_.root_) {
      build(source_.root_);
    } else {  // read on demand: the text parsed, once
      pugi::xml_document doc;
      doc.load_buffer(source_.text_.data(), source_.text_.size());
      build(doc.document_element());
    }
  }
  const auto it = first_.find(kind + "\n" + key);
  return it == first_.end() ? -1 : it->second;
}

void FirstDefinitions::build(pugi::xml_node root) {
  built_ = true;
  for (pugi::xml_node n : root.children()) {
    const std::string name = n.name();
    if (name == "edge" || name == "junction") first_.emplace(name + "\n" + n.attribute("id").value(), n.offset_debug());
    if (name == "tlLogic") {
      first_.emplace(name + "\n" + n.attribute("id").value() + "\n" + n.attribute("programID").value(),
                     n.offset_debug());
    }
    if (name != "edge") continue;
    for (pugi::xml_node lane : n.children("lane"))
      first_.emplace(std::string("lane\n") + lane.attribute("id").value(), lane.offset_debug());
  }
}

// ---- small lists and the id store --------------------------------------------------------------------

void IdList::add(std::string_view id) {
  if (first.empty()) {
    first = id;
    return;
  }
  if ((more.empty() ? first : more.back()) != id) more.push_back(id);
}

void ViaList::add(std::string_view lane, std::string_view from_edge) {
  if (first.lane.empty()) {
    first = {lane, from_edge};
    return;
  }
  const Via& last = more.empty() ? first : more.back();
  if (last.lane != lane || last.from_edge != from_edge) more.push_back({lane, from_edge});
}

std::string_view IdStore::keep(std::string_view text) {
  const std::size_t n = text.size();
  if (used_ + n > size_) {
    size_ = std::max<std::size_t>(n, 1u << 16);
    blocks_.push_back(std::make_unique<char[]>(size_));
    used_ = 0;
  }
  char* at = blocks_.back().get() + used_;
  if (n != 0) std::memcpy(at, text.data(), n);
  used_ += n;
  return {at, n};
}

ParsedElement::ParsedElement(const std::string& text, std::size_t begin, std::size_t end) {
  // The last element's stretch runs to the end of the text: its parse stops at </net> with the
  // element complete (pugixml keeps what it parsed).
  doc_.load_buffer(text.data() + begin, end - begin, pugi::parse_default | pugi::parse_fragment, pugi::encoding_utf8);
}

// ---- NetSource -------------------------------------------------------------------------------------

pugi::xml_parse_result NetSource::parse_in_place() {
  const pugi::xml_parse_result parsed = doc_.load_buffer_inplace(text_.data(), text_.size());
  if (parsed) root_ = doc_.document_element();
  return parsed;
}

EdgeEntry* NetSource::edge_entry(std::string_view id) {
  const auto it = edges.find(id);
  return it == edges.end() || it->second.edge.head == ElementGroup::kNone ? nullptr : &it->second;
}

ElementGroup* NetSource::connections_from(std::string_view edge_id) {
  const auto it = edges.find(edge_id);
  return it == edges.end() ? nullptr : &it->second.connections;
}

std::vector<std::string> NetSource::lane_ids(const ElementGroup& group) const {
  std::vector<std::string> out;
  const Element& e = elements_[group.head];
  const ParsedElement parsed(text_, e.begin, e.end);
  for (pugi::xml_node lane : parsed.node().children("lane")) out.emplace_back(lane.attribute("id").value());
  return out;
}

std::string_view NetSource::edge_named_by(std::string_view lane_id) {
  const std::size_t cut = lane_id.rfind('_');
  if (cut == std::string_view::npos) return {};
  const auto edge = edges.find(lane_id.substr(0, cut));
  if (edge == edges.end() || edge->second.edge.head == ElementGroup::kNone) return {};
  for (const std::string& id : lane_ids(edge->second.edge))
    if (id == lane_id) return edge->first;
  return {};
}

ViaList* NetSource::via_list(std::string_view lane_id, bool create) {
  const std::size_t cut = lane_id.rfind('_');
  if (cut != std::string_view::npos) {
    if (create) return &edges[lane_id.substr(0, cut)].vias;
    const auto it = edges.find(lane_id.substr(0, cut));
    return it == edges.end() ? nullptr : &it->second.vias;
  }
  if (create) return &vias_elsewhere_[lane_id];
  const auto it = vias_elsewhere_.find(lane_id);
  return it == vias_elsewhere_.end() ? nullptr : &it->second;
}

void NetSource::add(Kind kind, ElementGroup& group, std::size_t begin) {
  const auto index = static_cast<std::uint32_t>(elements_.size());
  Element e;
  e.begin = begin;  // its '<'
  e.end = text_.size();  // until the next element's start is known
  e.kind = kind;
  e.group = &group;
  elements_.push_back(e);
  if (group.head == ElementGroup::kNone) group.head = index;
  else elements_[group.tail].next = index;
  group.tail = index;
}

/// What scan() keeps of each start tag: the root's, its children's, an edge's lanes.
class NetSource::TagVisitor : public StartTagVisitor {
 public:
  explicit TagVisitor(NetSource& source) : s_(source) {}

  void start(const StartTag& tag) override {
    if (tag.depth == 0) return root(tag);
    if (tag.depth == 2) {
      if (lanes_of_ != nullptr && tag.name == "lane") lane(tag);
      return;
    }
    // A child of the root: it ends the previous child's stretch.
    if (previous_ != kNone) s_.elements_[previous_].end = tag.begin;
    if (previous_light_) s_.lights_and_roundabouts_.back().second = tag.begin;
    previous_ = kNone;
    previous_light_ = false;
    lanes_of_ = nullptr;
    const std::size_t recorded = s_.elements_.size();
    if (tag.name == "edge") edge(tag);
    else if (tag.name == "connection") connection(tag);
    else if (tag.name == "junction") junction(tag);
    else if (tag.name == "tlLogic" || tag.name == "roundabout") {
      s_.lights_and_roundabouts_.emplace_back(tag.begin, s_.text_.size());
      previous_light_ = true;
    }
    if (s_.elements_.size() > recorded) previous_ = static_cast<std::uint32_t>(recorded);
  }

 private:
  static constexpr std::uint32_t kNone = ElementGroup::kNone;

  std::string_view value(const StartTag& tag, std::string_view name) {
    return attribute_value(tag, name, scratch_);
  }

  /// `id` where it lasts as long as the source: in the text when it was read as it is written
  /// there (the text never changes on demand), else a copy in the id store.
  std::string_view lasting(std::string_view id) {
    const char* text = s_.text_.data();
    const std::less<const char*> before;
    return !before(id.data(), text) && before(id.data(), text + s_.text_.size()) ? id : s_.ids_.keep(id);
  }

  void root(const StartTag& tag) {
    s_.root_name = std::string(tag.name);
    s_.root_offset = tag.begin;
    if (raw_attribute(tag, "lefthand")) s_.root_lefthand = std::string(value(tag, "lefthand"));
  }

  void edge(const StartTag& tag) {
    const std::string_view id = value(tag, "id");
    if (id.empty()) return s_.add(Kind::Edge, s_.edges_without_id, tag.begin);
    const auto entry = s_.edges.try_emplace(lasting(id)).first;
    ElementGroup& group = entry->second.edge;
    const bool first = group.head == ElementGroup::kNone;
    s_.add(Kind::Edge, group, tag.begin);
    if (!first) return;  // a repeated edge is ignored whole, its lanes too
    ++s_.edge_count;
    lanes_of_ = &entry->first;
  }

  void lane(const StartTag& tag) {
    const std::string_view lane_id = value(tag, "id");
    if (!lane_id.empty() && !names_edge(lane_id, *lanes_of_))
      s_.lanes_elsewhere_[lasting(lane_id)].add(*lanes_of_);
  }

  void connection(const StartTag& tag) {
    const std::string_view from = value(tag, "from");
    if (from.empty()) return s_.add(Kind::Connection, s_.connections_without_from, tag.begin);
    // netconvert writes an edge's connections one after another: the entry of the last from-edge is kept.
    if (last_from_entry_ == nullptr || last_from_ != from) {
      const auto entry = s_.edges.try_emplace(lasting(from)).first;
      last_from_ = entry->first;
      last_from_entry_ = &entry->second;
    }
    s_.add(Kind::Connection, last_from_entry_->connections, tag.begin);
    if (const std::string_view via = value(tag, "via"); !via.empty()) {
      const std::string_view kept = lasting(via);
      s_.via_list(kept, true)->add(kept, last_from_);
    }
  }

  void junction(const StartTag& tag) {
    const std::string_view id = value(tag, "id");
    if (id.empty()) return s_.add(Kind::Junction, s_.junctions_without_id, tag.begin);
    const auto entry = s_.junctions.try_emplace(lasting(id)).first;
    s_.add(Kind::Junction, entry->second, tag.begin);
  }

  NetSource& s_;
  std::string scratch_;  // a decoded attribute value
  std::uint32_t previous_ = kNone;  // the previous child of the root, when it is in elements_
  bool previous_light_ = false;     // ... when it is a light or a roundabout
  const std::string_view* lanes_of_ = nullptr;  // the edge whose lanes are being visited (its first <edge>)
  std::string_view last_from_;
  EdgeEntry* last_from_entry_ = nullptr;
};

bool NetSource::scan() {
  // A net has an <edge> for about every 450 to 900 bytes (a netgenerate grid 456, Bad Hersfeld
  // 660, bologna 900): a first guess (a visit of every element costs as much as the hashing it saves).
  edges.reserve(text_.size() / 500);
  TagVisitor visitor(*this);
  return scan_start_tags(text_, visitor);
}

}  // namespace signalsim::sumo
