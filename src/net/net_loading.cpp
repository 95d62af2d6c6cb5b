// NetIndex::load and NetLoader: reads a SUMO 1.15 .net.xml into a NetIndex (docs/behaviour.md §S2: roundabouts,
// junction types and <stopOffset> have no libsumo API, so the file is read directly).
//
// Elements read (children of <net>): <edge> with its <lane>s, <param>s and <stopOffset>s; <junction>;
// <connection>; <roundabout>; <tlLogic> with its <phase>s. Everything else (<location>, <type>,
// <request>, <neigh>, ...) is skipped. <location> is irrelevant: signalsim works in net coordinates.
// load reads <net>, the light programs and roundabouts, and scans where the other elements are
// (NetSource, without parsing the whole file); those are read when a lookup needs them
// (net_on_demand.cpp). A whole reading parses the file and reads every element at once.
//
// The loading rule (net_index.hpp): a value signalsim reads that cannot be used as written is a
// NetDefect against its element, never an exception; each element is read once, so loading stays
// linear in the file.
#include <pugixml.hpp>

#include <algorithm>
#include <cstring>
#include <unordered_map>
#include <utility>

#include "net/net_data.hpp"
#include "net/net_file.hpp"
#include "net/net_loader.hpp"
#include "net/net_xml_reading.hpp"
#include "core/number_parsing.hpp"

