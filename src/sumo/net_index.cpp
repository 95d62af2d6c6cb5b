// Reads a SUMO 1.15 .net.xml into a NetIndex (spec SUMO §2: roundabouts, junction types and
// <stopOffset> have no libsumo API, so the file is read directly).
//
// Elements read (children of <net>): <edge> with its <lane>s, <param>s and <stopOffset>s; <junction>;
// <connection>; <roundabout>; <tlLogic> with its <phase>s. Everything else (<location>, <type>,
// <request>, <neigh>, ...) is skipped. <location> is irrelevant: signalsim works in net coordinates.
#include "sumo/net_index.hpp"

#include <sstream>

#include <pugixml.hpp>

#include <algorithm>
#include <cstring>
#include <utility>

#include "sumo/net_file.hpp"
#include "sumo/net_xml_reading.hpp"

namespace signalsim::sumo {
namespace {

bool lists_class(const std::string& classes, const std::string& wanted) {
  std::istringstream words(classes);
  for (std::string w; words >> w;)
    if (w == wanted || w == "all") return true;
  return false;
}

}  // namespace

// SUMO lane permissions: `allow` lists the classes that may use the lane, else `disallow` those
// that may not; neither means everyone.
bool passenger_allowed(const std::string& allow, const std::string& disallow) {
  if (!allow.empty()) return lists_class(allow, "passenger");
  if (!disallow.empty()) return !lists_class(disallow, "passenger");
  return true;
}

namespace {

const std::vector<NetConnection> kNoConnections;

bool is(pugi::xml_node node, const char* name) { return std::strcmp(node.name(), name) == 0; }

std::map<std::string, std::string> read_params(const std::string& path, pugi::xml_node parent,
                                               const std::string& owner) {
  std::map<std::string, std::string> params;
  for (pugi::xml_node p : parent.children("param")) {
    const XmlElement param(path, p, owner + " <param>");
    params[param.required_text("key")] = param.text("value");
  }
  return params;
}

/// The `value` of the first <stopOffset> child, if any. Its vClasses/exceptions filters are ignored:
/// signalsim drives a passenger car, and netconvert writes vClasses="all" unless told otherwise.
std::optional<double> read_stop_offset(const std::string& path, pugi::xml_node parent, const std::string& owner) {
  const pugi::xml_node s = parent.child("stopOffset");
  if (!s) return std::nullopt;
  return XmlElement(path, s, owner + " <stopOffset>").required_number("value");
}

char read_dir(const std::string& dir) {
  if (dir.size() == 1) return dir.front();  // s t T l r L R
  return 'i';                                // "invalid" (and anything unknown)
}

}  // namespace

NetIndex NetIndex::load(const std::string& path) {
  // The buffer must outlive the document (parsed in place).
  std::string bytes = read_net_file(path);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer_inplace(bytes.data(), bytes.size());
  if (!parsed) {
    throw NetError(path + ": not XML: " + parsed.description() + " at offset " + std::to_string(parsed.offset));
  }
  const pugi::xml_node root = doc.document_element();
  if (!is(root, "net")) {
    throw NetError(path + ": no <net> root element (found <" + std::string(root.name()) + ">)");
  }

  NetIndex net;
  net.path_ = path;
  net.lefthand_ = XmlElement(path, root, "<net>").boolean("lefthand", false);

  for (pugi::xml_node node : root.children()) {
    if (node.type() != pugi::node_element) continue;

    if (is(node, "edge")) {
      const XmlElement e(path, node, describe("edge", node.attribute("id").value()));
      NetEdge edge;
      edge.id = e.required_text("id");
      edge.is_internal = e.text("function") == "internal";
      edge.from_junction = e.text("from");
      edge.to_junction = e.text("to");
      const std::string what = describe("edge", edge.id);
      edge.params = read_params(path, node, what);
      edge.stop_offset = read_stop_offset(path, node, what).value_or(0.0);
      for (pugi::xml_node lane_node : node.children("lane")) {
        const XmlElement l(path, lane_node, describe("lane", lane_node.attribute("id").value()));
        NetLane lane;
        lane.id = l.required_text("id");
        lane.index = l.required_integer("index");
        lane.speed = l.number("speed", lane.speed);
        lane.length = l.required_number("length");
        lane.width = l.number("width", lane.width);
        lane.shape = l.shape("shape");
        lane.allows_passenger = passenger_allowed(l.text("allow"), l.text("disallow"));
        const std::string lane_what = describe("lane", lane.id);
        lane.params = read_params(path, lane_node, lane_what);
        lane.stop_offset = read_stop_offset(path, lane_node, lane_what).value_or(edge.stop_offset);
        edge.lanes.push_back(std::move(lane));
      }
      std::sort(edge.lanes.begin(), edge.lanes.end(),
                [](const NetLane& a, const NetLane& b) { return a.index < b.index; });
      for (std::size_t i = 0; i < edge.lanes.size(); ++i) {
        if (edge.lanes[i].index != static_cast<int>(i)) {
          e.fail("lane indices are not 0.." + std::to_string(edge.lanes.size() - 1) + " (lane '" +
                 edge.lanes[i].id + "' has index " + std::to_string(edge.lanes[i].index) + ")");
        }
      }
      const std::size_t edge_pos = net.edges_.size();
      if (!net.edge_by_id_.emplace(edge.id, edge_pos).second) e.fail("duplicate edge id");
      for (std::size_t i = 0; i < edge.lanes.size(); ++i) {
        if (!net.lane_by_id_.emplace(edge.lanes[i].id, std::make_pair(edge_pos, i)).second) {
          throw NetError(path + ": " + describe("lane", edge.lanes[i].id) + ": duplicate lane id");
        }
      }
      net.edges_.push_back(std::move(edge));

    } else if (is(node, "junction")) {
      const XmlElement j(path, node, describe("junction", node.attribute("id").value()));
      NetJunction junction;
      junction.id = j.required_text("id");
      junction.type = j.text("type");
      junction.x = j.number("x", 0.0);
      junction.y = j.number("y", 0.0);
      if (!net.junctions_.emplace(junction.id, junction).second) j.fail("duplicate junction id");

    } else if (is(node, "connection")) {
      const XmlElement c(path, node,
                         "connection '" + std::string(node.attribute("from").value()) + "' -> '" +
                             node.attribute("to").value() + "'");
      NetConnection conn;
      conn.from_edge = c.required_text("from");
      conn.to_edge = c.required_text("to");
      conn.from_lane = c.required_integer("fromLane");
      conn.to_lane = c.required_integer("toLane");
      conn.via = c.text("via");
      conn.dir = read_dir(c.text("dir", "s"));
      const std::string state = c.text("state", "M");
      conn.state = state.size() == 1 ? state.front() : 'M';
      conn.tl = c.text("tl");
      conn.link_index = c.integer("linkIndex", -1);
      if (!conn.via.empty()) net.connection_by_via_.emplace(conn.via, conn);
      net.connections_by_from_lane_[conn.from_edge + "_" + std::to_string(conn.from_lane)].push_back(
          std::move(conn));

    } else if (is(node, "roundabout")) {
      const XmlElement r(path, node, "<roundabout>");
      NetRoundabout ra;
      ra.nodes = r.list("nodes");
      ra.edges = r.list("edges");
      for (const std::string& e : ra.edges) net.roundabout_by_edge_.emplace(e, net.roundabouts_.size());
      net.roundabouts_.push_back(std::move(ra));

    } else if (is(node, "tlLogic")) {
      const XmlElement t(path, node, describe("tlLogic", node.attribute("id").value()));
      NetTlLogic logic;
      logic.id = t.required_text("id");
      logic.program_id = t.text("programID");
      logic.type = t.text("type");
      logic.offset = t.number("offset", 0.0);
      for (pugi::xml_node p : node.children("phase")) {
        const XmlElement ph(path, p, describe("tlLogic", logic.id) + " <phase>");
        logic.phases.push_back({ph.required_number("duration"), ph.required_text("state")});
      }
      // Several programs may share an id: tl_logic(id) returns the first one in the file.
      net.tl_logic_by_id_.emplace(logic.id, net.tl_logics_.size());
      net.tl_logics_.push_back(std::move(logic));
    }
  }
  return net;
}

const NetEdge* NetIndex::edge(const std::string& id) const {
  auto it = edge_by_id_.find(id);
  return it == edge_by_id_.end() ? nullptr : &edges_[it->second];
}

const NetLane* NetIndex::lane(const std::string& id) const {
  auto it = lane_by_id_.find(id);
  return it == lane_by_id_.end() ? nullptr : &edges_[it->second.first].lanes[it->second.second];
}

const NetEdge* NetIndex::edge_of_lane(const std::string& lane_id) const {
  auto it = lane_by_id_.find(lane_id);
  return it == lane_by_id_.end() ? nullptr : &edges_[it->second.first];
}

const NetJunction* NetIndex::junction(const std::string& id) const {
  auto it = junctions_.find(id);
  return it == junctions_.end() ? nullptr : &it->second;
}

const std::vector<NetConnection>& NetIndex::connections_from_lane(const std::string& lane_id) const {
  auto it = connections_by_from_lane_.find(lane_id);
  return it == connections_by_from_lane_.end() ? kNoConnections : it->second;
}

const NetConnection* NetIndex::connection_via(const std::string& internal_lane_id) const {
  auto it = connection_by_via_.find(internal_lane_id);
  return it == connection_by_via_.end() ? nullptr : &it->second;
}

std::optional<std::size_t> NetIndex::roundabout_of_edge(const std::string& edge_id) const {
  auto it = roundabout_by_edge_.find(edge_id);
  if (it == roundabout_by_edge_.end()) return std::nullopt;
  return it->second;
}

const NetTlLogic* NetIndex::tl_logic(const std::string& id) const {
  auto it = tl_logic_by_id_.find(id);
  return it == tl_logic_by_id_.end() ? nullptr : &tl_logics_[it->second];
}

}  // namespace signalsim::sumo
