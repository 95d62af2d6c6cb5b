// Where SUMO leaves signalsim's lane plan (docs/run.md). signalsim plans the ego's lanes and
// turns SUMO's lane changes off, but SUMO chooses the connection at a junction itself (see
// route/sumo_lane_choice.hpp): when it takes another one than the plan's, the ego is on a lane of a
// route edge (or an internal lane of a route junction) that is not the planned one, and the route
// may no longer be drivable from there. Each step the watch tells whether the ego is off the plan:
//   - on a lanelet of the route (the lane itself, at or after the current lanelet): on the plan;
//   - on another lane of a route edge: off the plan, unless signalsim drives lateral motion on that
//     edge (a lane change of the plan or a maneuver: the ego is between lanes by signalsim's command);
//   - on an internal lane of another connection of a route junction: off the plan.
// Consecutive off-plan steps on one lane are one OffPlanStretch (summary.json off_plan and
// counts.off_plan_steps). While the ego is off the plan a light's stop is the planned link's, not
// the lane SUMO drives: signalsim does not hold it (the stuck rule applies), and a run that ends
// off the plan says so (not_arrived reason "off_plan", naming the edge, the planned lane and SUMO's).
#pragma once

#include <optional>
#include <string>

#include "map/route_map.hpp"
#include "step/route_planning.hpp"
#include "report/timeline.hpp"

namespace signalsim {

class PlanWatch {
 public:
  PlanWatch(const RouteMap& route, const LateralPlan& lateral) : route_(route), lateral_(lateral) {}

  /// One step: the ego's lane and edge, the route lanelet index it was located at (`hint`) and its
  /// route position. Extends record.off_plan; returns whether the ego is off the plan.
  bool observe(const std::string& lane, const std::string& edge, std::size_t hint, double s_front, double time,
               RunRecord& record);

  /// The stretch the ego is in, when it was off the plan at the last observation.
  const OffPlanStretch* current(const RunRecord& record) const {
    return off_ && !record.off_plan.empty() ? &record.off_plan.back() : nullptr;
  }

  /// A run that ends off the plan: reason "off_plan", the detail naming the edge and both lanes;
  /// signalsim held nothing (its stop was for the planned link).
  void explain(NotArrived& n, const RunRecord& record) const;

 private:
  const RouteMap& route_;
  const LateralPlan& lateral_;
  bool off_ = false;
  double since_time_ = 0.0;     // when this divergence began
  std::size_t since_index_ = 0;  // its first stretch in record.off_plan
};

}  // namespace signalsim
