// One route -> one scenario draft: lane plan, speed, sections, expectations, departure, duration, header.
#include "generate/route_scenario.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "law/expectation_rules.hpp"
#include "core/number_text.hpp"
#include "generate/route_facts.hpp"
#include "law/speed_profile.hpp"
#include "planning/stop/jerk_limited_stop.hpp"
#include "scenario/input_error.hpp"
#include "step/route_planning.hpp"

namespace signalsim::generate {
namespace {

constexpr double kInsertionRoom = 5.0;   // [m] SUMO inserts the ego only if it can stop this short of the edge end
constexpr double kDurationFactor = 1.3;  // duration = factor x (travel + waits) + slack, in 10 s steps
constexpr double kDurationSlack = 30.0;  // [s]
constexpr double kYieldWait = 5.0;       // [s] per link where SUMO makes the ego yield
constexpr double kLightRoom = 1.0;       // [m] a normal stop from the departure speed ends this short of the first light's stop point

Scenario planning_scenario(const std::string& path, const std::string& net_path, const std::vector<std::string>& edges,
                           const ParameterSet& params, const RouteScenarioOptions& o) {
  Scenario s;
  s.path = path;
  s.name = "candidate";
  s.net = net_path;
  s.country = o.country;
  s.params = params;
  s.run_params = run_parameters(params);
  s.ego.route = edges;
  s.ego.max_speed = o.max_speed;
  s.ego.length = o.length;
  s.ego.base_link_to_front = o.base_link_to_front;
  s.ego.accel = o.accel;
  s.ego.decel = o.decel;
  return s;
}

// The departure speed: no faster than the ego, the first lane's limit, the speed planner's braking
// envelope at s 0 (so the planner never starts above its own profile), what SUMO can stop from by
// the first edge's end (else it delays the insertion at a red light), and what a normal stop
// (planning/stop, as the step loop starts it: -0.9 m/s^2 of the normal set's -1 m/s^2, jerk 1 m/s^3,
// one step late, kLightRoom to spare) can shed before the first light's stop point. A light red at
// the departure and closer than the judge's stopping distance is passed by the judge when the ego
// can reach it within the yellow lamp period (docs/behaviour.md §L2.3), i.e. crossed on red.
double depart_speed(const RouteMap& route, const std::vector<LightFact>& lights, double stop_margin,
                    const RouteScenarioOptions& o) {
  double v = std::min(o.max_speed, route.at(0).speed_limit);
  const double horizon = o.max_speed * o.max_speed / (2.0 * o.decel) + 1.0;
  for (std::size_t i = 0; i < route.size() && route.at(i).s_start < horizon; ++i)
    v = std::min(v, std::sqrt(route.at(i).speed_limit * route.at(i).speed_limit + 2.0 * o.decel * route.at(i).s_start));
  v = std::min(v, std::sqrt(2.0 * vehicle_defaults::kSumoDecel * std::max(0.0, route.at(0).length - kInsertionRoom)));
  if (!lights.empty()) {
    const double room = lights.front().stop_line - stop_margin - kLightRoom;
    const StopPlannerParameters stop;
    const auto fits = [&](double speed) {
      return speed <= 0.0 ||
             stopping_distance(speed, 0.0, stop.brake_start_ratio * stop.normal.min_acc, -stop.normal.min_jerk) +
                     speed * kStepLength <=
                 room;
    };
    for (long tenths = std::lround(std::max(0.0, floor_tenth(v)) * 10.0);; --tenths) {  // in 0.1 m/s steps
      v = 0.1 * static_cast<double>(std::max(0L, tenths));
      if (fits(v)) break;
    }
  }
  return std::max(0.0, floor_tenth(v));
}

std::string lanelet_list(const RouteMap& route) {
  std::ostringstream out;
  for (std::size_t i = 0; i < route.size(); ++i) {
    const Lanelet& l = route.at(i);
    if (i % 4 == 0) out << (i ? "\n" : "") << "  ";
    else out << ", ";
    out << l.lane_id;
    if (l.is_internal && l.roundabout_role == RoundaboutRole::None &&
        (l.turn_direction == TurnDirection::Left || l.turn_direction == TurnDirection::Right))
      out << " (" << to_string(l.turn_direction) << ")";
    if (l.roundabout_role != RoundaboutRole::None) out << " [" << to_string(l.roundabout_role) << "]";
    out << " " << rounded_fixed(l.s_start, 1) << "-" << rounded_fixed(l.s_end(), 1);
  }
  return out.str();
}

void split_lines(const std::string& text, std::vector<std::string>& into) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) into.push_back(line);
}

