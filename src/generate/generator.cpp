// generate's loop: walks, rejections, the files, each loaded back as `run` would before it is kept.
#include "generate/generator.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

#include "generate/net_graph.hpp"
#include "core/number_text.hpp"
#include "generate/output_dir.hpp"
#include "scenario/countries.hpp"
#include "report/expectations.hpp"
#include "scenario/input_error.hpp"
#include "step/route_planning.hpp"
#include "session/sumo_session.hpp"

namespace signalsim::generate {
namespace fs = std::filesystem;
namespace {

constexpr std::size_t kMinWalks = 2000;
constexpr std::size_t kWalksPerScenario = 200;

ParameterSet resolved_parameters(const std::string& country) {
  ParameterSet params;  // the schema defaults: Autoware's (config/autoware_defaults.yaml)
  if (!country.empty()) {
    const Country c = load_country(country);
    params.apply(c.parameters, c.path);
  }
  // docs/behaviour.md §T5.2: with persistence the entry request lasts to the exit's end; the rules here do
  // not model that (no preset sets it).
  if (run_parameters(params).decider.turn_signal_roundabout_entry_indicator_persistence)
    throw GenerateError("--country " + country +
                        ": turn_signal_roundabout_entry_indicator_persistence is true, which generate does not model");
  return params;
}

bool wanted(const RouteFeatures& f, const Through& t) {
  return (t.turns && !f.turns.empty()) || (t.lights && !f.lights.empty()) || (t.roundabouts && !f.roundabouts.empty());
}

std::string file_name(const std::string& stem, std::size_t number, std::size_t count) {
  std::string digits = std::to_string(number);
  const std::size_t width = std::max<std::size_t>(4, std::to_string(count).size());
  if (digits.size() < width) digits.insert(0, width - digits.size(), '0');
  return stem + "_" + digits + ".yaml";
}

// The generated file as `run` reads it: a refusal here is a defect of the generator.
void check_loads(const std::string& path, const sumo::NetIndex& net) {
  const Scenario scenario = load_scenario(path);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  check_expectations_apply(scenario, plan.map);
}

}  // namespace

Through parse_through(const std::string& list) {
  Through t{false, false, false};
  std::string item;
  for (const char c : list + ',') {
    if (c != ',') {
      item += c;
      continue;
    }
    if (item == "turns") t.turns = true;
    else if (item == "lights") t.lights = true;
    else if (item == "roundabouts") t.roundabouts = true;
    else throw GenerateError("--through: '" + item + "' is not one of turns, lights, roundabouts");
    item.clear();
  }
  return t;
}

std::string to_string(const Through& t) {
  std::string out;
  for (const auto& [on, name] : {std::pair{t.turns, "turns"}, {t.lights, "lights"}, {t.roundabouts, "roundabouts"}})
    if (on) out += (out.empty() ? "" : ",") + std::string(name);
  return out;
}

std::string net_stem(const std::string& net_path) {
  std::string name = fs::path(net_path).filename().string();
  for (const char* suffix : {".gz", ".xml", ".net"})
    if (name.size() > std::string(suffix).size() && name.ends_with(suffix)) name.resize(name.size() - std::string(suffix).size());
  return name;
}

namespace {

// The options' ranges; throws GenerateError naming the option.
void check_options(const GenerateOptions& o) {
  if (o.count == 0) throw GenerateError("--count must be at least 1");
  if (o.count > kMaxCount) throw GenerateError("--count " + std::to_string(o.count) + ": at most " + std::to_string(kMaxCount));
  if (!std::isfinite(o.scenario.max_speed) || !std::isfinite(o.scenario.straight))
    throw GenerateError("--max-speed and --straight must be finite numbers");
  if (!(o.min_length > 0.0) || !(o.max_length >= o.min_length) || !std::isfinite(o.max_length))
    throw GenerateError("--min-length " + rounded_fixed(o.min_length, 0) + " and --max-length " +
                        rounded_fixed(o.max_length, 0) + ": need 0 < min <= max");
}

// The whole net (the walk graph reads every edge); throws GenerateError when it cannot be read.
sumo::NetIndex load_whole_net(const std::string& path) {
  try {
    return sumo::NetIndex::load(path, sumo::NetReading::Whole);
  } catch (const sumo::NetError& e) {
    throw GenerateError(e.what());
  }
}

// The header lines of a generated file: where it comes from and how its expectations are made.
std::vector<std::string> draft_header(const GenerateOptions& o, std::size_t number, std::size_t walks) {
  return {std::string(kScenarioMarker + 2) + " (route " + std::to_string(number) + ", random walk " +
              std::to_string(walks) + " of seed " + std::to_string(o.seed) + "):",
          "  " + o.command_line,
          "Net: " + o.net + " (net: below is relative to this file). The expectations come from the rules (docs/behaviour.md "
          "§T4-§T6, §T8.2; docs/behaviour.md §L) and the route, never from a run; `signalsim run` on this file checks them."};
}

}  // namespace

GenerateReport generate(const GenerateOptions& o) {
  check_options(o);
  const ParameterSet params = resolved_parameters(o.scenario.country);
  const sumo::NetIndex net = load_whole_net(o.net);
  const RouteGraph graph = graph_of_net(net);
  if (graph.starts().empty())
    throw GenerateError(o.net + ": no edge a passenger car may drive on to another: nothing to generate");
  // signalsim reads more nets than SUMO 1.15 loads (a newer netconvert's vClass 'cable_car', ...):
  // every run would fail, so SUMO itself must load the net.
  if (const std::string error = sumo::net_load_error(o.net); !error.empty())
    throw GenerateError(o.net + ": SUMO cannot load this net, so no scenario on it could run: " + error);
  check_output_dir(o.out_dir);
  bool prepared = false;  // the folder is made (and earlier outputs removed) with the first scenario

  // The net as the files name it: relative to the folder they are in.
  const std::string net_from_dir =
      fs::absolute(o.net).lexically_normal().lexically_relative(fs::absolute(o.out_dir).lexically_normal()).string();
  const std::string stem = net_stem(o.net);
  const std::string candidate = (fs::path(o.out_dir) / kCandidateFile).string();
  Rng rng(o.seed);
  GenerateReport report;
  std::map<std::string, std::size_t> rejected;
  std::set<std::vector<std::string>> seen;
  const std::size_t budget = std::max(kMinWalks, kWalksPerScenario * o.count);
  const bool had_folder = fs::exists(o.out_dir);
  try {
    while (report.files.size() < o.count && report.walks < budget) {
      ++report.walks;
      const auto walk = random_walk(graph, rng, {o.min_length, o.max_length});
      if (!walk) {
        ++rejected["dead end or length out of range"];
        continue;
      }
      std::vector<std::string> edges;
      for (std::size_t e : walk->edges) edges.push_back(graph.edges()[e].id);
      if (!seen.insert(edges).second) {
        ++rejected["route already generated"];
        continue;
      }
      RouteRejection why;
      std::optional<RouteScenario> made = route_scenario(net, net_from_dir, edges, params, o.scenario, candidate, why);
      if (!made) {
        ++rejected[why.reason];
        continue;
      }
      if (!wanted(made->features, o.through)) {
        ++rejected["through none of " + to_string(o.through)];
        continue;
      }
      const std::size_t number = report.files.size() + 1;
      const std::string name = file_name(stem, number, o.count);
      ScenarioDraft& d = made->draft;
      d.name = name.substr(0, name.size() - 5);
      d.description = "generated route " + std::to_string(number) + " on " + stem + ": " +
                      rounded_fixed(made->length, 1) + " m, " + std::to_string(made->features.turns.size()) +
                      " turn(s), " + std::to_string(made->features.lights.size()) + " light(s), " +
                      std::to_string(made->features.roundabouts.size()) + " roundabout(s)";
      const std::vector<std::string> header = draft_header(o, number, report.walks);
      d.header.insert(d.header.begin(), header.begin(), header.end());
      if (!prepared) prepare_output_dir(o.out_dir);
      prepared = true;
      write_file_atomically(candidate, scenario_text(d));
      try {
        check_loads(candidate, net);
      } catch (const InputError& e) {
        throw std::runtime_error(std::string("generate wrote a scenario signalsim refuses (a generator defect): ") + e.what());
      }
      fs::rename(candidate, fs::path(o.out_dir) / name);
      report.files.push_back({name, edges, made->features, made->length, d.expect.size()});
    }
  } catch (...) {
    // No half-written output: the candidate and every file of this run go (earlier outputs are
    // already replaced), and the folder too when this run made it and it is left empty.
    std::error_code ec;
    for (const std::string& f : {candidate, candidate + ".tmp"}) fs::remove(f, ec);
    for (const GeneratedFile& f : report.files) fs::remove(fs::path(o.out_dir) / f.file, ec);
    if (!had_folder && fs::is_empty(o.out_dir, ec)) fs::remove(o.out_dir, ec);
    throw;
  }
  for (const auto& [reason, n] : rejected) report.rejections.push_back({reason, n});
  if (report.files.empty())
    throw GenerateError(o.net + ": no route of " + rounded_fixed(o.min_length, 0) + "-" +
                        rounded_fixed(o.max_length, 0) + " m a passenger car can drive through " +
                        to_string(o.through) + " (" + std::to_string(report.walks) +
                        " random walks tried): nothing to generate");
  write_file_atomically((fs::path(o.out_dir) / kIndexFile).string(), index_text(o, report));
  return report;
}

}  // namespace signalsim::generate
