// The scenario file's lists: `obstacles` (mappings), `maneuvers` and `expect` (one-key mappings
// `- <kind>: <value>`, each kind with its table). The kinds' order is the order messages list them.
// Defaults are the value types' own (scenario/scenario.hpp).
#include "scenario/scenario_keys.hpp"

#include <stdexcept>

#include "scenario/scenario.hpp"

namespace signalsim {
namespace {

KeySpec blinker_key() { return required_text_key("blinker", "The blinker.", blinker_choices()); }
KeySpec light_key() { return required_text_key("light", "The traffic light (tls id) on the route."); }
KeySpec lead_key() {
  return required_number_key("lead", 0.0, 10000.0, "m", "On at least this far (front bumper) before the entry.");
}
KeySpec from_s_key() { return required_number_key("from_s", -1e6, 1e9, "m", "Start of the stretch (route s, front bumper)."); }
KeySpec to_s_key() { return required_number_key("to_s", -1e6, 1e9, "m", "End of the stretch, at least from_s."); }
// An operator's RTC approval of a module's maneuver (planning/operator_approval.hpp), counted from `since`.
KeySpec approval_delay_key(double default_value, const std::string& since) {
  return number_key("approval_delay", default_value, 0.0, 3600.0, "s",
                    "Approval comes this long after " + since + " (an operator's RTC approval; 0: at once).");
}

const KeyTable& lane_change_keys() {
  static const LaneChangeManeuver d;
  static const KeyTable table{
      "maneuvers[].lane_change",
      "A lane change: from ego.depart_lane on the first edge, or (with edge) a requested one on a route edge.",
      {
          text_key_or("edge", d.edge, "A route edge: the lane change is requested there (with to_lane); empty: the "
                                      "first edge's, from ego.depart_lane."),
          [] {  // required with a non-empty edge (the loader's rule), and only with one
            KeySpec k = required_number_key("to_lane", 0.0, 63.0, "", "With edge (then required): the lane index "
                                                                      "the ego is on at the end of edge.");
            k.required = false;
            k.needs = {"edge"};
            return k;
          }(),
          required_number_key("at", 0.0, 1e6, "m", "base_link's earliest start of the lateral motion (route s; on "
                                                   "edge with edge)."),
          number_key("length", kDefaultLaneChangeLength, 1.0, 10000.0, "m", "Route s over which the ego shifts one lane."),
          approval_delay_key(d.approval_delay, "the blinker"),
      }};
  return table;
}

const KeyTable& avoid_keys() {
  static const AvoidManeuver d;
  static const KeyTable table{
      "maneuvers[].avoid",
      "Pass a declared obstacle on the ego's planned lane: shift out, hold, shift back.",
      {
          required_text_key("obstacle", "The obstacle's id (obstacles)."),
          number_key("clearance", d.clearance, 0.0, 10.0, "m", "Lateral gap between the ego's side and the obstacle."),
          text_key_or("side", d.side, "The side to pass on (auto: left).", {"auto", "left", "right"}),
          number_key("length", d.length, 0.0, 10000.0, "m",
                     "Each shift's length; 0: from the jerk and acceleration limits at max_speed."),
          approval_delay_key(d.approval_delay, "the module began to wait (the ego waits before the shift)"),
      }};
  return table;
}

const KeyTable& pull_out_keys() {
  static const PullOutManeuver d;
  static const KeyTable table{
      "maneuvers[].pull_out",
      "Depart beside the lane's centre (the road side) and shift back to it (first edge only; at most one).",
      {
          required_number_key("offset", -10.0, 10.0, "m", "Departure offset from the lane's centre, left positive."),
          number_key("length", d.length, 1.0, 10000.0, "m", "Length of the shift back."),
          with_default_note(number_key("at", d.at, 0.0, 1e6, "m", "Route s of base_link where the shift starts."),
                            "the depart position (minus backward)"),
          number_key("backward", d.backward, 0.0, 1000.0, "m", "First back up this far (hazard lights)."),
          number_key("engage_delay", d.engage_delay, 0.0, 3600.0, "s",
                     "The ego is engaged (Autoware's autonomous mode) this long after the run starts; it stands "
                     "still until then."),
      }};
  return table;
}

const KeyTable& pull_over_keys() {
  static const PullOverManeuver d;
  static const KeyTable table{
      "maneuvers[].pull_over",
      "The goal is a stop at the road side: shift to offset and stop there (at most one).",
      {
          required_text_key("edge", "The goal's edge."),
          required_number_key("pos", 0.0, 1e6, "m", "Lane position of the front bumper at the goal."),
          required_number_key("offset", -10.0, 10.0, "m", "Goal offset from the lane's centre, left positive."),
          number_key("length", d.length, 1.0, 10000.0, "m", "Length of the shift."),
      }};
  return table;
}

const KeyTable& blinker_through_junction_keys() {
  static const KeyTable table{
      "expect[].blinker_through_junction",
      "A blinker is on from at least lead before the route enters the junction until base_link leaves it.",
      {required_text_key("junction", "The junction id on the route."), blinker_key(), lead_key()}};
  return table;
}

const KeyTable& blinker_through_lanelet_keys() {
  static const KeyTable table{
      "expect[].blinker_through_lanelet",
      "A blinker is on from at least lead before the route enters the lanelet until base_link leaves it.",
      {required_text_key("lanelet", "The lanelet (SUMO lane) id on the route."), blinker_key(), lead_key()}};
  return table;
}

const KeyTable& blinker_on_keys() {
  static const KeyTable table{"expect[].blinker_on", "The blinker is on at every step within [from_s, to_s].",
                              {blinker_key(), from_s_key(), to_s_key()}};
  return table;
}

const KeyTable& no_blinker_keys() {
  static const KeyTable table{"expect[].no_blinker", "No blinker at any step within [from_s, to_s].",
                              {from_s_key(), to_s_key()}};
  return table;
}

const KeyTable& stops_before_light_keys() {
  static const ExpectStopsBeforeLight d;
  static const KeyTable table{
      "expect[].stops_before_light",
      "The ego comes to rest for the light with its front within tolerance of the stop point.",
      {light_key(), number_key("tolerance", d.tolerance, 0.0, 100.0, "m", "Allowed distance from the stop point.")}};
  return table;
}

// The expectations that name only a light (the vector is never changed: its tables stay in place).
const std::vector<KeyTable>& light_expectation_keys() {
  static const std::vector<KeyTable> tables = {
      {"expect[].passes_light",
       "The ego crosses the light's stop line without a stop decision and without coming to rest.", {light_key()}},
      {"expect[].emergency_stop_at_light", "The judge ordered an emergency stop (dilemma zone) at the light.",
       {light_key()}},
      {"expect[].never_in_dilemma_zone",
       "The judge judged the light and never classified a dilemma zone there nor ordered an emergency stop.",
       {light_key()}},
      {"expect[].v2i_stop_at_light",
       "The judge ordered a stop at the light because V2I predicted red within the horizon.", {light_key()}},
  };
  return tables;
}

const KeyTable& light_expectation(const std::string& kind) {
  for (const KeyTable& table : light_expectation_keys())
    if (table.where == "expect[]." + kind) return table;
  throw std::logic_error("no light expectation '" + kind + "'");
}

const KeyTable& lateral_keys() {
  static const ExpectLateralFollowsPlan d;
  static const KeyTable table{
      "expect[].lateral_offset_follows_plan",
      "While a lateral plan is driven, |lateral offset - planned offset| stays within tolerance.",
      {number_key("tolerance", d.tolerance, 0.0, 10.0, "m", "Allowed deviation from the plan.")}};
  return table;
}

}  // namespace

const std::vector<std::string>& blinker_choices() {
  static const std::vector<std::string> choices = {"left", "right", "hazard", "none"};
  return choices;
}

const KeyTable& obstacle_keys() {
  static const ObstacleSpec d;
  static const KeyTable table{
      "obstacles[]",
      "A vehicle standing still on a lane for the whole run (1.8 m wide).",
      {
          required_text_key("id", "Its id (avoid names it), unique."),
          required_text_key("edge", "The edge it stands on."),
          integer_key("lane", d.lane, 0, 100, "Lane index on edge."),
          required_number_key("pos", 0.0, 1e6, "m", "Lane position of its front."),
          number_key("length", d.length, 0.5, 30.0, "m", "Its length."),
      }};
  return table;
}

const KeyTable& maneuver_kinds() {
  static const KeyTable table{
      "maneuvers[]",
      "One maneuver: a one-key mapping, e.g. `- lane_change: {at: 40, length: 50}`.",
      {
          table_key("lane_change", KeyType::Mapping, lane_change_keys(), lane_change_keys().description),
          table_key("avoid", KeyType::Mapping, avoid_keys(), avoid_keys().description),
          table_key("pull_out", KeyType::Mapping, pull_out_keys(), pull_out_keys().description),
          table_key("pull_over", KeyType::Mapping, pull_over_keys(), pull_over_keys().description),
      }};
  return table;
}

const KeyTable& expectation_kinds() {
  const auto kind = [](const std::string& name, const KeyTable& body) {
    return table_key(name, KeyType::Mapping, body, body.description);
  };
  const auto light = [&](const std::string& name) { return kind(name, light_expectation(name)); };
  static const KeyTable table{
      "expect[]",
      "One expectation: a one-key mapping, e.g. `- blinker_never: right`.",
      {
          kind("blinker_through_junction", blinker_through_junction_keys()),
          kind("blinker_through_lanelet", blinker_through_lanelet_keys()),
          kind("blinker_on", blinker_on_keys()),
          kind("no_blinker", no_blinker_keys()),
          text_key("blinker_never", "This blinker value never occurs.", blinker_choices()),
          kind("stops_before_light", stops_before_light_keys()),
          light("passes_light"),
          light("emergency_stop_at_light"),
          light("never_in_dilemma_zone"),
          light("v2i_stop_at_light"),
          shape_key("never_runs_red", KeyType::True, "The front never crosses a stop line while the ego's link shows red."),
          kind("lateral_offset_follows_plan", lateral_keys()),
          shape_key("arrives", KeyType::True, "The ego reaches the end of its route within the run's duration."),
      }};
  return table;
}

}  // namespace signalsim