namespace signalsim::sumo {
namespace {

bool is(pugi::xml_node node, const char* name) { return std::strcmp(node.name(), name) == 0; }

DefectOwner owner(NetElement kind, const std::string& id) {
  if (id.empty()) return std::nullopt;
  return std::make_pair(kind, id);
}


// The `dir` values SUMO 1.15 writes (LinkDirection): s t T l r L R, and "invalid".
std::optional<char> read_dir(const std::string& dir) {
  if (dir == "invalid") return 'i';
  if (dir.size() == 1 && std::strchr("stTlrLR", dir.front()) != nullptr) return dir.front();
  return std::nullopt;
}

}  // namespace

std::map<std::string, std::string> NetLoader::params(pugi::xml_node parent, const std::string& owner_what,
                                                     const DefectOwner& owner) {
  std::map<std::string, std::string> out;
  for (pugi::xml_node p : parent.children("param")) {
    const XmlElement param(p, owner_what + " <param>", owner, log_);
    const auto key = param.required_text("key");
    if (!key) continue;
    out[*key] = param.text("value");
    // The one param signalsim reads as a number (docs/behaviour.md §T4.1: a lanelet's own search distance).
    if (*key == "turn_signal_distance" && !parse_double(out[*key]))
      log_.add(owner, owner_what, "param 'turn_signal_distance' is not a number: '" + out[*key] + "'",
               log_.fragment_base() + p.offset_debug());
  }
  return out;
}

/// The `value` of the first <stopOffset> child, if any. Its vClasses/exceptions filters are ignored:
/// signalsim drives a passenger car, and netconvert writes vClasses="all" unless told otherwise.
std::optional<double> NetLoader::stop_offset(pugi::xml_node parent, const std::string& owner_what,
                                             const DefectOwner& owner) {
  const pugi::xml_node s = parent.child("stopOffset");
  if (!s) return std::nullopt;
  return XmlElement(s, owner_what + " <stopOffset>", owner, log_).required_number("value");
}

NetLane NetLoader::lane(pugi::xml_node node, const NetEdge& edge, const DefectOwner& edge_owner) {
  NetLane lane;
  lane.id = node.attribute("id").value();
  if (lane.id.empty()) {
    XmlElement(node, describe("edge", edge.id), edge_owner, log_).defect("a <lane> has no id");
  }
  const std::string what = describe("lane", lane.id);
  const DefectOwner self = owner(NetElement::Lane, lane.id);
  const XmlElement l(node, what, self, log_);
  lane.speed = l.number("speed", lane.speed);
  lane.length = l.required_number("length").value_or(0.0);
  if (lane.length < 0.0) l.defect("attribute 'length' is negative: '" + l.text("length") + "'");
  lane.width = l.number("width", lane.width);
  if (lane.width <= 0.0) l.defect("attribute 'width' is not positive: '" + l.text("width") + "'");
  lane.shape = l.shape("shape").value_or(Polyline{});
  lane.allow = l.text("allow");
  lane.disallow = l.text("disallow");
  lane.allows_passenger = passenger_allowed(lane.allow, lane.disallow);
  if (node.first_child()) {
    lane.params = params(node, what, self);
    lane.stop_offset = stop_offset(node, what, self).value_or(edge.stop_offset);
  } else {
    lane.stop_offset = edge.stop_offset;
  }
  return lane;
}

// Lanes are used by index (a connection's fromLane/toLane, the lane plan): a normal edge's indices
// must be 0..n-1. SUMO 1.15 loads other indices (netconvert 1.22 writes two index-0 lanes on some
// internal edges); signalsim then keeps the file order, and records the defect. An internal edge's
// lanes are found by id (a connection's `via`), so there it affects no route.
// Returns the file position of the lane at each index.
std::vector<std::size_t> NetLoader::lane_order(const XmlElement& e, const NetEdge& edge,
                                               const std::vector<std::optional<int>>& indices) {
  const std::size_t n = edge.lanes.size();
  std::vector<std::size_t> at(n, n);  // at[index] = position in the file
  std::string problem;
  const auto lane = [&](std::size_t i) { return "lane '" + edge.lanes[i].id + "'"; };
  for (std::size_t i = 0; i < n && problem.empty(); ++i) {
    if (!indices[i]) problem = lane(i) + " has no integer index";
    else if (*indices[i] < 0 || static_cast<std::size_t>(*indices[i]) >= n)
      problem = lane(i) + " has index " + std::to_string(*indices[i]);
    else if (at[static_cast<std::size_t>(*indices[i])] != n)
      problem = lane(i) + " repeats index " + std::to_string(*indices[i]);
    else at[static_cast<std::size_t>(*indices[i])] = i;
  }
  if (problem.empty()) return at;
  e.defect("lane indices are not 0.." + std::to_string(n - 1) + " (" + problem + "); the file's lane order is used",
           !edge.is_internal);
  for (std::size_t i = 0; i < n; ++i) at[i] = i;
  return at;
}

void NetLoader::edge(pugi::xml_node node) {
  NetEdge edge;
  edge.id = node.attribute("id").value();
  const std::string what = describe("edge", edge.id);
  const DefectOwner self = owner(NetElement::Edge, edge.id);
  const XmlElement e(node, what, self, log_);
  if (edge.id.empty()) return e.defect("attribute 'id' is missing");
  if (net_.edge_by_id.count(edge.id) != 0) {
    return e.defect("another edge has this id; this one is ignored", true, first_.of("edge", edge.id));
  }
  edge.is_internal = e.text("function") == "internal";
  edge.from_junction = e.text("from");
  edge.to_junction = e.text("to");
  edge.bidi = e.text("bidi");
  edge.params = params(node, what, self);
  edge.stop_offset = stop_offset(node, what, self).value_or(0.0);
  std::vector<std::optional<int>> indices;
  std::vector<pugi::xml_node> nodes;
  for (pugi::xml_node lane_node : node.children("lane")) {
    indices.push_back(parse_int(lane_node.attribute("index").value()));
    nodes.push_back(lane_node);
    edge.lanes.push_back(lane(lane_node, edge, self));
  }
  // SUMO refuses a normal edge without lanes; recorded against the edge, so that a route on it names this line.
  if (edge.lanes.empty() && !edge.is_internal) e.defect("the edge has no <lane>");
  const std::vector<std::size_t> order = lane_order(e, edge, indices);
  if (!std::is_sorted(order.begin(), order.end())) {  // netconvert writes them in order
    std::vector<NetLane> lanes;
    lanes.reserve(order.size());
    for (std::size_t k : order) lanes.push_back(std::move(edge.lanes[k]));
    edge.lanes = std::move(lanes);
  }

  const std::size_t edge_pos = net_.edges.size();
  net_.edge_by_id.emplace(edge.id, edge_pos);
  for (std::size_t i = 0; i < edge.lanes.size(); ++i) {
    NetLane& lane = edge.lanes[i];
    lane.index = static_cast<int>(i);
    if (lane.id.empty()) continue;
    if (const auto [first, fresh] = net_.lane_by_id.emplace(lane.id, std::make_pair(edge_pos, i)); !fresh) {
      XmlElement(nodes[order[i]], describe("lane", lane.id), owner(NetElement::Lane, lane.id), log_)
          .defect("another lane has this id", true, first_.of("lane", lane.id));
    }
  }
  net_.edges.push_back(std::move(edge));
  net_.edge_offsets.push_back(e.offset());
}

void NetLoader::junction(pugi::xml_node node) {
  NetJunction junction;
  junction.id = node.attribute("id").value();
  const XmlElement j(node, describe("junction", junction.id), owner(NetElement::Junction, junction.id), log_);
  if (junction.id.empty()) return j.defect("attribute 'id' is missing");
  junction.type = j.text("type");
  junction.x = j.number("x", 0.0);
  junction.y = j.number("y", 0.0);
  if (net_.junctions.count(junction.id) != 0) {
    return j.defect("another junction has this id; this one is ignored", true,
                    first_.of("junction", junction.id));
  }
  net_.junctions.emplace(junction.id, std::move(junction));
}

// A connection's defects go against its from-lane: a route reads every connection leaving the
// lanes it drives (successor turn directions, approach lights). Without a usable from-lane, against
// the from-edge.
void NetLoader::connection(pugi::xml_node node) {
  const std::string from = node.attribute("from").value();
  const std::string to = node.attribute("to").value();
  const auto from_lane = parse_int(node.attribute("fromLane").value());
  const DefectOwner against = from.empty()  ? DefectOwner{}
                              : from_lane   ? owner(NetElement::Lane, from + "_" + std::to_string(*from_lane))
                                            : owner(NetElement::Edge, from);
  const XmlElement c(node, "connection '" + from + "' -> '" + to + "'", against, log_);
  NetConnection conn;
  const auto from_edge = c.required_text("from");
  const auto to_edge = c.required_text("to");
  const auto from_index = c.required_integer("fromLane");
  const auto to_index = c.required_integer("toLane");
  if (!from_edge || !to_edge || !from_index || !to_index) return;  // unusable: recorded above
  conn.from_edge = *from_edge;
  conn.to_edge = *to_edge;
  conn.from_lane = *from_index;
  conn.to_lane = *to_index;
  conn.via = c.text("via");
  if (const auto dir = c.required_text("dir")) {
    const auto known = read_dir(*dir);
    if (!known) c.defect("attribute 'dir' is not a SUMO link direction (s t T l r L R invalid): '" + *dir + "'");
    conn.dir = known.value_or('i');
  }
  const std::string state = c.text("state", "M");  // not read by signalsim
  conn.state = state.size() == 1 ? state.front() : 'M';
  conn.tl = c.text("tl");
  if (const char* link = node.attribute("linkIndex").value(); *link != '\0') {
    // SUMO 1.15 loads any linkIndex; signalsim reads it only with a light.
    if (const auto index = parse_int(link)) conn.link_index = *index;
    else c.defect(std::string("attribute 'linkIndex' is not an integer: '") + link + "'", !conn.tl.empty());
  }
  if (!conn.via.empty()) {
    // The first in the file: connections may be read out of file order (on demand).
    const auto [it, fresh] = net_.connection_by_via.try_emplace(conn.via, c.offset(), conn);
    if (!fresh && c.offset() < it->second.first) it->second = {c.offset(), conn};
  }
  net_.connections_by_from_lane[conn.from_edge + "_" + std::to_string(conn.from_lane)].push_back(std::move(conn));
}

void NetLoader::roundabout(pugi::xml_node node) {
  const XmlElement r(node, "<roundabout>", std::nullopt, log_);
  NetRoundabout ra;
  ra.nodes = r.list("nodes");
  ra.edges = r.list("edges");
  if (ra.edges.empty()) return r.defect("attribute 'edges' is missing");
  for (const std::string& e : ra.edges) net_.roundabout_by_edge.emplace(e, net_.roundabouts.size());
  net_.roundabouts.push_back(std::move(ra));
}

void NetLoader::tl_logic(pugi::xml_node node) {
  NetTlLogic logic;
  logic.id = node.attribute("id").value();
  const std::string what = describe("tlLogic", logic.id);
  const XmlElement t(node, what, owner(NetElement::TlLogic, logic.id), log_);
  if (logic.id.empty()) return t.defect("attribute 'id' is missing");
  logic.program_id = t.text("programID");
  logic.type = t.text("type");
  logic.offset = t.number("offset", 0.0);
  for (pugi::xml_node p : node.children("phase")) {
    const XmlElement ph(p, what + " <phase>", owner(NetElement::TlLogic, logic.id), log_);
    const auto duration = ph.required_number("duration");
    const auto state = ph.required_text("state");
    logic.phases.push_back({duration.value_or(0.0), state.value_or("")});
  }
  if (net_.tl_logic_by_id.count(logic.id) != 0) {
    // Several programs may share an id, not an id and a programID.
    const std::ptrdiff_t first = first_.of("tlLogic", logic.id + "\n" + logic.program_id);
    if (first != t.offset()) {
      return t.defect("another tlLogic has this id and programID '" + logic.program_id + "'; this one is ignored",
                      true, first);
    }
  }
  // Several programs may share an id: tl_logic(id) returns the first one in the file.
  net_.tl_logic_by_id.emplace(logic.id, net_.tl_logics.size());
  net_.tl_logics.push_back(std::move(logic));
}

namespace {

// `line`: the root element's line in the file.
void read_root(const std::string& path, std::string_view name, const std::optional<std::string>& lefthand, int line,
               NetData& net) {
  const std::string at = path + ":" + std::to_string(line) + ": ";
  if (name != "net") throw NetError(at + "no <net> root element (found <" + std::string(name) + ">)");
  net.path = path;
  // The driving side changes every route: a value that is not a boolean is fatal (as in SUMO).
  if (lefthand) {
    const auto value = parse_sumo_bool(*lefthand);
    if (!value) throw NetError(at + "<net>: attribute 'lefthand' is not a boolean: '" + *lefthand + "'");
    net.lefthand = *value;
  }
}

// The 1-based line of byte `offset`, given the offsets of the text's newlines.
int line_of_offset(const std::vector<std::size_t>& newlines, std::ptrdiff_t offset) {
  const auto at = static_cast<std::size_t>(std::max<std::ptrdiff_t>(offset, 0));
  return 1 + static_cast<int>(std::lower_bound(newlines.begin(), newlines.end(), at) - newlines.begin());
}

}  // namespace

NetIndex NetIndex::load(const std::string& path, NetReading reading) {
  // Every element read at load from the document, in file order.
  const auto load_whole = [&path](std::string text) {
    // For the defects' lines: parsing in place overwrites some characters (ends of names and values),
    // so the newlines are found first.
    std::vector<std::size_t> newlines = newline_offsets(text);
    auto source = std::make_unique<NetSource>(std::move(text));
    if (const pugi::xml_parse_result parsed = source->parse_in_place(); !parsed) {
      throw NetError(path + ":" + std::to_string(line_of_offset(newlines, parsed.offset)) + ": not XML: " +
                     parsed.description());
    }
    const pugi::xml_node root = source->root();
    std::optional<std::string> lefthand;
    if (const pugi::xml_attribute a = root.attribute("lefthand")) lefthand = a.value();
    NetIndex index;
    NetData& net = *index.data_;
    read_root(path, root.name(), lefthand, line_of_offset(newlines, root.offset_debug()), net);
    net.log = DefectLog(std::move(newlines));
    net.source = std::move(source);
    NetLoader loader(net);
    for (pugi::xml_node node : root.children()) {
      if (node.type() != pugi::node_element) continue;
      if (is(node, "edge")) loader.edge(node);
      else if (is(node, "junction")) loader.junction(node);
      else if (is(node, "connection")) loader.connection(node);
      else if (is(node, "roundabout")) loader.roundabout(node);
      else if (is(node, "tlLogic")) loader.tl_logic(node);
    }
    net.edge_count = net.edge_by_id.size();
    net.finish_whole_net();
    return index;
  };
  std::string bytes = read_net_file(path);
  if (reading == NetReading::Whole) return load_whole(std::move(bytes));
  auto source = std::make_unique<NetSource>(std::move(bytes));
  // A text the tag scan does not read exactly: pugixml's parse, and its description of an error.
  if (!source->scan()) return load_whole(std::move(*source).take_text());
  NetIndex index;
  NetData& net = *index.data_;
  const std::string& text = source->text();
  const auto before_root = text.begin() + static_cast<std::ptrdiff_t>(std::min(source->root_offset, text.size()));
  read_root(path, source->root_name, source->root_lefthand, 1 + static_cast<int>(std::count(text.begin(), before_root, '\n')),
            net);
  net.log = DefectLog(&source->text());
  net.source = std::move(source);
  // Few and read whole by their users (approach lights, generate): read now.
  NetLoader loader(net);
  net.source->each_light_or_roundabout([&](pugi::xml_node node, std::ptrdiff_t base) {
    net.log.set_fragment_base(base);
    if (is(node, "roundabout")) loader.roundabout(node);
    else loader.tl_logic(node);
  });
  net.log.set_fragment_base(0);
  net.edge_count = net.source->edge_count;
  net.whole = false;
  return index;
}

}  // namespace signalsim::sumo
