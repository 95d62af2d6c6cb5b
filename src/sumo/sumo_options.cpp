#include "sumo/sumo_options.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

namespace signalsim::sumo {
namespace {

// SUMO 1.15's synonyms of the options this file knows (`sumo --save-template`, `synonymes=`).
const std::map<std::string, std::string>& synonyms() {
  static const std::map<std::string, std::string> table = {
      {"c", "configuration-file"}, {"configuration", "configuration-file"}, {"C", "save-configuration"},
      {"save-config", "save-configuration"}, {"n", "net-file"}, {"net", "net-file"}, {"r", "route-files"},
      {"routes", "route-files"}, {"a", "additional-files"}, {"additional", "additional-files"},
      {"w", "weight-files"}, {"weights", "weight-files"}, {"b", "begin"}, {"e", "end"},
      {"ndump", "netstate-dump"}, {"netstate", "netstate-dump"}, {"netstate-output", "netstate-dump"},
      {"summary", "summary-output"}, {"tripinfo", "tripinfo-output"}, {"vehroutes", "vehroute-output"},
      {"personroutes", "personroute-output"}, {"statistics-output", "statistic-output"}, {"l", "log"},
      {"log-file", "log"}, {"g", "gui-settings-file"}, {"data-files", "edgedata-files"}, {"Q", "quit-on-end"},
      {"S", "start"}, {"d", "delay"}, {"G", "game"}, {"B", "breakpoints"}, {"D", "demo"},
      {"T", "disable-textures"}, {"?", "help"}, {"V", "version"}, {"abs-rand", "random"},
      {"W", "no-warnings"}, {"suppress-warnings", "no-warnings"}, {"v", "verbose"}};
  return table;
}

struct Owned {
  const char* name;
  const char* reason;
};

// What signalsim sets itself, and why a user may not.
constexpr Owned kOwned[] = {
    {"configuration-file", "give the .sumocfg as the scenario's `sumocfg:`"},
    {"save-configuration", "it makes SUMO write a file and exit"},
    {"save-template", "it makes SUMO write a file and exit"},
    {"save-schema", "it makes SUMO write a file and exit"},
    {"help", "it makes SUMO print and exit"},
    {"version", "it makes SUMO print and exit"},
    {"net-file", "the net is the scenario's `net:` (or its sumocfg's)"},
    {"route-files", "route files are the scenario's `routes:` (or its sumocfg's)"},
    {"additional-files", "additional files are the scenario's `additional:` (or its sumocfg's)"},
    {"step-length", "the step length is the scenario's `step_length:`"},
    {"begin", "the begin time comes from the scenario's sumocfg"},
    {"end", "the end is the scenario's `duration:`"},
    {"seed", "the seed is the scenario's `seed:`"},
    {"random", "the seed is the scenario's `seed:` (runs must be reproducible)"},
    {"remote-port", "signalsim runs SUMO itself, or attaches with --connect"},
    {"num-clients", "signalsim runs SUMO itself, or attaches with --connect"},
    {"log", "signalsim writes SUMO's messages to OUT/sumo.log"},
    {"message-log", "signalsim writes SUMO's messages to OUT/sumo.log"},
    {"error-log", "signalsim writes SUMO's messages to OUT/sumo.log"},
    {"no-warnings", "signalsim counts SUMO's warnings in OUT/sumo.log"},
    {"output-prefix", "it would move signalsim's own files; relative output paths already land in --out"},
    {"lateral-resolution", "signalsim switches SUMO's sublane model on when a maneuver needs it"},
    {"collision.action", "signalsim counts collisions and needs the ego kept (warn)"},
    {"start", "signalsim starts sumo-gui itself (--gui)"},
    {"quit-on-end", "signalsim starts sumo-gui itself (--gui)"},
    {"delay", "use signalsim's --gui-delay"},
    {"demo", "it restarts the simulation"},
    {"game", "it hands the lights to a person"},
    {"breakpoints", "it halts the simulation"},
};

// FILE options of the output category: the files SUMO writes.
constexpr const char* kOutputFiles[] = {
    "netstate-dump", "emission-output", "battery-output", "elechybrid-output", "chargingstations-output",
    "overheadwiresegments-output", "substations-output", "fcd-output", "full-output", "queue-output",
    "vtk-output", "amitran-output", "summary-output", "person-summary-output", "tripinfo-output",
    "vehroute-output", "personroute-output", "link-output", "railsignal-block-output", "bt-output",
    "lanechange-output", "stop-output", "collision-output", "edgedata-output", "lanedata-output",
    "statistic-output", "save-state.prefix", "save-state.files", "device.rerouting.output",
    "device.taxi.dispatch-algorithm.output", "device.taxi.idle-algorithm.output", "gui-testing.setting-output"};

// FILE options SUMO reads (besides the owned net, route and additional files).
constexpr const char* kInputFiles[] = {"weight-files",
                                       "load-state",
                                       "fcd-output.filter-edges.input-file",
                                       "device.ssm.filter-edges.input-file",
                                       "astar.all-distances",
                                       "astar.landmark-distances",
                                       "phemlight-path",
                                       "gui-settings-file",
                                       "edgedata-files"};

constexpr const char* kGuiOnly[] = {"gui-settings-file", "quit-on-end", "game", "game.mode", "start", "delay",
                                    "breakpoints", "edgedata-files", "demo", "disable-textures",
                                    "registry-viewport", "window-size", "window-pos", "tracker-interval",
                                    "osg-view", "gui-testing", "gui-testing-debug", "gui-testing.setting-output"};

template <std::size_t N>
bool listed(const char* const (&names)[N], const std::string& name) {
  return std::any_of(std::begin(names), std::end(names), [&](const char* n) { return name == n; });
}

bool is_option_name(const std::string& token) {
  std::size_t i = 0;
  while (i < token.size() && i < 2 && token[i] == '-') ++i;
  return i > 0 && i < token.size() && (std::isalpha(static_cast<unsigned char>(token[i])) != 0 || token[i] == '?');
}

std::string relative_to(const std::string& dir, const std::string& path) {
  if (path.empty() || dir.empty() || std::filesystem::path(path).is_absolute()) return path;
  return (std::filesystem::path(dir) / path).lexically_normal().string();
}

// A list value ("a.xml,b.xml"): each entry resolved.
std::string each_relative_to(const std::string& dir, const std::string& value) {
  std::string out;
  std::size_t start = 0;
  while (start <= value.size()) {
    const std::size_t comma = value.find(',', start);
    const std::string entry = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out += (out.empty() ? "" : ",") + relative_to(dir, entry);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

std::string canonical_option(const std::string& name) {
  const auto it = synonyms().find(name);
  return it == synonyms().end() ? name : it->second;
}

OptionKind option_kind(const std::string& name, std::string* reason) {
  for (const Owned& o : kOwned)
    if (name == o.name) {
      if (reason) *reason = o.reason;
      return OptionKind::Owned;
    }
  if (listed(kOutputFiles, name)) return OptionKind::OutputFile;
  if (listed(kInputFiles, name)) return OptionKind::InputFile;
  return OptionKind::Other;
}

bool gui_only_option(const std::string& name) { return listed(kGuiOnly, name); }

std::vector<std::string> classified_file_options() {
  std::vector<std::string> out = {"configuration-file", "save-configuration", "save-template", "save-schema",
                                  "net-file", "route-files", "additional-files", "log", "message-log", "error-log"};
  out.insert(out.end(), std::begin(kOutputFiles), std::end(kOutputFiles));
  out.insert(out.end(), std::begin(kInputFiles), std::end(kInputFiles));
  return out;
}

std::vector<SumoOption> parse_sumo_tokens(const std::vector<std::string>& tokens) {
  std::vector<SumoOption> out;
  for (std::size_t i = 0; i < tokens.size(); ++i) {
    const std::string& token = tokens[i];
    if (!is_option_name(token))
      throw SumoOptionError("'" + token + "' is a value without an option before it (write e.g. --fcd-output fcd.xml)");
    SumoOption option;
    std::string name = token.substr(token.rfind("--", 0) == 0 ? 2 : 1);
    if (const auto eq = name.find('='); eq != std::string::npos) {
      option.value = name.substr(eq + 1);
      option.has_value = true;
      name.erase(eq);
    } else if (i + 1 < tokens.size() && !is_option_name(tokens[i + 1])) {
      option.value = tokens[++i];
      option.has_value = true;
    }
    option.name = canonical_option(name);
    out.push_back(option);
  }
  return out;
}

std::vector<std::string> sumo_tokens(const std::vector<SumoOption>& options, const std::string& source,
                                     const std::string& out_dir, const std::string& input_dir, bool gui) {
  std::vector<std::string> out;
  for (const SumoOption& option : options) {
    std::string reason;
    const OptionKind kind = option_kind(option.name, &reason);
    if (kind == OptionKind::Owned)
      throw SumoOptionError(source + ": SUMO option '" + option.name + "' is set by signalsim: " + reason);
    if (gui_only_option(option.name) && !gui) continue;
    std::string value = option.value;
    if (kind == OptionKind::OutputFile) {
      if (!option.has_value || value.empty())
        throw SumoOptionError(source + ": SUMO option '" + option.name + "' needs a file name");
      value = relative_to(out_dir, value);
    } else if (kind == OptionKind::InputFile) {
      value = each_relative_to(input_dir, value);
    }
    out.push_back("--" + option.name);
    if (option.has_value) out.push_back(value);
  }
  return out;
}

}  // namespace signalsim::sumo
