// NetIndex lookups and lane permissions. Loading is in net_loading.cpp.
#include "sumo/net_index.hpp"

#include <sstream>

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
std::string sumo_cannot_drive(const NetIndex& net, const NetEdge& edge) {
  if (edge.bidi.empty()) return {};
  const NetEdge* partner = net.edge(edge.bidi);
  const std::size_t partner_lanes = partner ? partner->lanes.size() : 0;
  if (edge.lanes.size() <= 1 && partner_lanes <= 1) return {};
  return "edge '" + edge.id + "' (" + std::to_string(edge.lanes.size()) + " lanes) is bidirectional with '" +
         edge.bidi + "' (" + std::to_string(partner_lanes) +
         " lanes): SUMO 1.15 aborts on a vehicle there (assertion bidiEdge->getLanes().size() == 1 in "
         "MSLane::getBidiLane; it supports one-lane bidi edges only)";
}

bool passenger_allowed(const std::string& allow, const std::string& disallow) {
  if (!allow.empty()) return lists_class(allow, "passenger");
  if (!disallow.empty()) return !lists_class(disallow, "passenger");
  return true;
}

bool lane_permits(const NetLane& lane, const std::string& vclass) {
  if (vclass.empty() || vclass == "passenger") return lane.allows_passenger;
  if (!lane.allow.empty()) return lists_class(lane.allow, vclass);
  if (!lane.disallow.empty()) return !lists_class(lane.disallow, vclass);
  return true;
}

namespace {

const std::vector<NetConnection> kNoConnections;

}  // namespace

std::string defect_key(NetElement kind, const std::string& id) {
  return std::to_string(static_cast<int>(kind)) + ":" + id;
}

const NetDefect* NetIndex::defect(NetElement kind, const std::string& id) const {
  if (defect_by_element_.empty()) return nullptr;
  auto it = defect_by_element_.find(defect_key(kind, id));
  return it == defect_by_element_.end() ? nullptr : &defects_[it->second];
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
