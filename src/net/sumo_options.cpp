#include "net/sumo_options.hpp"

#include "core/file_paths.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <map>

namespace signalsim::sumo {
namespace {

// Every synonym of SUMO 1.15's options (`sumo --save-template` and `sumo-gui --save-template`, their
// `synonymes=`; the test sumo_option_table checks the table against the installed SUMO).
const std::map<std::string, std::string>& synonyms() {
  static const std::map<std::string, std::string> table = {
      {"?", "help"}, {"B", "breakpoints"}, {"C", "save-configuration"}, {"D", "demo"}, {"G", "game"},
      {"H", "human-readable-time"}, {"Q", "quit-on-end"}, {"S", "start"}, {"T", "disable-textures"},
      {"V", "version"}, {"W", "no-warnings"}, {"X", "xml-validation"}, {"a", "additional-files"},
      {"abs-rand", "random"}, {"additional", "additional-files"}, {"b", "begin"}, {"c", "configuration-file"},
      {"carfollow.model", "default.carfollowmodel"}, {"configuration", "configuration-file"}, {"d", "delay"},
      {"data-files", "edgedata-files"}, {"device.battery.knownveh", "device.battery.explicit"},
      {"device.bluelight.knownveh", "device.bluelight.explicit"},
      {"device.btreceiver.knownveh", "device.btreceiver.explicit"},
      {"device.btsender.knownveh", "device.btsender.explicit"},
      {"device.driverstate.knownveh", "device.driverstate.explicit"},
      {"device.elechybrid.knownveh", "device.elechybrid.explicit"},
      {"device.emissions.knownveh", "device.emissions.explicit"},
      {"device.example.knownveh", "device.example.explicit"}, {"device.fcd.knownveh", "device.fcd.explicit"},
      {"device.friction.knownveh", "device.friction.explicit"}, {"device.glosa.knownveh", "device.glosa.explicit"},
      {"device.rerouting.knownveh", "device.rerouting.explicit"},
      {"device.routing.adaptation-interval", "device.rerouting.adaptation-interval"},
      {"device.routing.adaptation-steps", "device.rerouting.adaptation-steps"},
      {"device.routing.adaptation-weight", "device.rerouting.adaptation-weight"},
      {"device.routing.period", "device.rerouting.period"},
      {"device.routing.pre-period", "device.rerouting.pre-period"},
      {"device.routing.with-taz", "device.rerouting.with-taz"}, {"device.ssm.knownveh", "device.ssm.explicit"},
      {"device.taxi.knownveh", "device.taxi.explicit"}, {"device.toc.knownveh", "device.toc.explicit"},
      {"device.tripinfo.knownveh", "device.tripinfo.explicit"},
      {"device.vehroute.knownveh", "device.vehroute.explicit"}, {"dump-empty-edges", "netstate-dump.empty-edges"},
      {"dump-precision", "netstate-dump.precision"}, {"e", "end"}, {"g", "gui-settings-file"}, {"l", "log"},
      {"log-file", "log"}, {"measure", "weight-attribute"},
      {"meso.ignore-lanes.by-vclass", "meso-ignore-lanes-by-vclass"}, {"n", "net-file"}, {"ndump", "netstate-dump"},
      {"net", "net-file"}, {"netstate", "netstate-dump"}, {"netstate-output", "netstate-dump"},
      {"netstate-output.empty-edges", "netstate-dump.empty-edges"},
      {"netstate-output.precision", "netstate-dump.precision"},
      {"netstate.empty-edges", "netstate-dump.empty-edges"}, {"netstate.precision", "netstate-dump.precision"},
      {"no-duration-log", "duration-log.disable"},
      {"person-device.btreceiver.knownveh", "person-device.btreceiver.explicit"},
      {"person-device.btsender.knownveh", "person-device.btsender.explicit"},
      {"person-device.fcd.knownveh", "person-device.fcd.explicit"},
      {"person-device.rerouting.knownveh", "person-device.rerouting.explicit"},
      {"person-device.routing.period", "person-device.rerouting.period"}, {"personroutes", "personroute-output"},
      {"r", "route-files"}, {"routes", "route-files"}, {"routing-threads", "device.rerouting.threads"},
      {"s", "route-steps"}, {"save-config", "save-configuration"},
      {"save-config.relative", "save-configuration.relative"}, {"save-template.commented", "save-commented"},
      {"srand", "seed"}, {"statistics-output", "statistic-output"}, {"summary", "summary-output"},
      {"suppress-warnings", "no-warnings"}, {"t", "duration-log.statistics"}, {"tripinfo", "tripinfo-output"},
      {"v", "verbose"}, {"vehroutes", "vehroute-output"}, {"vehroutes.dua", "vehroute-output.dua"},
      {"vehroutes.exit-times", "vehroute-output.exit-times"},
      {"vehroutes.intended-depart", "vehroute-output.intended-depart"},
      {"vehroutes.last-route", "vehroute-output.last-route"},
      {"vehroutes.route-length", "vehroute-output.route-length"}, {"vehroutes.sorted", "vehroute-output.sorted"},
      {"w", "weight-files"}, {"weights", "weight-files"}, {"with-taz", "device.rerouting.with-taz"},
      {"x", "weight-attribute"}};
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
    {"collision.action", "signalsim counts collisions and needs the ego kept (warn)"},
    {"start", "signalsim starts sumo-gui itself (--gui)"},
    {"quit-on-end", "signalsim starts sumo-gui itself (--gui)"},
    {"delay", "use signalsim's --gui-delay"},
    {"demo", "it restarts the simulation"},
    {"game", "it hands the lights to a person"},
    {"breakpoints", "it halts the simulation"},
    {"mesosim", "the decider and the judge need SUMO's microscopic model (lanes, positions, signals)"},
    {"no-internal-links", "turn lanelets are the junctions' internal lanes (docs/behaviour.md §S3)"},
};

// FILE options of the output category: the files SUMO writes.
constexpr const char* kOutputFiles[] = {
    "netstate-dump", "emission-output", "battery-output", "elechybrid-output", "chargingstations-output",
    "overheadwiresegments-output", "substations-output", "fcd-output", "full-output", "queue-output",
    "vtk-output", "amitran-output", "summary-output", "person-summary-output", "tripinfo-output",
    "vehroute-output", "personroute-output", "link-output", "railsignal-block-output", "bt-output",
    "lanechange-output", "stop-output", "collision-output", "edgedata-output", "lanedata-output",
    "statistic-output", "save-state.prefix", "save-state.files", "device.rerouting.output",
    "device.taxi.dispatch-algorithm.output", "device.taxi.idle-algorithm.output", "gui-testing.setting-output",
    // STR options that name output files
    "device.ssm.file", "device.toc.file"};

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

// A list value ("a.xml,b.xml"): each entry resolved.
std::string each_relative_to(const std::string& dir, const std::string& value) {
  std::string out;
  std::size_t start = 0;
  while (start <= value.size()) {
    const std::size_t comma = value.find(',', start);
    const std::string entry = value.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out += (out.empty() ? "" : ",") + resolve_path(dir, entry);
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
  for (std::size_t i = 0; i < options.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (options[i].name == options[j].name)
        throw SumoOptionError(source + ": SUMO option '" + options[i].name + "' is given twice");
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
      value = each_relative_to(out_dir, value);
    } else if (kind == OptionKind::InputFile) {
      value = each_relative_to(input_dir, value);
    }
    out.push_back("--" + option.name);
    if (option.has_value) out.push_back(value);
  }
  return out;
}

}  // namespace signalsim::sumo
