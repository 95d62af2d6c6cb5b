// NetSource: the net's text, its parsed document until the scan is done, and where its elements
// are (see the header).
#include "sumo/net_source.hpp"

#include <algorithm>
#include <cstring>
#include <utility>

namespace signalsim::sumo {
namespace {

std::string_view id_of(pugi::xml_node node, const char* attribute) { return node.attribute(attribute).value(); }

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
    } else {  // the document is freed: the text again, once
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

std::string_view IdStore::keep(const char* text) {
  const std::size_t n = std::strlen(text);
  if (used_ + n > size_) {
    size_ = std::max<std::size_t>(n, 1u << 16);
    blocks_.push_back(std::make_unique<char[]>(size_));
    used_ = 0;
  }
  char* at = blocks_.back().get() + used_;
  std::memcpy(at, text, n);
  used_ += n;
  return {at, n};
}

ParsedElement::ParsedElement(const std::string& text, std::size_t begin, std::size_t end) {
  // The last element's stretch runs to the end of the text: its parse stops at </net> with the
  // element complete (pugixml keeps what it parsed).
  doc_.load_buffer(text.data() + begin, end - begin, pugi::parse_default | pugi::parse_fragment, pugi::encoding_utf8);
}

// ---- NetSource -------------------------------------------------------------------------------------

NetSource::NetSource(std::string bytes, bool on_demand) : text_(std::move(bytes)) {
  parsed_ = on_demand ? doc_.load_buffer(text_.data(), text_.size()) : doc_.load_buffer_inplace(text_.data(), text_.size());
  if (parsed_) root_ = doc_.document_element();
}

void NetSource::drop_document() {
  lights_and_roundabouts.clear();
  root_ = {};
  doc_.reset();
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

void NetSource::add(Kind kind, ElementGroup& group, pugi::xml_node node) {
  const auto index = static_cast<std::uint32_t>(elements_.size());
  Element e;
  e.begin = static_cast<std::size_t>(node.offset_debug() - 1);  // its '<'
  e.end = text_.size();  // until the next element's start is known
  e.kind = kind;
  e.group = &group;
  elements_.push_back(e);
  if (group.head == ElementGroup::kNone) group.head = index;
  else elements_[group.tail].next = index;
  group.tail = index;
}

bool NetSource::scan() {
  // Offsets are those of the text only for UTF-8 (pugixml converts other encodings first).
  if (parsed_.encoding != pugi::encoding_utf8) return false;
  // A net has an <edge> for about every 600 bytes (Bad Hersfeld 660, bologna 900): a first guess
  // (a visit of every element costs as much as the hashing it saves).
  edges.reserve(text_.size() / 600);
  // netconvert writes an edge's connections one after another: the entry of the last from-edge is kept.
  std::string_view last_from;
  EdgeEntry* last_from_entry = nullptr;
  bool previous_recorded = false;  // whether the previous child element is in elements_
  for (pugi::xml_node node = root_.first_child(); node; node = node.next_sibling()) {
    if (node.type() != pugi::node_element) continue;
    const std::ptrdiff_t at = node.offset_debug() - 1;
    if (at < 0 || text_[static_cast<std::size_t>(at)] != '<') return false;
    if (previous_recorded) elements_.back().end = static_cast<std::size_t>(at);
    const std::size_t recorded = elements_.size();
    const char* name = node.name();
    if (std::strcmp(name, "edge") == 0) {
      const char* id = node.attribute("id").value();
      if (*id == '\0') {
        add(Kind::Edge, edges_without_id, node);
      } else {
        auto entry = edges.find(id);
        if (entry == edges.end()) entry = edges.try_emplace(ids_.keep(id)).first;
        ElementGroup& group = entry->second.edge;
        const bool first = group.head == ElementGroup::kNone;
        add(Kind::Edge, group, node);
        if (first) {  // a repeated edge is ignored whole, its lanes too
          ++edge_count;
          for (pugi::xml_node lane : node.children("lane")) {
            const std::string_view lane_id = id_of(lane, "id");
            if (!lane_id.empty() && !names_edge(lane_id, entry->first))
              lanes_elsewhere_[ids_.keep(lane_id.data())].add(entry->first);
          }
        }
      }
    } else if (std::strcmp(name, "connection") == 0) {
      const char* from = node.attribute("from").value();
      if (*from == '\0') {
        add(Kind::Connection, connections_without_from, node);
      } else {
        if (last_from_entry == nullptr || last_from != from) {
          auto entry = edges.find(from);
          if (entry == edges.end()) entry = edges.try_emplace(ids_.keep(from)).first;
          last_from = entry->first;
          last_from_entry = &entry->second;
        }
        add(Kind::Connection, last_from_entry->connections, node);
        if (const char* via = node.attribute("via").value(); *via != '\0') {
          const std::string_view kept = ids_.keep(via);
          via_list(kept, true)->add(kept, last_from);
        }
      }
    } else if (std::strcmp(name, "junction") == 0) {
      const char* id = node.attribute("id").value();
      if (*id == '\0') {
        add(Kind::Junction, junctions_without_id, node);
      } else {
        auto entry = junctions.find(id);
        if (entry == junctions.end()) entry = junctions.try_emplace(ids_.keep(id)).first;
        add(Kind::Junction, entry->second, node);
      }
    } else if (std::strcmp(name, "tlLogic") == 0 || std::strcmp(name, "roundabout") == 0) {
      lights_and_roundabouts.push_back(node);
    }
    previous_recorded = elements_.size() > recorded;
  }
  return true;
}

}  // namespace signalsim::sumo
