// The law's verdicts on a run (docs/outputs.md "law", docs/decider.md "Outputs"): whatever decided the
// blinker and the lights (the reference or a system under test), the run is judged by the rules of
// docs/behaviour.md alone. The rules are law/'s, the same that write `signalsim generate`'s
// expectations (law/expectation_rules.hpp), fed with the route's sections (from the RouteMap and the
// run's maneuvers) and the run's recorded speeds (law/recorded_speed.hpp) instead of a prediction:
//
//   per section that asks for left or right (turn, roundabout entry / exit, a lane change the run
//   approved), over the stretch where its blinker is guaranteed:
//     lead        the section's blinker with the front from `lead` m before its start to its start
//     through     the section's blinker from its start until base_link leaves it (its desired end)
//     on          the section's blinker over the stretch, when the stretch does not cover the section
//     wrong_side  no step in the stretch shows the other side (or the hazard lights)
//     flicker     no change of the blinker in the stretch
//   off           no blinker where no rule can ask for one (at least `straight` m, after the desired
//                 end of the section named, or "route" "start" before the first one)
//   never_left / never_right / never_hazard   a side no section of the route asks for
//   per light on the route: red   the front never crossed its stop line while the ego's link showed red
//
// A stretch the run never drove gives no verdict. Runs SUMO drove (`run --driver sumo`) have none.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "map/route_map.hpp"
#include "report/timeline.hpp"
#include "scenario/scenario.hpp"

namespace signalsim {

struct LawVerdict {
  std::string section;  ///< "turn", "roundabout_entry", "roundabout_exit", "lane_change", "route", "light"
  std::string id;       ///< junction id, edge id (lane change), light id; "" for route-wide rules
  std::string rule;     ///< lead, through, on, wrong_side, flicker, off, never_<side>, red
  bool passed = true;
  std::string detail;   ///< what held, or the first step that broke it
};

/// Every verdict of the run, sections in route order, then the route-wide ones, then the lights.
std::vector<LawVerdict> law_verdicts(const Scenario& scenario, const RouteMap& route, const RunRecord& record);

/// How many verdicts failed.
int law_failed(const std::vector<LawVerdict>& verdicts);

/// summary.json's "law": {"failed": n, "verdicts": [{section, id, rule, passed, detail}]}; null for
/// a run SUMO drove.
nlohmann::ordered_json law_json(const RunRecord& record, const std::vector<LawVerdict>& verdicts);

}  // namespace signalsim
