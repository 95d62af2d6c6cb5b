// The lateral segments of the maneuvers a scenario declares beside its lane changes (docs/maneuvers.md):
// an avoidance of a declared obstacle, the pull out on the first edge and the pull over to the goal,
// each with the checks it needs before SUMO starts; see maneuver_segments.hpp.
#include "step/maneuver_segments.hpp"

#include <algorithm>
#include <sstream>

#include "scenario/input_error.hpp"

namespace signalsim {
namespace {

// `message` at the line of the scenario key `key` (or the --set item that gave it).
[[noreturn]] void refuse(const Scenario& scenario, const std::string& key, const std::string& message) {
  throw key_error(scenario, key, message);
}

// A plan must start and end while base_link and the front are on the segment's edge.
void check_within_edge(const Scenario& scenario, const LateralSegment& seg, const Lanelet& lanelet,
                       const std::string& what, const std::string& key) {
  const double b2f = scenario.ego.base_link_to_front;
  const double first_s = seg.plan.lines().front().s_start;
  const double last_s = seg.plan.lines().back().s_end;
  if (first_s < lanelet.s_start - 1e-9 || last_s + b2f > lanelet.s_end()) {
    std::ostringstream out;
    out << "maneuvers: " << what << " (base_link " << first_s << " to " << last_s << " m) must start and end while "
        << "the ego is on edge '" << seg.edge << "' (route s " << lanelet.s_start << " to " << lanelet.s_end()
        << " m, front bumper included)";
    refuse(scenario, key, out.str());
  }
}

// What a pull out needs of the ego and the start planner's parameters (docs/behaviour.md §T8.2 "Pull out"),
// refused with the maneuver's line: room to back up, backing and waits only from rest, backing only
// where the start planner may back up (enable_back).
void check_pull_out(const Scenario& scenario, const Lanelet& first) {
  const PullOutManeuver& m = *scenario.pull_out;
  const BehaviorSignalParameters& p = scenario.run_params.behavior;
  std::ostringstream out;
  if (m.backward > 0.0 && scenario.ego.depart_pos - m.backward < scenario.ego.length)
    out << "pull_out.backward " << m.backward << " m would back the ego off the start of edge '" << first.edge_id
        << "' (depart_pos " << scenario.ego.depart_pos << " m, length " << scenario.ego.length << " m)";
  else if (m.backward > 0.0 && scenario.ego.depart_speed > 0.0)
    out << "pull_out.backward needs ego.depart_speed 0";
  else if (m.backward > 0.0 && !p.enable_back)
    out << "pull_out.backward needs enable_back true (start_planner.enable_back is false, "
        << scenario.params.origin("enable_back") << ")";
  else if ((m.engage_delay > 0.0 || p.prepare_time_before_start > 0.0) && scenario.ego.depart_speed > 0.0)
    out << "pull_out waits at its start (engage_delay " << m.engage_delay << " s, prepare_time_before_start "
        << p.prepare_time_before_start << " s): it needs ego.depart_speed 0";
  if (!out.str().empty()) refuse(scenario, m.key, "maneuvers: " + out.str());
}

}  // namespace

LateralSegment avoid_segment(const Scenario& scenario, const sumo::RoutePlan& plan, const AvoidManeuver& avoid,
                             std::size_t index) {
  const std::string where = "maneuvers: avoid '" + avoid.obstacle + "': ";
  const ObstacleSpec* obstacle = nullptr;
  for (const ObstacleSpec& o : scenario.obstacles)
    if (o.id == avoid.obstacle) obstacle = &o;
  if (obstacle == nullptr) refuse(scenario, avoid.key + ".avoid.obstacle", where + "no such obstacle in 'obstacles'");
  const auto route_index = plan.map.find_edge(obstacle->edge);
  if (!route_index) refuse(scenario, avoid.key, where + "edge '" + obstacle->edge + "' is not on the ego's route");
  const Lanelet& lanelet = plan.map.at(*route_index);
  const std::string lane_id = obstacle->edge + "_" + std::to_string(obstacle->lane);
  if (lanelet.lane_id != lane_id)
    refuse(scenario, avoid.key, where + "it stands on " + lane_id + ", not on the ego's planned lane " + lanelet.lane_id);
  if (obstacle->pos > lanelet.length || obstacle->pos < obstacle->length)
    refuse(scenario, avoid.key, where + "its position must lie between its length and the lane length");
  const double b2f = scenario.ego.base_link_to_front;
  AvoidanceRequest request;
  request.s_object_start = lanelet.s_start + obstacle->pos - obstacle->length;
  request.s_object_end = lanelet.s_start + obstacle->pos;
  request.object_left = 0.5 * kObstacleWidth;
  request.object_right = -0.5 * kObstacleWidth;
  request.clearance = avoid.clearance;
  request.vehicle_width = kObstacleWidth;  // the ego uses SUMO's default width too
  request.side = avoid.side == "left" ? AvoidSide::Left : avoid.side == "right" ? AvoidSide::Right : AvoidSide::Auto;
  request.base_link_to_front = b2f;
  request.rear_overhang = scenario.ego.length - b2f;
  request.speed = scenario.ego.max_speed;
  if (avoid.length > 0.0) request.lengths.fixed_length = avoid.length;
  LateralSegment seg;
  seg.kind = LateralKind::Avoidance;
  seg.route_index = *route_index;
  seg.edge = lanelet.edge_id;
  seg.reference_lane = lanelet.lane_id;
  seg.left_half_width = seg.right_half_width = 0.5 * lanelet.width;
  seg.plan = plan_avoidance(request);
  seg.first_line_id = 1000 * (index + 1);
  // docs/behaviour.md §T8.2 "Avoidance": the wait point, stop_buffer before the first shift.
  seg.avoidance.wait_point = seg.plan.lines().front().s_start - kAvoidanceStopBuffer;
  seg.avoidance.approval_delay = avoid.approval_delay;
  const double first_s = seg.plan.lines().front().s_start;
  const double last_s = seg.plan.lines().back().s_end;
  if (first_s < lanelet.s_start || last_s + b2f > lanelet.s_end()) {
    std::ostringstream out;
    out << where << "the avoidance (base_link " << first_s << " to " << last_s << " m) must start and end while the "
        << "ego is on edge '" << seg.edge << "' (route s " << lanelet.s_start << " to " << lanelet.s_end()
        << " m, front bumper included); move the obstacle or shorten the shifts (length)";
    refuse(scenario, avoid.key, out.str());
  }
  return seg;
}

// The pull out on the first edge: one shift line from the road side back to the lane's centre.
LateralSegment pull_out_segment(const Scenario& scenario, const sumo::RoutePlan& plan) {
  const PullOutManeuver& m = *scenario.pull_out;
  const Lanelet& first = plan.map.at(0);
  check_pull_out(scenario, first);
  LateralSegment seg;
  seg.kind = LateralKind::PullOut;
  seg.edge = first.edge_id;
  seg.reference_lane = first.lane_id;
  seg.left_half_width = seg.right_half_width = 0.5 * first.width;
  const double depart_base = scenario.ego.depart_pos - scenario.ego.base_link_to_front;
  const double at = m.at < 0.0 ? std::max(0.0, depart_base - m.backward) : m.at;
  seg.plan = plan_pull_out(at, m.offset, m.length);
  check_within_edge(scenario, seg, first, "pull_out", m.key);
  // The module runs while base_link is before the shift's end: a wait at the start (engagement,
  // prepare_time_before_start) behind it would never be held (docs/behaviour.md §T8.2 "Pull out").
  const bool waits = m.engage_delay > 0.0 || scenario.run_params.behavior.prepare_time_before_start > 0.0;
  if (waits && m.backward <= 0.0 && at + m.length < depart_base) {
    std::ostringstream out;
    out << "maneuvers: pull_out waits at its start, but its shift ends at s " << at + m.length
        << " m, behind the ego's base_link at departure (" << depart_base << " m)";
    refuse(scenario, m.key, out.str());
  }
  return seg;
}


// The goal is a stop at the road side: one shift line from the lane's centre to the offset at the goal.
LateralSegment pull_over_segment(const Scenario& scenario, const sumo::RoutePlan& plan) {
  const PullOverManeuver& m = *scenario.pull_over;
  const auto index = plan.map.find_edge(m.edge);
  if (!index) refuse(scenario, m.key + ".pull_over.edge", "maneuvers: pull_over: edge '" + m.edge + "' is not on the ego's route");
  const Lanelet& lanelet = plan.map.at(*index);
  LateralSegment seg;
  seg.kind = LateralKind::PullOver;
  seg.edge = lanelet.edge_id;
  seg.reference_lane = lanelet.lane_id;
  seg.route_index = *index;
  seg.left_half_width = seg.right_half_width = 0.5 * lanelet.width;
  seg.goal_s = lanelet.s_start + m.pos - scenario.ego.base_link_to_front;
  seg.plan = plan_pull_over(seg.goal_s, m.offset, m.length);
  check_within_edge(scenario, seg, lanelet, "pull_over", m.key);
  return seg;
}

}  // namespace signalsim
