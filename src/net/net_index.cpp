// NetIndex lookups and lane permissions. Loading is in net_loading.cpp, reading on demand in
// net_on_demand.cpp: each lookup reads what its answer depends on, then looks it up.
#include "net/net_index.hpp"

#include <sstream>

#include "net/net_data.hpp"

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

/// `find()` after `read()` (under the lock, unless the whole net is read already).
template <typename Read, typename Find>
auto look_up(NetData& net, Read&& read, Find&& find) {
  if (net.whole.load(std::memory_order_acquire)) return find();
  std::lock_guard lock(net.reading);
  if (net.source) read();
  return find();
}

/// The whole net read (for the whole-net queries).
NetData& whole(NetData& net) {
  if (!net.whole.load(std::memory_order_acquire)) {
    std::lock_guard lock(net.reading);
    if (net.source) net.read_whole_net();
  }
  return net;
}

}  // namespace

std::string defect_key(NetElement kind, const std::string& id) {
  return std::to_string(static_cast<int>(kind)) + ":" + id;
}

NetIndex::NetIndex() : data_(std::make_unique<NetData>()) { data_->whole = true; }
NetIndex::NetIndex(NetIndex&&) noexcept = default;
NetIndex& NetIndex::operator=(NetIndex&&) noexcept = default;
NetIndex::~NetIndex() = default;

const std::string& NetIndex::path() const { return data_->path; }
bool NetIndex::lefthand() const { return data_->lefthand; }
std::size_t NetIndex::edge_count() const { return data_->edge_count; }
const std::vector<NetRoundabout>& NetIndex::roundabouts() const { return data_->roundabouts; }
const std::vector<NetTlLogic>& NetIndex::tl_logics() const { return data_->tl_logics; }

const std::vector<std::reference_wrapper<const NetEdge>>& NetIndex::edges() const {
  return whole(*data_).edges_in_file_order;
}

const std::vector<NetDefect>& NetIndex::defects() const { return whole(*data_).defects_in_file_order; }

const NetDefect* NetIndex::defect(NetElement kind, const std::string& id) const {
  NetData& net = *data_;
  return look_up(net, [&] { net.read_defects_of(kind, id); }, [&] { return net.log.first_against(kind, id); });
}

const NetEdge* NetIndex::edge(const std::string& id) const {
  NetData& net = *data_;
  return look_up(net, [&] { net.read_edge(id); }, [&]() -> const NetEdge* {
    auto it = net.edge_by_id.find(id);
    return it == net.edge_by_id.end() ? nullptr : &net.edges[it->second];
  });
}

const NetLane* NetIndex::lane(const std::string& id) const {
  NetData& net = *data_;
  return look_up(net, [&] { net.read_lane(id); }, [&]() -> const NetLane* {
    auto it = net.lane_by_id.find(id);
    return it == net.lane_by_id.end() ? nullptr : &net.edges[it->second.first].lanes[it->second.second];
  });
}

const NetEdge* NetIndex::edge_of_lane(const std::string& lane_id) const {
  NetData& net = *data_;
  return look_up(net, [&] { net.read_lane(lane_id); }, [&]() -> const NetEdge* {
    auto it = net.lane_by_id.find(lane_id);
    return it == net.lane_by_id.end() ? nullptr : &net.edges[it->second.first];
  });
}

const NetJunction* NetIndex::junction(const std::string& id) const {
  NetData& net = *data_;
  return look_up(net, [&] { net.read_junction(id); }, [&]() -> const NetJunction* {
    auto it = net.junctions.find(id);
    return it == net.junctions.end() ? nullptr : &it->second;
  });
}

const std::vector<NetConnection>& NetIndex::connections_from_lane(const std::string& lane_id) const {
  NetData& net = *data_;
  return *look_up(net, [&] { net.read_connections_from_lane(lane_id); }, [&]() -> const std::vector<NetConnection>* {
    auto it = net.connections_by_from_lane.find(lane_id);
    return it == net.connections_by_from_lane.end() ? &kNoConnections : &it->second;
  });
}

const NetConnection* NetIndex::connection_via(const std::string& internal_lane_id) const {
  NetData& net = *data_;
  return look_up(net, [&] { net.read_connections_via(internal_lane_id); }, [&]() -> const NetConnection* {
    auto it = net.connection_by_via.find(internal_lane_id);
    return it == net.connection_by_via.end() ? nullptr : &it->second.second;
  });
}

std::optional<std::size_t> NetIndex::roundabout_of_edge(const std::string& edge_id) const {
  auto it = data_->roundabout_by_edge.find(edge_id);
  if (it == data_->roundabout_by_edge.end()) return std::nullopt;
  return it->second;
}

const NetTlLogic* NetIndex::tl_logic(const std::string& id) const {
  auto it = data_->tl_logic_by_id.find(id);
  return it == data_->tl_logic_by_id.end() ? nullptr : &data_->tl_logics[it->second];
}

}  // namespace signalsim::sumo