// The speed the ego is predicted to drive, with the places it may stop: their braking distances come
// from the planned speed without stops (the ego is no faster than that).
SpeedProfile planned_speed(const RouteMap& route, const PlannedRouteFacts& facts, double v0,
                           const RouteScenarioOptions& o) {
  const SpeedLimits limits{o.max_speed, o.accel, o.decel};
  const SpeedProfile free_run(route, 0.0, v0, limits, kStepLength, {});
  std::vector<StopPoint> stops;
  for (const PlannedRouteFacts::Stop& s : facts.stops) {
    const double v = free_run.max_planned(s.s - 200.0, s.s) + kSpeedSlack;
    stops.push_back({s.s, s.light ? light_braking_distance(v) : yield_braking_distance(v), s.what});
  }
  return SpeedProfile(route, 0.0, v0, limits, kStepLength, stops);
}

// The decider's parameters that find the route's sections.
SectionParameters section_parameters(const RunParameters& typed) {
  SectionParameters out;
  out.intersection_search_distance = typed.decider.turn_signal_intersection_search_distance;
  out.roundabout_search_distance = typed.decider.turn_signal_roundabout_search_distance;
  out.on_entry = typed.decider.turn_signal_roundabout_on_entry;
  out.on_exit = typed.decider.turn_signal_roundabout_on_exit;
  out.entry_persistence = typed.decider.turn_signal_roundabout_entry_indicator_persistence;
  return out;
}

// The decider's parameters and the ego's measures the expectation rules use.
RuleParameters rule_parameters(const RunParameters& typed, const RouteScenarioOptions& o) {
  RuleParameters out;
  out.search_time = typed.decider.turn_signal_search_time;
  out.minimum_search_distance = typed.decider.turn_signal_minimum_search_distance;
  out.base_link_to_front = o.base_link_to_front;
  out.straight = o.straight;
  return out;
}

// The turns, roundabouts (entry -> exit), lights and lane changes the route passes through.
RouteFeatures route_features(const std::vector<Section>& sections, const PlannedRouteFacts& facts) {
  RouteFeatures out;
  for (const Section& s : sections) {
    if (s.kind == SectionKind::Turn) out.turns.push_back(s.id + " " + to_string(s.side));
    if (s.kind == SectionKind::LaneChange) ++out.lane_changes;
  }
  for (std::size_t i = 0; i < sections.size(); ++i) {
    if (sections[i].kind != SectionKind::RoundaboutEntry) continue;
    std::string exit = "(ends on the ring)";
    for (std::size_t j = i + 1; j < sections.size(); ++j)
      if (sections[j].kind == SectionKind::RoundaboutExit) {
        exit = sections[j].id;
        break;
      }
    out.roundabouts.push_back(sections[i].id + " -> " + exit);
  }
  for (const LightFact& l : facts.lights)
    if (std::find(out.lights.begin(), out.lights.end(), l.id) == out.lights.end()) out.lights.push_back(l.id);
  return out;
}

// [s] The time the ego may wait on the way: a full cycle of every light and kYieldWait per yield.
double expected_waits(const PlannedRouteFacts& facts) {
  double waits = 0.0;
  int yields = 0;
  for (double c : facts.light_cycles) waits += c;
  for (const PlannedRouteFacts::Stop& s : facts.stops) yields += s.light ? 0 : 1;
  waits += kYieldWait * yields;
  return waits;
}

// The header line of the parameters the expectations were derived with.
std::string parameters_line(const RouteScenarioOptions& o, const RunParameters& typed,
                            const SectionParameters& section_params, const RuleParameters& rules) {
  return "Parameters: Autoware's defaults" + (o.country.empty() ? std::string() : " + country preset " + o.country) +
         ": search " + rounded_fixed(rules.search_time, 1) + " s x v + " +
         rounded_fixed(section_params.intersection_search_distance, 1) + " m (turns), + " +
         rounded_fixed(section_params.roundabout_search_distance, 1) + " m (roundabout entries); entry " +
         section_params.on_entry + ", exit " + section_params.on_exit + "; exit signal from the previous exit: " +
         (typed.decider.turn_signal_roundabout_exit_signal_from_previous_exit ? "yes" : "no");
}

// The header line of the ego's measures and its departure.
std::string ego_line(const RouteScenarioOptions& o, const RouteMap& route, double v0) {
  return "Ego: " + rounded_fixed(o.length, 1) + " m, front " + rounded_fixed(o.base_link_to_front, 1) +
         " m ahead of base_link, at most " + rounded_fixed(o.max_speed, 2) + " m/s, accel/decel " +
         rounded_fixed(o.accel, 1) + "/" + rounded_fixed(o.decel, 1) + " m/s^2; departs at s 0 on " +
         route.at(0).lane_id + " at " + rounded_fixed(v0, 1) +
         " m/s (the least of its top speed, the lane limit, the speed planner's braking envelope, what SUMO "
         "can stop from by the edge's end and what a normal stop sheds before the first light)";
}

