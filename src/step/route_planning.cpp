// A scenario's route and lateral plan (lane changes, avoidance, pull out, pull over); see route_planning.hpp.
#include "step/route_planning.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>

#include "scenario/input_error.hpp"
#include "step/maneuver_segments.hpp"
#include "turn_signal/behavior_modules.hpp"
#include "turn_signal/exit_signal_marking.hpp"

namespace signalsim {

sumo::RoutePlan prepare_route(sumo::RoutePlan plan, const TurnSignalParameters& params) {
  plan.map = route_for_decider(std::move(plan.map), params);
  return plan;
}

sumo::LaneChangeEgo lane_change_ego(const Scenario& scenario) {
  sumo::LaneChangeEgo ego;
  ego.base_link_to_front = scenario.ego.base_link_to_front;
  ego.depart_pos = scenario.ego.depart_pos;
  ego.max_speed = scenario.ego.max_speed;
  ego.accel = scenario.ego.accel;
  ego.decel = scenario.ego.decel;
  // A taken-over vehicle departs at the speed SUMO gives it (unknown here: its maximum).
  if (scenario.ego.id.empty()) ego.depart_speed = scenario.ego.depart_speed;
  ego.max_lateral_accel = scenario.ego.emergency_decel;
  // A taken-over vehicle's departure lane is SUMO's: the plan starts where it is (an added ego's
  // depart_lane asks for a lane change onto the planned lane instead).
  if (!scenario.ego.id.empty()) ego.first_lane = scenario.ego.depart_lane;
  ego.vclass = scenario.ego.vclass;
  ego.sumo_decel = scenario.ego.sumo_decel;
  ego.step_length = scenario.step_length;
  return ego;
}

sumo::RoutePlan build_scenario_route(const Scenario& scenario, const sumo::NetIndex& net) {
  return sumo::build_route(net, scenario.ego.route, required_exit_lanes(scenario), lane_change_ego(scenario));
}

std::string no_room_message(const sumo::RoutePlan& plan) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2) << "no lane plan leaves room for every lane change the route needs; "
      << "the best one changes lanes";
  const char* sep = " ";
  for (const sumo::PlannedLaneChange& c : plan.changes) {
    out << sep << "on edge '" << c.edge << "' (lane " << c.from_lane << " -> " << c.to_lane << ", a " << c.shift
        << " m shift, " << c.room << " m of room";
    if (!c.fits) {
      const double room = sumo::lane_change_room_needed(c.min_length);
      out << "; at " << plan.rooms[c.edge_index].speed << " m/s it needs " << c.min_length << " m of lateral motion, ";
      if (std::isfinite(room)) out << "so " << room << " m of room";
      else out << "more than the " << sumo::kLaneChangeLength << " m a lane change is given";
    }
    out << ")";
    sep = ", ";
  }
  return out.str();
}

