// libFuzzer target: NetIndex::load (src/sumo/net_loading, net_xml_reading) on arbitrary bytes as a
// .net.xml, then every lookup of the index and, for the first connections of the net, the route
// builder and the approach lights on two-edge routes. Documented failures: NetError from load,
// RouteError (NetDefectError) from build_route. Anything else is a finding.
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_common.hpp"
#include "sumo/approach_lights.hpp"
#include "sumo/net_index.hpp"
#include "sumo/route_builder.hpp"

using namespace signalsim::sumo;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = signalsim::fuzz::write_file(signalsim::fuzz::work_dir() / "fuzz.net.xml", data, size);
  std::optional<NetIndex> loaded;
  try {
    loaded.emplace(NetIndex::load(path));
  } catch (const NetError&) {
    return 0;
  }
  const NetIndex& net = *loaded;
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
