// The scenario file's mappings with fixed keys: the top level, ego, perception, params. Defaults are
// the value types' own (EgoSpec, PerceptionModelParameters, Scenario), so the loader, the types and
// the schema agree.
#include "scenario/scenario_keys.hpp"

#include "scenario/scenario.hpp"

namespace signalsim {

const KeyTable& scenario_keys() {
  static const Scenario d;  // the defaults
  static const KeyTable table{
      "",
      "A signalsim scenario: the SUMO net, the ego and its route, parameters and expectations.",
      {
          required_text_key("name", "The run's name (summary.json, results.csv)."),
          text_key_or("description", "", "One line about what the scenario shows."),
          text_key("net", "The SUMO net (.net.xml), relative to this file; wins over the sumocfg's net-file."),
          text_key("sumocfg", "A SUMO configuration: its net, route and additional files, step length, begin, end "
                              "and seed (the scenario's own keys win, and are recorded)."),
          text_list_key("routes", "Route files (SUMO -r), after the sumocfg's, relative to this file."),
          text_list_key("sumo_args", "SUMO options passed on as written, e.g. [--lateral-resolution, 0.8]; the "
                                     "options signalsim sets itself are refused."),
          text_list_key("additional", "Additional files (traffic-light programs, ...), after the sumocfg's, "
                                      "relative to this file."),
          with_default_note(number_key("step_length", d.step_length, 0.001, 1.0, "s",
                                       "The simulation step: a whole number of milliseconds."),
                            "the sumocfg's step-length when it has one"),
          with_default_note(number_key("duration", d.duration, 0.001, 86400.0, "s",
                                       "Simulated seconds at most (at most 2 000 000 steps)."),
                            "the sumocfg's end - begin when it has an end"),
          with_default_note(integer_key("seed", d.seed, 0, 2147483647, "SUMO's and the perception model's seed."),
                            "the sumocfg's seed when it has one"),
          text_key_or("country", "", "A country preset (config/countries/<code>.yaml, e.g. jp): its parameter "
                                     "values apply after params.files; empty for none."),
          table_key("ego", KeyType::Mapping, ego_keys(),
                    "The ego vehicle and its route; optional only with fleet: (an egoless fleet run, docs/fleet.md)."),
          table_key("perception", KeyType::Mapping, perception_keys(),
                    "The traffic-light perception model's faults; all off by default."),
          shape_key("light_offsets", KeyType::NumberMapping,
                    "Shifts of traffic-light programs: light (tls) id: seconds."),
          table_key("params", KeyType::Mapping, params_keys(),
                    "Parameters: defaults, params.files, the country, params.set, then --set."),
          table_key("obstacles", KeyType::MappingList, obstacle_keys(),
                    "Vehicles standing still on a lane for the whole run."),
          table_key("maneuvers", KeyType::KindList, maneuver_kinds(),
                    "Lateral maneuvers: each item one of lane_change, avoid, pull_out, pull_over."),
          text_key_or("decider", "reference",
                      "The turn-signal decider under test (docs/decider.md): reference, autoware_core, traci, "
                      "lib:PATH.so (relative to this file) or exec:COMMAND (run in this file's directory)."),
          text_key_or("light_judge", "reference",
                      "The traffic-light judge under test: reference, traci, lib:PATH.so or exec:COMMAND."),
          number_key("sut_timeout", d.sut_timeout, 0.01, 3600.0, "s",
                     "A decider or light judge under test answers each step within this, or the run ends as an error."),
          as_nullable(table_key("fleet", KeyType::Mapping, fleet_keys(),
                                "Fleet mode (docs/fleet.md): the reference decider gives every selected vehicle of "
                                "SUMO's traffic its blinker; empty: every vehicle.")),
          table_key("expect", KeyType::KindList, expectation_kinds(),
                    "Expectations checked after the run (exit code 1 when one fails)."),
      },
      {{"net", "sumocfg"}, {"ego", "fleet"}}};
  return table;
}

const KeyTable& ego_keys() {
  static const EgoSpec d;  // the defaults
  static const KeyTable table{
      "ego",
      "The ego vehicle: signalsim's own (on `route`) or a vehicle of the route files taken over (`id`).",
      {
          text_key_or("id", d.id, "Take over this vehicle of the route files when it departs (its route, vType "
                                  "and departure are SUMO's: give no depart_pos, depart_speed, depart_lane); empty: "
                                  "signalsim adds its own ego."),
          text_list_key("route", "Edge ids, each connecting to the next (at least one without id)."),
          number_key("depart_pos", d.depart_pos, 0.0, 1e6, "m", "Departure position on the first edge."),
          number_key("depart_speed", d.depart_speed, 0.0, 100.0, "m/s", "Departure speed, at most max_speed."),
          number_key("max_speed", d.max_speed, 0.1, 100.0, "m/s", "The ego's top speed."),
          number_key("length", d.length, 0.5, 30.0, "m", "Vehicle length."),
          number_key("width", d.width, 0.3, 5.0, "m", "Vehicle width."),
          computed_number_key("base_link_to_front", 0.0, 30.0, "m", "3.7/4.5 of length (3.7 m of 4.5 m)",
                              "Rear-axle centre (base_link) to front bumper, at most length."),
          number_key("accel", d.accel, 0.1, 10.0, "m/s^2", "Comfortable acceleration."),
          number_key("decel", d.decel, 0.1, 10.0, "m/s^2", "Comfortable deceleration."),
          number_key("emergency_decel", d.emergency_decel, 1.0, 15.0, "m/s^2", "The most the ego can brake."),
          integer_key("depart_lane", d.depart_lane, -1, 100,
                      "Lane index to depart on; -1: the planned lane of the first edge (another lane plans a "
                      "lane change onto it)."),
          text_key("vehicle_info", "Autoware's vehicle_info.param.yaml, relative to this file: length, width and "
                                   "base_link_to_front from it (the keys given here win)."),
      },
      {{"route", "id"}}};
  return table;
}

const KeyTable& fleet_keys() {
  static const KeyTable table{
      "fleet",
      "Which vehicles of SUMO's traffic get their blinker from the reference decider, and whether it is set.",
      {
          text_key("vtype", "Only vehicles of this vType id."),
          text_key("vclass", "Only vehicles of this vClass (passenger, bus, ...)."),
          text_key("id_pattern", "Only vehicles whose whole id matches this ECMAScript regular expression."),
          text_key_or("signals", "set",
                      "set: signalsim sets their signals every step; observe: it decides, sets nothing and "
                      "compares with SUMO's own blinker.",
                      {"set", "observe"}),
      }};
  return table;
}

const KeyTable& perception_keys() {
  static const PerceptionModelParameters d;  // the defaults
  static const KeyTable table{
      "perception",
      "The traffic-light perception model (docs/behaviour.md §L): range, dropouts, latency, noise, blackouts and "
      "omissions.",
      {
          with_default_note(number_key("detection_range", d.detection_range, 0.0, 1e9, "m",
                                       "Lights farther away are not seen."),
                            "unlimited"),
          number_key("dropout_probability", d.dropout_probability, 0.0, 1.0, "",
                     "Probability that a step captures nothing at all."),
          number_key("latency", d.latency, 0.0, 60.0, "s", "A capture is delivered this much later."),
          integer_key("detections_per_light", d.detections_per_light, 1, 100,
                      "Detections of every bulb per capture (e.g. cameras)."),
          number_key("confidence_noise", d.confidence_noise, 0.0, 1.0, "", "Noise on each detection's confidence."),
          number_key("misclassification_probability", d.misclassification_probability, 0.0, 1.0, "",
                     "Probability that a detection reports another colour."),
          shape_key("blackouts", KeyType::Intervals, "[start, end] pairs of simulated seconds without captures."),
          number_key("omission_probability", d.omission_probability, 0.0, 1.0, "",
                     "Probability that a captured message is delivered without the light (a stop signal once seen)."),
          shape_key("omissions", KeyType::Intervals,
                    "[start, end] pairs of simulated seconds in which messages are delivered without the light."),
          as_nullable(table_key("v2i", KeyType::Mapping, v2i_channel_keys(),
                                "The V2I channel's faults (docs/behaviour.md §L1.7; with v2i.use_remaining_time); by "
                                "default the camera's dropout, latency and blackouts.")),
      }};
  return table;
}

const KeyTable& v2i_channel_keys() {
  static const KeyTable table{
      "perception.v2i",
      "The V2I channel's faults; a key not given takes the camera's value (perception.<key>).",
      {
          computed_number_key("dropout_probability", 0.0, 1.0, "", "perception.dropout_probability",
                              "Probability that a step's message is lost."),
          computed_number_key("latency", 0.0, 60.0, "s", "perception.latency", "A message arrives this much later."),
          with_default_note(shape_key("blackouts", KeyType::Intervals,
                                      "[start, end] pairs of simulated seconds without messages."),
                            "perception.blackouts"),
      }};
  return table;
}

const KeyTable& params_keys() {
  static const KeyTable table{
      "params",
      "Parameters with Autoware's names (config/autoware_defaults.yaml lists them with their defaults).",
      {
          text_list_key("files", "Parameter files, relative to this file, applied in order: Autoware's as "
                                 "shipped (`/**: ros__parameters:`) or signalsim's flat ones."),
          shape_key("set", KeyType::Parameters,
                    "Parameter values, applied after the files and the country preset."),
          boolean_key("strict", false, "Every key of a parameter file (and of ego.vehicle_info) that signalsim "
                                       "does not use must be one of Autoware's keys of that file "
                                       "(data/autoware_keys.yaml); a key Autoware dropped is a warning."),
      }};
  return table;
}

}  // namespace signalsim
