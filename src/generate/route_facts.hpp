// What the rules need to know about one planned route beyond its lanelets, read from the net once
// per route: its lights (stop lines, cycle times), the links where SUMO makes the ego yield, and the
// lane changes its lane plan needs (scenario/route_planning's lateral plan).
#pragma once

#include <string>
#include <vector>

#include "law/expectation_rules.hpp"
#include "law/sections.hpp"
#include "law/speed_profile.hpp"
#include "step/route_planning.hpp"
#include "net/net_index.hpp"

namespace signalsim::generate {
using namespace law;  // the rules: sections, speeds, expectations (src/law)

struct PlannedRouteFacts {
  std::vector<LightFact> lights;            ///< signalised approaches, route order
  std::vector<double> light_cycles;         ///< [s] the net's program cycle of each light (same order)
  /// Where the ego may stop, without braking distances (SpeedProfile's StopPoint::braking is set
  /// from the planned speed later): every light's stop line, and every link of the route SUMO gives
  /// no right of way (minor m, equal =, stop s, all-way stop w, zipper Z, off o/O, or a light on an
  /// internal link), at the end of the lanelet it leaves.
  struct Stop {
    double s = 0.0;
    bool light = false;
    std::string what;
  };
  std::vector<Stop> stops;
  std::vector<LaneChangeFact> lane_changes;
  /// Lights whose program never shows the route's link green (G, g, s) nor off (o, O): the ego would
  /// wait there forever, as SUMO's own vehicles do ("<tls> link <index>"). SUMO runs the program
  /// loaded last for an id, so that one is read.
  std::vector<std::string> never_green;
};

PlannedRouteFacts route_facts(const sumo::RoutePlan& plan, const LateralPlan& lateral, const sumo::NetIndex& net);

}  // namespace signalsim::generate
