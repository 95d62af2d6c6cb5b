#include "scenario/sumo_inputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>

#include "scenario/input_error.hpp"
#include "core/number_parsing.hpp"
#include "core/file_paths.hpp"
#include "net/sumocfg.hpp"

namespace signalsim {
namespace fs = std::filesystem;
namespace {

// The sumo_args tokens, checked now so that a refused option stops the run before SUMO starts.
std::vector<std::string> read_sumo_args(const YamlFields& top, const std::string& path) {
  const std::vector<std::string> tokens = top.text_list("sumo_args");
  try {
    // Owned options are refused here; paths are resolved later, against the run's --out.
    (void)sumo::sumo_tokens(sumo::parse_sumo_tokens(tokens), "sumo_args", "", "", true);
  } catch (const sumo::SumoOptionError& e) {
    throw InputError(path, top.line_of("sumo_args"), e.what(), "sumo_args");
  }
  return tokens;
}

// Whether SUMO's message `reason` is about `option`: it names the option ("option '--name'", "option
// 'name'") or quotes its value ('x'), or ends with it, or names a file the value was resolved to.
bool names_option(const std::string& reason, const sumo::SumoOption& option) {
  const std::string name = sumo::canonical_option(option.name);
  for (const std::string& form : {"option '--" + name + "'", "option '" + name + "'", "option '--" + option.name + "'",
                                  "option '" + option.name + "'"})
    if (reason.find(form) != std::string::npos) return true;
  if (option.value.empty()) return false;
  const std::string& v = option.value;
  if (reason.find("'" + v + "'") != std::string::npos || reason.find("/" + v + "'") != std::string::npos) return true;
  return reason.size() >= v.size() + 1 && reason.compare(reason.size() - v.size() - 1, std::string::npos, " " + v) == 0;
}

// The index of the sumo_args token that gives `option` (its name, or --name=value).
std::size_t token_of(const std::vector<std::string>& tokens, const sumo::SumoOption& option) {
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::size_t start = tokens[i].find_first_not_of('-');
    if (start == 0 || start == std::string::npos) continue;
    const std::string name = tokens[i].substr(start, tokens[i].find('=') - start);
    if (sumo::canonical_option(name) == sumo::canonical_option(option.name)) return i;
  }
  return 0;
}

}  // namespace

std::optional<InputError> sumo_option_error(const Scenario& s, const std::string& message) {
  try {
    const std::vector<sumo::SumoOption> own = sumo::parse_sumo_tokens(s.sumo.sumo_args);
    for (const sumo::SumoOption& option : own)
      if (names_option(message, option)) {
        const std::string key = "sumo_args[" + std::to_string(token_of(s.sumo.sumo_args, option)) + "]";
        return key_error(s, key, "key 'sumo_args': --" + option.name + (option.has_value ? " " + option.value : "") +
                                     ": " + message);
      }
  } catch (const sumo::SumoOptionError&) {  // checked when the scenario was read
  }
  for (std::size_t i = 0; i < s.sumo.cfg_options.size(); ++i)
    if (names_option(message, s.sumo.cfg_options[i]))
      return InputError(s.sumo.sumocfg, i < s.sumo.cfg_option_lines.size() ? s.sumo.cfg_option_lines[i] : 0,
                        "option '" + s.sumo.cfg_options[i].name + "': " + message);
  return std::nullopt;
}

