#include "net/sumocfg.hpp"

#include <pugixml.hpp>

#include <cstdlib>
#include <functional>
#include <filesystem>

#include "core/file_paths.hpp"
#include "net/net_file.hpp"
#include "net/net_index.hpp"
#include "core/number_parsing.hpp"
#include "net/xml_lines.hpp"

namespace signalsim::sumo {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> split_list(const std::string& value) {
  // SUMO file lists are comma separated (blanks around entries are allowed).
  std::vector<std::string> out;
  std::string entry;
  const auto flush = [&] {
    const auto first = entry.find_first_not_of(" \t\r\n");
    if (first != std::string::npos) out.push_back(entry.substr(first, entry.find_last_not_of(" \t\r\n") - first + 1));
    entry.clear();
  };
  for (char c : value) {
    if (c == ',') flush();
    else entry += c;
  }
  flush();
  return out;
}

// SUMO replaces ${NAME} in option values by the environment variable NAME. `unknown`: the first
// variable that is not set.
std::string with_environment(const std::string& value, std::string& unknown) {
  std::string out;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const std::size_t close = value.compare(i, 2, "${") == 0 ? value.find('}', i + 2) : std::string::npos;
    if (close == std::string::npos) {
      out += value[i];
      continue;
    }
    const std::string name = value.substr(i + 2, close - i - 2);
    const char* set = std::getenv(name.c_str());
    if (set == nullptr && unknown.empty()) unknown = name;
    out += set ? set : "";
    i = close;
  }
  return out;
}

}  // namespace

SumoConfigFile read_sumocfg(const std::string& path) {
  const std::string text = read_net_file(path);
  const LineIndex lines(text);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
  if (!parsed)
    throw NetError(path + ":" + std::to_string(lines.line_of(parsed.offset)) + ": not XML: " + parsed.description());
  const pugi::xml_node root = doc.document_element();
  const std::string root_name = root.name();
  if (root_name != "configuration" && root_name != "sumoConfiguration")
    throw NetError(path + ":" + std::to_string(lines.line_of(root.offset_debug())) +
                   ": not a SUMO configuration (root <" + root_name + ">, expected <configuration>)");

  SumoConfigFile cfg;
  cfg.path = path;
  cfg.dir = fs::path(path).parent_path().string();
  const auto resolve = [&](const std::string& name) { return resolve_beside(path, name); };
  // Options are elements with a value (SUMO's categories are optional: a flat file works too).
  std::vector<pugi::xml_node> options;  // in file order
  const std::function<void(pugi::xml_node)> collect = [&](pugi::xml_node parent) {
    for (pugi::xml_node e : parent.children()) {
      if (e.type() != pugi::node_element) continue;
      if (e.attribute("value") || e.attribute("v")) options.push_back(e);
      else collect(e);
    }
  };
  collect(root);
  for (pugi::xml_node element : options) {
    const int line = lines.line_of(element.offset_debug());
    const auto fail = [&](const std::string& reason) -> void {
      throw NetError(path + ":" + std::to_string(line) + ": " + reason);
    };
    const pugi::xml_attribute value_attribute = element.attribute("value") ? element.attribute("value")
                                                                            : element.attribute("v");
    const std::string name = canonical_option(element.name());
    std::string unknown;
    const std::string value = with_environment(value_attribute.value(), unknown);
    if (!unknown.empty()) fail("option '" + name + "': environment variable '" + unknown + "' is not set");
    const auto number = [&]() {
      const auto v = parse_double(value);
      if (!v) fail("option '" + name + "' is not a number: '" + value + "'");
      return *v;
    };
    const auto existing = [&](const std::string& file) {
      const std::string resolved = resolve(file);
      if (const std::string problem = input_file_problem(resolved); !problem.empty())
        fail("option '" + name + "': file '" + resolved + "' " + problem);
      return resolved;
    };
    if (name == "net-file") {
      cfg.net = existing(value);
    } else if (name == "route-files") {
      for (const std::string& f : split_list(value)) cfg.route_files.push_back(existing(f));
    } else if (name == "additional-files") {
      for (const std::string& f : split_list(value)) cfg.additional.push_back(existing(f));
    } else if (name == "begin") {
      cfg.begin = number();
    } else if (name == "end") {
      cfg.end = number();
      cfg.end_line = line;
    } else if (name == "step-length") {
      cfg.step_length = number();
      cfg.step_length_line = line;
    } else if (name == "seed") {
      const auto seed = parse_int(value);
      if (!seed) fail("option 'seed' is not an integer: '" + value + "'");
      cfg.seed = *seed;
    } else {
      cfg.others.push_back({SumoOption{name, value, true}, line});
    }
  }
  return cfg;
}

}  // namespace signalsim::sumo