namespace {

// `message` at the line of scenario key `key` (or the --set item that gave it).
[[noreturn]] void fail(const Scenario& scenario, const std::string& key, const std::string& message) {
  throw key_error(scenario, key, message);
}

// The lane the ego enters route edge `i` on: ego.depart_lane on the first edge (one it may drive),
// later the previous connection's to-lane.
int entry_lane(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetEdge& edge, std::size_t i) {
  const int planned = plan.lane_per_edge[i];
  int entry = i < plan.entry_lane_per_edge.size() ? plan.entry_lane_per_edge[i] : planned;
  if (i != 0) return entry;
  if (scenario.ego.depart_lane >= 0) entry = scenario.ego.depart_lane;
  if (entry >= static_cast<int>(edge.lanes.size()) ||
      !sumo::lane_permits(edge.lanes[static_cast<std::size_t>(entry)], scenario.ego.vclass)) {
    std::ostringstream out_msg;
    out_msg << "ego.depart_lane: edge '" << edge.id << "' has no lane " << entry << " the ego may drive ("
            << edge.lanes.size() << " lanes)";
    fail(scenario, "ego.depart_lane", out_msg.str());
  }
  return entry;
}

// The lane change the scenario asks for on route edge `i` (no `edge`: the first edge), or nullptr.
const LaneChangeManeuver* requested_lane_change(const Scenario& scenario, std::size_t i) {
  const std::string& edge = scenario.ego.route[i];
  const LaneChangeManeuver* requested = nullptr;
  for (const LaneChangeManeuver& m : scenario.lane_changes)
    if (m.edge.empty() ? i == 0 : m.edge == edge) {
      if (requested) fail(scenario, m.key, "maneuvers: two lane_change maneuvers on the first edge '" + edge + "'");
      requested = &m;
    }
  return requested;
}

// A lane change never crosses a lane the ego may not use (the lane plan avoids them; the first edge's
// change from ego.depart_lane is the scenario's).
void check_crossed_lanes(const Scenario& scenario, const sumo::NetEdge& edge, int entry, int planned,
                         const Lanelet& lanelet) {
  for (int k = std::min(entry, planned) + 1; k < std::max(entry, planned); ++k)
    if (!sumo::lane_permits(edge.lanes[static_cast<std::size_t>(k)], scenario.ego.vclass))
      fail(scenario, "ego.depart_lane", "ego.depart_lane: the lane change from lane " + std::to_string(entry) + " to the planned lane " +
                         lanelet.lane_id + " crosses lane '" + edge.lanes[static_cast<std::size_t>(k)].id + "', which " +
                         (scenario.ego.vclass == "passenger" ? std::string("a passenger car")
                                                            : "vClass '" + scenario.ego.vclass + "'") +
                         " may not use");
}

// A lane change's `at` and `length` are drivable: sharp no more than the ego can drive at the edge's
// speed, not behind base_link's earliest start, ended while the front is still on the edge (no
// lateral command on internal lanes).
void check_lane_change(const Scenario& scenario, const LaneChangeManeuver& m, const sumo::NetEdge& edge,
                       const Lanelet& lanelet, double shift, double speed, double earliest, bool first) {
  const double needed = sumo::min_lane_change_length(shift, speed, lane_change_ego(scenario));
  const std::string key = m.key.empty() ? "ego.depart_lane" : m.key;  // the default one: depart_lane's
  std::ostringstream out_msg;
  if (m.length < needed - 1e-9) {
    out_msg << std::fixed << std::setprecision(2) << "maneuvers: lane_change on '" << edge.id << "': a " << shift
            << " m shift in " << m.length << " m is sharper than the ego can drive at " << speed
            << " m/s; it needs at least " << needed << " m";
    fail(scenario, key, out_msg.str());
  }
  if (m.at < earliest - 1e-9) {
    out_msg << "maneuvers: lane_change.at " << m.at << " m is behind base_link's "
            << (first ? "depart position " : "entry ") << earliest << " m";
    fail(scenario, key, out_msg.str());
  }
  if (m.at + m.length + scenario.ego.base_link_to_front > lanelet.s_end()) {
    out_msg << "maneuvers: the lane change on '" << edge.id << "' (base_link " << m.at << " + " << m.length
            << " m) must end while the front bumper is still on the edge (" << lanelet.length << " m)";
    fail(scenario, key, out_msg.str());
  }
}

// The lane change on route edge `i`, when the ego enters it on another lane than the planned one: one
// shift line from the entry lane's offset to 0 on that edge.
std::optional<LateralSegment> lane_change_on_edge(const Scenario& scenario, const sumo::RoutePlan& plan,
                                                  const sumo::NetIndex& net, std::size_t i,
                                                  const BehaviorSignalParameters& module_params) {
  const auto index = plan.map.find_edge(scenario.ego.route[i]);
  const sumo::NetEdge* edge = net.edge(scenario.ego.route[i]);
  if (!index || edge == nullptr) return std::nullopt;
  const Lanelet& lanelet = plan.map.at(*index);
  const int planned = plan.lane_per_edge[i];
  const int entry = entry_lane(scenario, plan, *edge, i);
  const bool first = i == 0;
  const LaneChangeManeuver* requested = requested_lane_change(scenario, i);
  if (entry == planned) {
    if (requested)
      fail(scenario, requested->key, first && requested->edge.empty()
                         ? "maneuvers: lane_change: the ego departs on the planned lane " + lanelet.lane_id +
                               " of the first edge; set ego.depart_lane to another lane"
                         : "maneuvers: lane_change on '" + scenario.ego.route[i] + "': the ego already enters it on lane " +
                               lanelet.lane_id + " (to_lane)");
    return std::nullopt;
  }
  check_crossed_lanes(scenario, *edge, entry, planned, lanelet);
  // The entry lane's centre seen from the planned lane's centre (left positive), with the room, lane
  // widths and speed the lane plan chose this edge by (route/lane_change_room).
  const sumo::EdgeRoom& room = plan.rooms.at(i);
  const double shift = sumo::lane_shift(room.widths, entry, planned);
  const double offset = (entry > planned ? 1 : -1) * shift;
  const double half_width = 0.5 * edge->lanes[static_cast<std::size_t>(planned)].width;
  // Where base_link may start: its depart position on the first edge, the edge's start later.
  const double b2f = scenario.ego.base_link_to_front;
  const double earliest = first ? scenario.ego.depart_pos - b2f : lanelet.s_start;
  LaneChangeManeuver m;
  if (requested) {
    m = *requested;
    if (!requested->edge.empty()) m.at = lanelet.s_start + requested->at;  // `at` on the edge
  } else {
    // Default (sumo::default_lane_change): a lead after `earliest`, then the lateral motion, both
    // shrunk to fit a short edge (the shift ends with the front still on the edge).
    const sumo::LaneChangeTimingDefault timing = sumo::default_lane_change(room.room);
    m.at = earliest + timing.lead;
    m.length = timing.length;
    if (!sumo::lane_change_fits(room.room, shift, room.speed, lane_change_ego(scenario)))
      fail(scenario, "ego.route", "ego.route: " + no_room_message(plan));
  }
  check_lane_change(scenario, m, *edge, lanelet, shift, room.speed, earliest, first);
  LateralSegment seg;
  seg.kind = LateralKind::LaneChange;
  seg.edge = lanelet.edge_id;
  seg.reference_lane = lanelet.lane_id;
  seg.route_index = *index;
  seg.boundary = (entry > planned ? 1 : -1) * half_width;
  seg.left_half_width = seg.right_half_width = half_width;
  seg.first_line_id = 100 + i;
  seg.plan = ShiftPlan({ShiftLine{m.at, m.at + m.length, offset, 0.0}});  // nominal: started at `at`
  seg.lane_change.earliest_start = m.at;
  seg.lane_change.latest_start = lanelet.s_end() - b2f - m.length;
  seg.lane_change.length = m.length;
  seg.lane_change.shift_start = offset;
  seg.lane_change.approval_delay = m.approval_delay;
  // Hold point margin: the prepare segment from rest, driven at max_longitudinal_acc for the
  // module's shortest prepare time at standstill (docs/behaviour.md §T8.2).
  seg.lane_change.hold_margin = LaneChangeExecution::prepare_distance(
      0.0, module_params.max_longitudinal_acc, scenario.ego.max_speed,
      LaneChangeSignal::min_prepare_duration_at(0.0, module_params));
  return seg;
}

// The lane changes of the route: on every edge the ego enters on another lane than the planned one
// (the first edge: ego.depart_lane; later edges: the previous connection's to-lane).
std::vector<LateralSegment> plan_lane_changes(const Scenario& scenario, const sumo::RoutePlan& plan,
                                              const sumo::NetIndex& net) {
  const auto& edges = scenario.ego.route;
  for (const LaneChangeManeuver& m : scenario.lane_changes)
    if (!m.edge.empty() && std::find(edges.begin(), edges.end(), m.edge) == edges.end())
      fail(scenario, m.key + ".lane_change.edge", "maneuvers: lane_change: edge '" + m.edge + "' is not on the ego's route");
  const BehaviorSignalParameters module_params = behavior_parameters(scenario);
  std::vector<LateralSegment> out;
  for (std::size_t i = 0; i < edges.size() && i < plan.lane_per_edge.size(); ++i)
    if (auto seg = lane_change_on_edge(scenario, plan, net, i, module_params)) out.push_back(std::move(*seg));
  return out;
}

}  // namespace

