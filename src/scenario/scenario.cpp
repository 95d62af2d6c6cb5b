// Loading a scenario file: the overrides applied to its YAML tree, then each part read through its
// key table (scenario_keys.hpp) in a fixed order - the simulation keys, the ego, obstacles and
// maneuvers, the traffic-light inputs, parameters (kept by name and typed), expectations - and last
// the check that the top level holds no other key; then the country preset's driving side against the
// net's. Also the decider's and the behaviour modules' parameters with the ego's footprint.
#include "scenario/scenario.hpp"

#include "scenario/countries.hpp"
#include "scenario/ego_reading.hpp"
#include "scenario/expectation_reading.hpp"
#include "scenario/input_error.hpp"
#include "scenario/maneuver_reading.hpp"
#include "scenario/notes.hpp"
#include "scenario/overrides.hpp"
#include "scenario/scenario_keys.hpp"
#include "scenario/signal_reading.hpp"
#include "scenario/sumo_inputs.hpp"
#include "scenario/utf8_text.hpp"
#include "scenario/yaml_fields.hpp"
#include "core/file_paths.hpp"
#include "net/net_file.hpp"

#include <filesystem>
#include <optional>
#include <utility>

namespace signalsim {
namespace {

// Parameters: defaults, params.files, the country preset, params.set, then --set overrides.
void read_parameters(const YamlFields& top, const std::string& path, const YAML::Node& parameter_overrides,
                     const std::optional<Country>& country, Scenario& s) {
  YAML::Node set;
  if (top.has("params")) {
    YamlFields params(top.node("params"), path, "params", params_keys());
    // strict: every key of a parameter file must be one signalsim uses (else they are listed).
    (void)params.node("strict");  // read with the ego (it applies to ego.vehicle_info too)
    const std::vector<std::string> files = params.text_list("files");
    for (std::size_t i = 0; i < files.size(); ++i) {
      const std::string file = resolve_beside(path, files[i]);
      // One the scenario names is refused at its line; a --params file (an override) names itself.
      const std::string key = "params.files[" + std::to_string(i) + "]";
      if (const std::string problem = input_file_problem(file); !problem.empty() && !s.origins.set.count(key))
        throw key_error(s, key, "key 'params.files': parameter file '" + file + "' " + problem);
      s.params.apply_file(file, s.strict_params);
    }
    const YAML::Node given = params.node("set");
    if (given) set.reset(given);  // (assigning an absent node would throw)
    params.finish();
  }
  if (country) s.params.apply(country->parameters, ParameterOrigin{country->path, "country " + country->code});
  if (set && !set.IsNull()) s.params.apply(set, ParameterOrigin{path, "set"});
  if (parameter_overrides.size() > 0) s.params.apply(parameter_overrides, ParameterOrigin{"--set", "--set"});
  s.params.check_consistency(path);
  for (const UnusedParameters& file : s.params.unused()) s.notes.push_back(unused_parameters_note(file));
  s.warnings.insert(s.warnings.end(), s.params.warnings().begin(), s.params.warnings().end());
  s.run_params = run_parameters(s.params);
}

// A preset for the other driving side than the net's (read from the net's beginning; a net that
// cannot be read is the run's to report).
void check_driving_side(const Country& country, Scenario& s) {
  if (const std::optional<bool> lefthand = sumo::read_net_lefthand(s.net))
    if (auto warning = driving_side_warning(country, s.net, *lefthand)) s.warnings.push_back(std::move(*warning));
}

// `decider:`, `light_judge:` (a lib: path relative to this file; an exec: command runs in its
// directory) and `sut_timeout:`. An override of sut_override's form {sut: TEXT, dir: DIR} (--decider,
// a sweep file) names its own directory instead.
void read_systems_under_test(const YamlFields& top, const std::string& path, Scenario& s) {
  for (auto [key, spec] : {std::pair{"decider", &s.decider}, std::pair{"light_judge", &s.light_judge}}) {
    std::string dir = std::filesystem::path(path).parent_path().string();
    std::string text;
    if (const YAML::Node given = top.node(key); given && given.IsMap()) {
      const YAML::Node sut = given["sut"], base = given["dir"];
      if (given.size() != 2 || !sut || !sut.IsScalar() || !base || !base.IsScalar())
        top.fail(key, "expected a text (reference, autoware_core, traci, lib:PATH.so or exec:COMMAND)");
      text = sut.Scalar();
      dir = base.Scalar();
    } else {
      text = top.text_or(key);
    }
    if (text.empty()) continue;
    if (const std::string reason = parse_sut_spec(text, dir, *spec); !reason.empty()) top.fail(key, reason);
  }
  if (s.light_judge.kind == SutSpec::Kind::AutowareCore)
    top.fail("light_judge", "autoware_core is a decider (its path_generator has no traffic-light judge)");
  s.sut_timeout = top.number("sut_timeout");
}

// Every part of the scenario, read from its tree (the overrides applied) in a fixed order.
void read_scenario(const YAML::Node& root, const std::string& path, const YAML::Node& parameter_overrides, Scenario& s) {
  YamlFields top(root, path, "", scenario_keys());
  s.name = top.text("name");
  if (const std::string problem = name_problem(s.name, false); !problem.empty()) top.fail("name", problem);
  s.description = top.text_or("description");
  read_simulation_keys(top, path, s);
  // The timeline is kept in memory: cap the number of steps (about 0.5 kB each).
  if (s.duration / s.step_length > 2e6)
    top.fail("duration", "duration / step_length exceeds 2 000 000 steps; shorten the run or lengthen the step");
  s.country = top.text_or("country");
  if (!s.country.empty() && !is_country_code(s.country)) top.fail("country", unknown_country_reason(s.country));
  const std::optional<Country> country = s.country.empty() ? std::nullopt : std::optional(load_country(s.country));
  read_ego(top, root, path, s);
  read_obstacles(top, path, s);
  read_maneuvers(top, path, s);
  read_signal_inputs(top, path, s);
  read_parameters(top, path, parameter_overrides, country, s);
  read_expectations(top, path, s);
  read_systems_under_test(top, path, s);
  read_fleet(top, path, s);
  if (!s.has_ego) refuse_ego_only_keys(top);
  top.finish();
  if (country) check_driving_side(*country, s);
}

}  // namespace

Scenario load_scenario(const std::string& path, const ScenarioOverrides& overrides) {
  YAML::Node root = load_yaml_file(path, "scenario file");
  // Before the overrides walk it (fuzzing: a scalar file and --set threw yaml-cpp's own "operator[]
  // call on a scalar"; yaml-cpp turned a list file into a mapping). An empty file stays empty.
  if (root && !root.IsNull() && !root.IsMap()) YamlFields(root, path, "");
  YAML::Node parameter_overrides;
  Scenario s;
  s.path = path;
  root = apply_overrides(root, overrides, parameter_overrides, &s.origins.set);
  s.origins.lines = key_lines(root);
  try {
    read_scenario(root, path, parameter_overrides, s);
  } catch (const InputError& e) {
    throw attributed(e, path, s.origins);  // a value --set gave is the command line's, not the file's
  }
  // The scenario loaded: say what it ignored and what may not do what was meant.
  for (const std::string& note : s.notes) note_once(note);
  for (const std::string& warning : s.warnings) warn_once(warning);
  return s;
}

TurnSignalParameters turn_signal_parameters(const Scenario& scenario) {
  TurnSignalParameters p = scenario.run_params.decider;
  p.base_link_to_front = scenario.ego.base_link_to_front;
  return p;
}

BehaviorSignalParameters behavior_parameters(const Scenario& scenario) {
  BehaviorSignalParameters p =
      behavior_signal_parameters(turn_signal_parameters(scenario), scenario.run_params.behavior);
  p.rear_overhang = scenario.ego.length - scenario.ego.base_link_to_front;
  p.vehicle_width = kObstacleWidth;
  return p;
}

}  // namespace signalsim
