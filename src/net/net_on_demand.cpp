// Reading a net's elements on demand (net_index.hpp): what one lookup must read so that its answer,
// and every defect it could return, is what reading the whole file in order gives.
//
// Reading in file order decides three things, kept here whatever order the lookups come in:
//   - of edges with one id, the first is the edge and the later ones are defects: an id's edges
//     are read together, in file order;
//   - of lanes with one id (on different edges), the first is the lane and the later ones are
//     defects: before an edge is read, every earlier edge defining one of its lane ids is;
//   - of connections through one internal lane, connection_via gives the first in the file
//     (NetLoader::connection keeps the lowest offset).
// A defect is recorded against its element (net_loading.cpp): an edge's come from its <edge>
// elements and from connections from it whose `fromLane` is no integer; a lane's from the edges
// defining it and the connections from it; a junction's from its <junction>s; a light's are read
// at load.
#include <algorithm>
#include <charconv>

#include "net/net_data.hpp"
#include "net/net_loader.hpp"

namespace signalsim::sumo {
namespace {

template <typename F>
void read_group(NetData& net, ElementGroup& group, F&& read_element) {
  if (group.read || group.head == ElementGroup::kNone) return;
  group.read = true;
  net.source->each_element(group, [&](pugi::xml_node node, std::ptrdiff_t base) {
    net.log.set_fragment_base(base);
    read_element(node);
  });
  net.log.set_fragment_base(0);
}

/// The from-edge of a from-lane id "<from>_<fromLane>": the text before the last '_', when the
/// rest is an integer as std::to_string writes it (how NetLoader::connection makes the key).
std::optional<std::string> from_edge_of(const std::string& lane_id) {
  const std::size_t cut = lane_id.rfind('_');
  if (cut == std::string::npos) return std::nullopt;
  const std::string_view index(lane_id.data() + cut + 1, lane_id.size() - cut - 1);
  int value = 0;
  const auto [end, error] = std::from_chars(index.data(), index.data() + index.size(), value);
  if (error != std::errc{} || end != index.data() + index.size() || std::to_string(value) != index) return std::nullopt;
  return lane_id.substr(0, cut);
}

}  // namespace

void NetData::read_edge(const std::string& id) {
  NetSource& src = *source;
  EdgeEntry* found = src.edge_entry(id);
  if (found == nullptr || found->edge.read) return;
  // The edges to read: this one and, transitively, every earlier unread edge sharing a lane id.
  std::vector<std::pair<std::ptrdiff_t, ElementGroup*>> todo{{src.offset_of(found->edge), &found->edge}};
  for (std::size_t k = 0; k < todo.size(); ++k) {
    const std::ptrdiff_t offset = todo[k].first;
    const ElementGroup* group = todo[k].second;
    for (const std::string& lane_id : src.lane_ids(*group)) {
      src.each_edge_defining(lane_id, [&](std::string_view other) {
        ElementGroup& g = src.edge_entry(other)->edge;
        const std::ptrdiff_t at = src.offset_of(g);
        const bool listed = std::any_of(todo.begin(), todo.end(), [&](const auto& t) { return t.second == &g; });
        if (!g.read && at < offset && !listed) todo.emplace_back(at, &g);
      });
    }
  }
  std::sort(todo.begin(), todo.end());
  NetLoader loader(*this);
  for (const auto& [offset, group] : todo)
    read_group(*this, *group, [&](pugi::xml_node node) { loader.edge(node); });
}

void NetData::read_lane(const std::string& id) {
  std::vector<std::string> edge_ids;
  source->each_edge_defining(id, [&](std::string_view edge_id) { edge_ids.emplace_back(edge_id); });
  for (const std::string& edge_id : edge_ids) read_edge(edge_id);
}

void NetData::read_junction(const std::string& id) {
  const auto found = source->junctions.find(id);
  if (found == source->junctions.end()) return;
  NetLoader loader(*this);
  read_group(*this, found->second, [&](pugi::xml_node node) { loader.junction(node); });
}

void NetData::read_connections_from_edge(const std::string& edge_id) {
  ElementGroup* group = source->connections_from(edge_id);
  if (group == nullptr) return;
  NetLoader loader(*this);
  read_group(*this, *group, [&](pugi::xml_node node) { loader.connection(node); });
}

void NetData::read_connections_from_lane(const std::string& lane_id) {
  if (const auto edge_id = from_edge_of(lane_id)) read_connections_from_edge(*edge_id);
}

void NetData::read_connections_via(const std::string& lane_id) {
  std::vector<std::string> from_edges;
  source->each_from_edge_via(lane_id, [&](std::string_view edge_id) { from_edges.emplace_back(edge_id); });
  for (const std::string& edge_id : from_edges) read_connections_from_edge(edge_id);
}

void NetData::read_defects_of(NetElement kind, const std::string& id) {
  switch (kind) {
    case NetElement::Edge:
      read_edge(id);
      read_connections_from_edge(id);  // those whose fromLane is no integer
      break;
    case NetElement::Lane:
      read_lane(id);
      read_connections_from_lane(id);
      break;
    case NetElement::Junction: read_junction(id); break;
    case NetElement::TlLogic: break;  // read at load
  }
}

void NetData::read_whole_net() {
  // In file order, every earlier edge is read before an edge: read_edge's search is not needed.
  NetLoader loader(*this);
  source->each_element_group([&](NetSource::Kind kind, ElementGroup& group) {
    switch (kind) {
      case NetSource::Kind::Edge: read_group(*this, group, [&](pugi::xml_node node) { loader.edge(node); }); break;
      case NetSource::Kind::Junction: read_group(*this, group, [&](pugi::xml_node node) { loader.junction(node); }); break;
      case NetSource::Kind::Connection:
        read_group(*this, group, [&](pugi::xml_node node) { loader.connection(node); });
        break;
    }
  });

  finish_whole_net();
}

void NetData::finish_whole_net() {
  std::vector<std::size_t> order(edges.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return edge_offsets[a] < edge_offsets[b]; });
  edges_in_file_order.clear();
  for (std::size_t i : order) edges_in_file_order.emplace_back(edges[i]);
  defects_in_file_order = log.in_file_order();
  log.seal();
  source.reset();  // nothing left to read: the text's memory goes
  whole.store(true, std::memory_order_release);
}

}  // namespace signalsim::sumo