LateralPlan plan_lateral(const Scenario& scenario, const sumo::RoutePlan& plan, const sumo::NetIndex& net) {
  LateralPlan lateral;
  for (LateralSegment& seg : plan_lane_changes(scenario, plan, net)) lateral.segments.push_back(std::move(seg));
  for (std::size_t i = 0; i < scenario.obstacles.size(); ++i) {
    const ObstacleSpec& o = scenario.obstacles[i];
    const std::string key = "obstacles[" + std::to_string(i) + "]";
    const sumo::NetEdge* edge = net.edge(o.edge);
    if (edge == nullptr || edge->is_internal) fail(scenario, key + ".edge", "obstacles: '" + o.id + "': no edge '" + o.edge + "'");
    if (o.lane >= static_cast<int>(edge->lanes.size()))
      fail(scenario, key + ".lane", "obstacles: '" + o.id + "': edge '" + o.edge + "' has no lane " + std::to_string(o.lane));
    if (o.pos > edge->lanes[static_cast<std::size_t>(o.lane)].length)
      fail(scenario, key + ".pos", "obstacles: '" + o.id + "': pos is beyond the end of its lane");
  }
  if (scenario.pull_out) {
    if (lateral.on_edge(plan.map.at(0).edge_id))
      fail(scenario, scenario.pull_out->key, "maneuvers: pull_out and a lane change on the first edge");
    lateral.segments.push_back(pull_out_segment(scenario, plan));
    lateral.depart_offset = scenario.pull_out->offset;
    lateral.backward = scenario.pull_out->backward;
    lateral.engage_delay = scenario.pull_out->engage_delay;
  }
  if (scenario.pull_over) {
    LateralSegment seg = pull_over_segment(scenario, plan);
    if (lateral.on_edge(seg.edge))
      fail(scenario, scenario.pull_over->key, "maneuvers: at most one maneuver per edge ('" + seg.edge + "' has two)");
    lateral.segments.push_back(std::move(seg));
  }
  for (std::size_t i = 0; i < scenario.avoids.size(); ++i) {
    LateralSegment seg = avoid_segment(scenario, plan, scenario.avoids[i], i);
    if (lateral.on_edge(seg.edge))
      fail(scenario, scenario.avoids[i].key, "maneuvers: at most one maneuver per edge ('" + seg.edge + "' has two)");
    lateral.segments.push_back(std::move(seg));
  }
  std::sort(lateral.segments.begin(), lateral.segments.end(), [](const LateralSegment& a, const LateralSegment& b) {
    return a.plan.lines().front().s_start < b.plan.lines().front().s_start;
  });
  return lateral;
}

