// libFuzzer target: NetIndex::load (src/net/net_loading, net_xml_reading) on arbitrary bytes as a
// .net.xml, then every lookup of the index and, for the first connections of the net, the route
// builder and the approach lights on two-edge routes; an index reading on demand, asked in reverse
// file order, answers as one that read the whole net at load. Documented failures: NetError from
// load, RouteError (NetDefectError) from build_route. Anything else is a finding.
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "route/approach_lights.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"

using namespace signalsim::sumo;

namespace {

bool same_defect(const NetDefect* a, const NetDefect* b) {
  if (a == nullptr || b == nullptr) return a == b;
  return a->element == b->element && a->reason == b->reason && a->line == b->line && a->affects_routes == b->affects_routes;
}

bool same_connections(const std::vector<NetConnection>& a, const std::vector<NetConnection>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].to_edge != b[i].to_edge || a[i].to_lane != b[i].to_lane || a[i].via != b[i].via || a[i].dir != b[i].dir ||
        a[i].tl != b[i].tl || a[i].link_index != b[i].link_index)
      return false;
  return true;
}

/// `lazy` (reading on demand), asked about `whole`'s edges from the last to the first, answers as `whole`.
void check_on_demand(const NetIndex& whole, const NetIndex& lazy) {
  FUZZ_ASSERT(lazy.edge_count() == whole.edge_count());
  const auto& edges = whole.edges();
  for (auto it = edges.rbegin(); it != edges.rend(); ++it) {
    const NetEdge& e = *it;
    const NetEdge* l = lazy.edge(e.id);
    FUZZ_ASSERT(l != nullptr && l->lanes.size() == e.lanes.size() && l->from_junction == e.from_junction);
    FUZZ_ASSERT(same_defect(lazy.defect(NetElement::Edge, e.id), whole.defect(NetElement::Edge, e.id)));
    for (std::size_t i = 0; i < e.lanes.size(); ++i) {
      const std::string& id = e.lanes[i].id;
      FUZZ_ASSERT(l->lanes[i].id == id && l->lanes[i].length == e.lanes[i].length);
      FUZZ_ASSERT((lazy.lane(id) == nullptr) == (whole.lane(id) == nullptr));
      FUZZ_ASSERT(same_connections(lazy.connections_from_lane(id), whole.connections_from_lane(id)));
      FUZZ_ASSERT(same_defect(lazy.defect(NetElement::Lane, id), whole.defect(NetElement::Lane, id)));
      const NetConnection* va = lazy.connection_via(id);
      const NetConnection* vb = whole.connection_via(id);
      FUZZ_ASSERT((va == nullptr) == (vb == nullptr));
      if (va != nullptr) FUZZ_ASSERT(va->from_edge == vb->from_edge && va->from_lane == vb->from_lane);
    }
    FUZZ_ASSERT(same_defect(lazy.defect(NetElement::Junction, e.to_junction), whole.defect(NetElement::Junction, e.to_junction)));
  }
  const auto& a = lazy.defects();
  const auto& b = whole.defects();
  FUZZ_ASSERT(a.size() == b.size());
  for (std::size_t i = 0; i < a.size(); ++i) FUZZ_ASSERT(same_defect(&a[i], &b[i]));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = signalsim::fuzz::write_file(signalsim::fuzz::work_dir() / "fuzz.net.xml", data, size);
  std::optional<NetIndex> loaded, on_demand;
  try {
    loaded.emplace(NetIndex::load(path, NetReading::Whole));
  } catch (const NetError&) {
    return 0;
  }
  const NetIndex& net = *loaded;
  on_demand.emplace(NetIndex::load(path));  // it loaded once: it loads again
  check_on_demand(net, *on_demand);
  for (const NetDefect& d : net.defects()) FUZZ_ASSERT(d.line >= 1);
  std::vector<std::vector<std::string>> routes;
  for (const NetEdge& edge : net.edges()) {
    FUZZ_ASSERT(net.edge(edge.id) != nullptr);
    for (const NetLane& lane : edge.lanes) {
      // A lane without an id is kept in its edge (a defect) but cannot be looked up.
      if (!lane.id.empty()) {
        FUZZ_ASSERT(net.lane(lane.id) != nullptr);
        FUZZ_ASSERT(net.edge_of_lane(lane.id) != nullptr);
      }
      for (const NetConnection& c : net.connections_from_lane(lane.id)) {
        if (!c.via.empty()) (void)net.connection_via(c.via);
        if (!c.tl.empty()) (void)net.tl_logic(c.tl);
        (void)net.edge(c.to_edge);
        if (!edge.is_internal && routes.size() < 8) routes.push_back({c.from_edge, c.to_edge});
      }
      (void)net.defect(NetElement::Lane, lane.id);
    }
    (void)net.roundabout_of_edge(edge.id);
    (void)net.defect(NetElement::Edge, edge.id);
  }
  for (const NetRoundabout& r : net.roundabouts())
    for (const std::string& e : r.edges) {
      const auto index = net.roundabout_of_edge(e);
      FUZZ_ASSERT(index && *index < net.roundabouts().size());
    }
  for (const NetTlLogic& tl : net.tl_logics()) FUZZ_ASSERT(net.tl_logic(tl.id) != nullptr);
  for (const auto& route : routes) {
    try {
      const RoutePlan plan = build_route(net, route);
      FUZZ_ASSERT(plan.lane_per_edge.size() == route.size());
      (void)approach_lights(net, plan.map);
    } catch (const RouteError&) {
    }
  }
  return 0;
}
