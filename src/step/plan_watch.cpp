// The lane-plan watch of a signalsim-driven run; see the header.
#include "step/plan_watch.hpp"

#include <cstdio>

#include "core/number_text.hpp"

namespace signalsim {
namespace {

}  // namespace

bool PlanWatch::observe(const std::string& lane, const std::string& edge, std::size_t hint, double s_front,
                        double time, RunRecord& record) {
  bool off = false;
  std::string planned;
  if (!lane.empty() && !route_.find_lane(lane, hint)) {
    if (!edge.empty() && edge.front() == ':') {
      // Another connection of a route junction (RouteMap::s_of placed it there).
      if (route_.s_of(lane, edge, 0.0, hint)) {
        off = true;
        planned = route_.at(route_.index_at(s_front)).lane_id;
      }
    } else if (const auto index = route_.find_edge(edge, hint); index && lateral_.on_edge(edge) == nullptr) {
      off = true;
      planned = route_.at(*index).lane_id;
    }
  }
  if (off) {
    const bool continues = off_ && !record.off_plan.empty() && record.off_plan.back().lane == lane;
    if (continues) {
      record.off_plan.back().s_to = s_front;
      ++record.off_plan.back().steps;
    } else {
      record.off_plan.push_back({lane, planned, s_front, s_front, 1});
      if (!off_) {
        since_time_ = time;
        since_index_ = record.off_plan.size() - 1;
      }
    }
  }
  off_ = off;
  return off;
}

void PlanWatch::explain(NotArrived& n, const RunRecord& record) const {
  const OffPlanStretch* o = current(record);
  if (o == nullptr) return;
  n.reason = "off_plan";
  n.held_by.clear();
  n.leader.reset();
  n.junction.clear();
  const OffPlanStretch& left = record.off_plan[since_index_];  // where SUMO left the plan
  n.detail = "SUMO left the lane plan: on route edge '" + n.edge + "' it drives the ego on lane '" + o->lane +
             "', the plan's lane is '" + o->planned_lane + "' (off the plan since " + format_text("%.2f", since_time_) +
             " s, s_front " + format_text("%.2f", left.s_from) + " m, on lane '" + left.lane + "' instead of '" +
             left.planned_lane +
             "'); signalsim turned SUMO's lane changes off for the ego, so the route may not go on from there";
}

}  // namespace signalsim