std::vector<int> required_exit_lanes(const Scenario& scenario) {
  std::vector<int> out;
  for (const LaneChangeManeuver& m : scenario.lane_changes) {
    if (m.edge.empty()) continue;
    out.resize(scenario.ego.route.size(), -1);
    for (std::size_t i = 0; i < out.size(); ++i)
      if (scenario.ego.route[i] == m.edge) {
        out[i] = m.to_lane;
        break;
      }
  }
  return out;
}

sumo::RoutePlan plan_route(const Scenario& scenario, const sumo::NetIndex& net) {
  sumo::RoutePlan plan;
  try {
    plan = prepare_route(build_scenario_route(scenario, net), scenario.run_params.decider);
  } catch (const sumo::NetDefectError& e) {
    // The defect's own file and line (the net's), and which scenario route uses it.
    throw InputError(e.file(), e.line(), e.detail() + " in ego.route of " + scenario.path);
  } catch (const sumo::RouteError& e) {
    std::string hint;
    for (const LaneChangeManeuver& m : scenario.lane_changes)
      if (!m.edge.empty())
        hint += (hint.empty() ? " (with the requested lane change to lane " : "; to lane ") + std::to_string(m.to_lane) +
                " on '" + m.edge + "'";
    if (!hint.empty()) hint += ": each must be reachable from another lane and lead on)";
    throw key_error(scenario, "ego.route", std::string("ego.route: ") + e.what() + hint);
  }
  // What SUMO would otherwise clamp or reject only after it started.
  const Lanelet& first = plan.map.at(0);
  if (scenario.ego.depart_pos > first.length) {
    std::ostringstream out;
    out << "ego.depart_pos: " << scenario.ego.depart_pos << " m is beyond the end of edge '" << first.edge_id
        << "' (" << first.length << " m)";
    throw key_error(scenario, "ego.depart_pos", out.str());
  }
  plan_lateral(scenario, plan, net);  // checks the depart lane and the maneuvers
  for (const auto& [tls, offset] : scenario.light_offsets)
    if (!net.tl_logic(tls))
      throw key_error(scenario, "light_offsets." + tls, "light_offsets: '" + tls + "' is not a traffic light of the net");
  return plan;
}

}  // namespace signalsim