void read_simulation_keys(const YamlFields& top, const std::string& path, Scenario& s) {
  const std::string dir = fs::path(path).parent_path().string();
  s.sumo.scenario_dir = dir;
  std::optional<sumo::SumoConfigFile> cfg;
  if (top.has("sumocfg")) {
    s.sumo.sumocfg = resolve_beside(path, top.text("sumocfg"));
    if (const std::string problem = input_file_problem(s.sumo.sumocfg); !problem.empty())
      top.fail("sumocfg", "file '" + s.sumo.sumocfg + "' " + problem);
    cfg = sumo::read_sumocfg(s.sumo.sumocfg);  // NetError "<cfg>:<line>: ..." for a bad file
    s.sumo.cfg_dir = cfg->dir;
  }
  SumoInputs& in = s.sumo;
  const auto used = [&](const std::string& what) { in.cfg_used.push_back(what); };
  const auto overridden = [&](const std::string& option, const std::string& theirs, const std::string& key,
                              const std::string& ours) {
    in.cfg_overridden.push_back(option + " " + theirs + " -> scenario " + key + " " + ours);
  };

  // The net: the scenario's own key wins over the sumocfg's net-file.
  if (top.has("net")) {
    s.net = resolve_beside(path, top.text("net"));
    if (const std::string problem = input_file_problem(s.net); !problem.empty())
      top.fail("net", "net file '" + s.net + "' " + problem);
    if (cfg && cfg->net) overridden("net-file", *cfg->net, "net", s.net);
  } else if (cfg && cfg->net) {
    s.net = *cfg->net;
    used("net-file " + s.net);
  } else if (cfg) {
    top.fail("sumocfg", "'" + s.sumo.sumocfg + "' names no net-file, and the scenario has no net:");
  } else {
    throw InputError(path, 0, "missing required key 'net' (or 'sumocfg')");
  }

  // Route and additional files: the sumocfg's, then the scenario's.
  if (cfg) {
    in.route_files = cfg->route_files;
    s.additional = cfg->additional;
    for (const std::string& f : cfg->route_files) used("route-files " + f);
    for (const std::string& f : cfg->additional) used("additional-files " + f);
  }
  for (const std::string& r : top.text_list("routes")) {
    in.route_files.push_back(resolve_beside(path, r));
    if (const std::string problem = input_file_problem(in.route_files.back()); !problem.empty())
      top.fail("routes", "file '" + in.route_files.back() + "' " + problem);
  }
  for (const std::string& a : top.text_list("additional")) {
    s.additional.push_back(resolve_beside(path, a));
    if (const std::string problem = input_file_problem(s.additional.back()); !problem.empty())
      top.fail("additional", "file '" + s.additional.back() + "' " + problem);
  }

  // Step length, seed, begin and end.
  s.step_length = cfg && cfg->step_length ? top.number("step_length", *cfg->step_length) : top.number("step_length");
  // SUMO counts time in whole milliseconds and rounds a step length to them, while the planner would
  // integrate the value as written: the two clocks drift apart (0.0015 s ran a red light). Refuse it.
  if (const double ms = s.step_length * 1000.0; std::abs(ms - std::round(ms)) > 1e-6) {
    const std::string reason = short_number(s.step_length) +
                               " s is not a whole number of milliseconds (SUMO would round it to " +
                               short_number(std::max(1.0, std::round(ms)) / 1000.0) + " s)";
    if (top.has("step_length")) top.fail("step_length", reason);
    throw InputError(s.sumo.sumocfg, cfg ? cfg->step_length_line : 0, "step-length " + reason);
  }
  s.seed = cfg && cfg->seed ? top.integer("seed", *cfg->seed) : top.integer("seed");
  if (cfg && cfg->step_length) {
    if (top.has("step_length")) overridden("step-length", short_number(*cfg->step_length), "step_length", short_number(s.step_length));
    else used("step-length " + short_number(s.step_length));
  }
  if (cfg && cfg->seed) {
    if (top.has("seed")) overridden("seed", std::to_string(*cfg->seed), "seed", std::to_string(s.seed));
    else used("seed " + std::to_string(s.seed));
  }
  if (cfg && cfg->begin) {
    in.begin = *cfg->begin;
    used("begin " + short_number(in.begin));
  }
  if (cfg && cfg->end) {
    if (*cfg->end <= in.begin)
      throw InputError(s.sumo.sumocfg, cfg->end_line, "end " + short_number(*cfg->end) + " is not after begin " +
                                                          short_number(in.begin));
    in.end = *cfg->end;
    used("end " + short_number(*in.end));
  }
  // duration: the scenario's; else until the sumocfg's end; else the table's default (60 s).
  s.duration = in.end ? top.number("duration", *in.end - in.begin) : top.number("duration");

  // The sumocfg's other options go on to SUMO, but for those signalsim sets itself.
  if (cfg) {
    for (const sumo::SumoConfigFile::Other& o : cfg->others) {
      std::string reason;
      if (sumo::option_kind(o.option.name, &reason) == sumo::OptionKind::Owned) {
        in.cfg_ignored.push_back(o.option.name + " (line " + std::to_string(o.line) + "): " + reason);
        continue;
      }
      in.cfg_options.push_back(o.option);
      in.cfg_option_lines.push_back(o.line);
    }
  }
  in.sumo_args = read_sumo_args(top, path);
}

}  // namespace signalsim
