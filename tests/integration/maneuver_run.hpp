// One bundled maneuver scenario run on the real libsumo through run_scenario, with its lateral plan:
// what the maneuver integration tests read their steps from.
#pragma once

#include <string>

#include "net/net_index.hpp"
#include "report/outputs.hpp"
#include "scenario/scenario.hpp"
#include "sim/step_loop.hpp"
#include "step/route_planning.hpp"

namespace signalsim::test {

struct ManeuverRun {
  Scenario scenario;
  LateralPlan lateral;
  RunRecord record;
};

/// scenarios/<name>.yaml, run with its `--set`-style overrides.
inline ManeuverRun run_bundled(const std::string& name, std::vector<std::string> set = {}) {
  ManeuverRun r;
  r.scenario = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml",
                             ScenarioOverrides{std::move(set)});
  const sumo::NetIndex net = sumo::NetIndex::load(r.scenario.net);
  const sumo::RoutePlan plan = plan_route(r.scenario, net);
  r.lateral = plan_lateral(r.scenario, plan, net);
  r.record = run_scenario(r.scenario, plan, net);
  return r;
}

/// base_link's route s at a row.
inline double s_base(const ManeuverRun& r, const TimelineRow& row) { return row.s_front - r.record.base_link_to_front; }

}  // namespace signalsim::test