// The header lines of the route's sections with their possible and certain windows (none without sections).
void add_section_lines(const std::vector<Section>& sections, const Derivation& derivation,
                       std::vector<std::string>& h) {
  if (sections.empty()) return;
  h.push_back("Sections (front bumper; possible: its request may be valid; certain: its blinker is sure to show):");
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const Section& s = sections[i];
    const SectionWindows& w = derivation.windows[i];
    std::string line = "  " + std::string(to_string(s.kind)) + " " + s.id + " " + to_string(s.side) + ", s " +
                       rounded_fixed(s.start, 1) + "-" + rounded_fixed(s.end, 1);
    if (s.side != Side::None)
      line += ": possible " + rounded_fixed(w.possible_from, 1) + "-" + rounded_fixed(w.possible_to, 1);
    if (s.side == Side::Left || s.side == Side::Right)
      line += w.guaranteed_to > w.guaranteed_from
                  ? ", certain " + rounded_fixed(w.guaranteed_from, 1) + "-" + rounded_fixed(w.guaranteed_to, 1)
                  : ", never certain";
    h.push_back(line);
  }
}

}  // namespace

std::optional<RouteScenario> route_scenario(const sumo::NetIndex& net, const std::string& net_path,
                                            const std::vector<std::string>& edges, const ParameterSet& params,
                                            const RouteScenarioOptions& o, const std::string& scenario_path,
                                            RouteRejection& rejection) {
  const Scenario planning = planning_scenario(scenario_path, net_path, edges, params, o);
  sumo::RoutePlan plan;
  LateralPlan lateral;
  try {
    plan = plan_route(planning, net);  // the lane plan a run makes, with the exit-signal marking
    lateral = plan_lateral(planning, plan, net);
  } catch (const InputError& e) {
    rejection.reason = "no lane plan";
    return std::nullopt;
  }
  const RouteMap& route = plan.map;
  if (route.at(0).length < o.min_edge || route.at(route.size() - 1).length < o.min_edge) {
    rejection.reason = "first or last edge shorter than " + rounded_fixed(o.min_edge, 0) + " m";
    return std::nullopt;
  }

  const PlannedRouteFacts facts = route_facts(plan, lateral, net);
  if (!facts.never_green.empty()) {
    rejection.reason = "a light never lets the route's link go";
    return std::nullopt;
  }
  const RunParameters& typed = planning.run_params;
  const double v0 = depart_speed(route, facts.lights, typed.judge.stop_margin, o);
  const SpeedProfile speed = planned_speed(route, facts, v0, o);
  const SectionParameters section_params = section_parameters(typed);
  const std::vector<Section> sections = route_sections(route, section_params, facts.lane_changes);
  const RuleParameters rules = rule_parameters(typed, o);
  RouteFacts route_facts_for_rules{0.0, route.length(), facts.lights};
  const Derivation derivation = derive_expectations(sections, route_facts_for_rules, speed, rules);

  RouteScenario out;
  out.length = route.length();
  out.features = route_features(sections, facts);
  const double waits = expected_waits(facts);
  const double duration = 10.0 * std::ceil((kDurationFactor * (speed.travel_time() + waits) + kDurationSlack) / 10.0);

  ScenarioDraft& d = out.draft;
  d.net = net_path;
  d.country = o.country;
  d.duration = duration;
  d.route = edges;
  d.depart_speed = v0;
  d.max_speed = o.max_speed;
  d.length = o.length;
  d.base_link_to_front = o.base_link_to_front;
  d.expect = derivation.expectations;

  std::vector<std::string>& h = d.header;
  h.push_back(parameters_line(o, typed, section_params, rules));
  h.push_back(ego_line(o, route, v0));
  h.push_back("Duration " + rounded_fixed(duration, 0) + " s = " + rounded_fixed(kDurationFactor, 1) + " x (" +
              rounded_fixed(speed.travel_time(), 1) + " s planned travel + " + rounded_fixed(waits, 1) +
              " s of light cycles and yields) + " + rounded_fixed(kDurationSlack, 0) + " s, in 10 s steps");
  h.push_back("Speed: the step loop's planner (planning/speed_limit_planner) rolled out from the departure; where the "
              "ego may stop (lights, yields), braking may start earlier and it restarts from rest (generate/speed_profile)");
  h.push_back("Lanelets (route s of the front bumper, m):");
  split_lines(lanelet_list(route), h);
  if (!facts.stops.empty()) {
    h.push_back("Where the ego may stop (braking may start that far before):");
    for (const StopPoint& s : speed.stops())
      h.push_back("  " + s.what + " at s " + rounded_fixed(s.s, 1) + " (" + rounded_fixed(s.braking, 1) + " m)");
  }
  add_section_lines(sections, derivation, h);
  for (const std::string& note : derivation.notes) h.push_back("Note: " + note);
  return out;
}

}  // namespace signalsim::generate
