#include "session/sumo_command_line.hpp"

#include <algorithm>
#include <sstream>

#include "core/number_parsing.hpp"

namespace signalsim::sumo {
namespace {

std::string joined(const std::vector<std::string>& files) {
  std::string out;
  for (const std::string& f : files) out += (out.empty() ? "" : ",") + f;
  return out;
}

// Whether `extra` sets option `name` (as --name or --name=value).
bool sets(const std::vector<std::string>& extra, const std::string& name) {
  const std::string flag = "--" + name;
  return std::any_of(extra.begin(), extra.end(),
                     [&](const std::string& a) { return a == flag || a.rfind(flag + "=", 0) == 0; });
}

}  // namespace

std::vector<std::string> sumo_command_line(const SessionConfig& config, const std::string& binary) {
  std::vector<std::string> args = {binary, "-n", config.net, "--step-length", exact_number(config.step_length),
                                   "--seed", std::to_string(config.seed), "--collision.action", "warn"};
  if (config.begin != 0.0) args.insert(args.end(), {"--begin", exact_number(config.begin)});
  if (!config.route_files.empty()) args.insert(args.end(), {"-r", joined(config.route_files)});
  if (!config.additional.empty()) args.insert(args.end(), {"-a", joined(config.additional)});
  // Defaults a user may replace through sumo_args.
  const std::pair<const char*, const char*> defaults[] = {
      {"time-to-teleport", "-1"}, {"no-step-log", "true"}, {"duration-log.disable", "true"}};
  for (const auto& [name, value] : defaults)
    if (!sets(config.extra_args, name)) args.insert(args.end(), {std::string("--") + name, value});
  if (config.log_file.empty()) args.insert(args.end(), {"--no-warnings", "true"});
  else args.insert(args.end(), {"--log", config.log_file});
  if (config.lateral_resolution > 0.0 && !sets(config.extra_args, "lateral-resolution"))
    args.insert(args.end(), {"--lateral-resolution", exact_number(config.lateral_resolution)});
  if (config.lane_change_duration > 0.0 && !sets(config.extra_args, "lanechange.duration"))
    args.insert(args.end(), {"--lanechange.duration", exact_number(config.lane_change_duration)});
  args.insert(args.end(), config.extra_args.begin(), config.extra_args.end());
  return args;
}

std::string first_error_line(const std::string& text) {
  std::istringstream in(text);
  std::string line, first_line, error;
  bool in_error = false;
  while (std::getline(in, line)) {
    if (in_error) {
      // SUMO continues a message on lines that start with a blank: one line for the user.
      if (line.empty() || line.front() != ' ') break;
      const auto first = line.find_first_not_of(' ');
      if (first != std::string::npos) error += " " + line.substr(first);
      continue;
    }
    if (line.rfind("Error: ", 0) == 0) {
      error = line.substr(7);
      in_error = true;
      continue;
    }
    if (first_line.empty() && !line.empty() && line.rfind("Warning: ", 0) != 0 && line.front() != ' ')
      first_line = line;
  }
  return in_error ? error : first_line;
}

}  // namespace signalsim::sumo
