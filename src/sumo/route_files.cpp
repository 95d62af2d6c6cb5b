#include "sumo/route_files.hpp"

#include <pugixml.hpp>

#include <cctype>
#include <cstring>
#include <sstream>

#include "sumo/net_file.hpp"
#include "sumo/net_index.hpp"
#include "sumo/xml_lines.hpp"

namespace signalsim::sumo {
namespace {

std::vector<std::string> blank_separated(const char* text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

bool is(pugi::xml_node node, const char* name) { return std::strcmp(node.name(), name) == 0; }

}  // namespace

RouteFiles RouteFiles::scan(const std::vector<std::string>& files) {
  RouteFiles out;
  out.files_ = files;
  std::unordered_map<std::string, std::string> route_of;  // vehicle id -> route id to resolve
  for (const std::string& file : files) {
    const std::string text = read_net_file(file);
    const LineIndex lines(text);
    pugi::xml_document doc;
    const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size());
    if (!parsed)
      throw NetError(file + ":" + std::to_string(lines.line_of(parsed.offset)) + ": not XML: " + parsed.description());
    for (pugi::xml_node node : doc.document_element().children()) {
      if (node.type() != pugi::node_element) continue;
      const int line = lines.line_of(node.offset_debug());
      if (is(node, "route")) {
        if (const char* id = node.attribute("id").value(); *id != '\0')
          out.routes_[id] = blank_separated(node.attribute("edges").value());
        continue;
      }
      if (!is(node, "vehicle") && !is(node, "trip") && !is(node, "flow")) continue;
      RouteFileVehicle v;
      v.id = node.attribute("id").value();
      if (v.id.empty()) throw NetError(file + ":" + std::to_string(line) + ": <" + node.name() + "> without an id");
      v.kind = node.name();
      v.file = file;
      v.line = line;
      v.type = node.attribute("type").value();
      v.depart_lane = node.attribute("departLane").value();
      v.depart_pos = node.attribute("departPos").value();
      v.depart_speed = node.attribute("departSpeed").value();
      if (const pugi::xml_node inline_route = node.child("route"))
        v.edges = blank_separated(inline_route.attribute("edges").value());
      else if (const char* route = node.attribute("route").value(); *route != '\0')
        route_of[v.id] = route;
      out.vehicles_.emplace(v.id, std::move(v));  // SUMO itself refuses a second definition of an id
    }
  }
  // `route=` may name a route of another file, or one defined after the vehicle. A route
  // distribution's id is not a route: its vehicles keep no edges (SUMO draws one at departure).
  for (const auto& [vehicle, route] : route_of) {
    const auto it = out.routes_.find(route);
    if (it != out.routes_.end()) out.vehicles_[vehicle].edges = it->second;
  }
  return out;
}

const RouteFileVehicle* RouteFiles::vehicle(const std::string& id) const {
  if (const auto it = vehicles_.find(id); it != vehicles_.end()) return &it->second;
  // A flow's vehicles are "<flow id>.<index>".
  const std::size_t dot = id.rfind('.');
  if (dot == std::string::npos || dot + 1 == id.size()) return nullptr;
  for (std::size_t i = dot + 1; i < id.size(); ++i)
    if (std::isdigit(static_cast<unsigned char>(id[i])) == 0) return nullptr;
  const auto it = vehicles_.find(id.substr(0, dot));
  return it != vehicles_.end() && it->second.kind == "flow" ? &it->second : nullptr;
}

}  // namespace signalsim::sumo
