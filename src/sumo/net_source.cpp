// NetSource: the parsed net document and the scan of where its elements are (see the header).
#include "sumo/net_source.hpp"

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

std::ptrdiff_t FirstDefinitions::of(pugi::xml_node root, const std::string& kind, const std::string& key) {
  if (!built_) build(root);
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

void IdList::add(std::string_view id) {
  if (first.empty()) {
    first = id;
    return;
  }
  if ((more.empty() ? first : more.back()) != id) more.push_back(id);
}

NetSource::NetSource(std::string bytes) : bytes_(std::move(bytes)) {
  parsed_ = doc_.load_buffer_inplace(bytes_.data(), bytes_.size());
  if (parsed_) root_ = doc_.document_element();
}

void NetSource::add(Kind kind, ElementGroup& group, pugi::xml_node node) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(node);
  next_.push_back(ElementGroup::kNone);
  kind_.push_back(kind);
  group_of_.push_back(&group);
  if (group.head == ElementGroup::kNone) group.head = index;
  else next_[group.tail] = index;
  group.tail = index;
}

void ViaList::add(std::string_view lane, std::string_view from_edge) {
  if (first.lane.empty()) {
    first = {lane, from_edge};
    return;
  }
  const Via& last = more.empty() ? first : more.back();
  if (last.lane != lane || last.from_edge != from_edge) more.push_back({lane, from_edge});
}

EdgeEntry* NetSource::edge_entry(std::string_view id) {
  const auto it = edges.find(id);
  return it == edges.end() || it->second.edge.head == ElementGroup::kNone ? nullptr : &it->second;
}

ElementGroup* NetSource::connections_from(std::string_view edge_id) {
  const auto it = edges.find(edge_id);
  return it == edges.end() ? nullptr : &it->second.connections;
}

std::string_view NetSource::edge_named_by(std::string_view lane_id) {
  const std::size_t cut = lane_id.rfind('_');
  if (cut == std::string_view::npos) return {};
  const auto edge = edges.find(lane_id.substr(0, cut));
  if (edge == edges.end() || edge->second.edge.head == ElementGroup::kNone) return {};
  for (pugi::xml_node lane : head_node(edge->second.edge).children("lane"))
    if (id_of(lane, "id") == lane_id) return edge->first;
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

void NetSource::scan() {
  // A net has an <edge> for about every 600 bytes (Bad Hersfeld 660, bologna 900): a first guess
  // (a visit of every element costs as much as the hashing it saves).
  edges.reserve(bytes_.size() / 600);
  // netconvert writes an edge's connections one after another: the entry of the last from-edge is kept.
  std::string_view last_from;
  EdgeEntry* last_from_entry = nullptr;
  for (pugi::xml_node node = root_.first_child(); node; node = node.next_sibling()) {
    if (node.type() != pugi::node_element) continue;
    const char* name = node.name();
    if (std::strcmp(name, "edge") == 0) {
      const std::string_view id = id_of(node, "id");
      if (id.empty()) {
        add(Kind::Edge, edges_without_id, node);
        continue;
      }
      const auto entry = edges.try_emplace(id).first;
      ElementGroup& group = entry->second.edge;
      const bool first = group.head == ElementGroup::kNone;
      add(Kind::Edge, group, node);
      if (!first) continue;  // a repeated edge is ignored whole, its lanes too
      ++edge_count;
      for (pugi::xml_node lane : node.children("lane")) {
        const std::string_view lane_id = id_of(lane, "id");
        if (!lane_id.empty() && !names_edge(lane_id, id)) lanes_elsewhere_[lane_id].add(entry->first);
      }
    } else if (std::strcmp(name, "connection") == 0) {
      const std::string_view from = id_of(node, "from");
      if (from.empty()) {
        add(Kind::Connection, connections_without_from, node);
        continue;
      }
      if (last_from_entry == nullptr || from != last_from) {
        const auto entry = edges.try_emplace(from).first;
        last_from = entry->first;
        last_from_entry = &entry->second;
      }
      add(Kind::Connection, last_from_entry->connections, node);
      if (const std::string_view via = id_of(node, "via"); !via.empty()) via_list(via, true)->add(via, last_from);
    } else if (std::strcmp(name, "junction") == 0) {
      const std::string_view id = id_of(node, "id");
      add(Kind::Junction, id.empty() ? junctions_without_id : junctions[id], node);
    } else if (std::strcmp(name, "tlLogic") == 0 || std::strcmp(name, "roundabout") == 0) {
      lights_and_roundabouts.push_back(node);
    }
  }
}

}  // namespace signalsim::sumo
