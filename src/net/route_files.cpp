#include "net/route_files.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <sstream>

#include "net/net_file.hpp"
#include "net/net_index.hpp"

namespace signalsim::sumo {
namespace {

std::vector<std::string> blank_separated(const char* text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

int line_at(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

// One element of a file found by its id attribute: its name, where it starts, and its text.
struct FoundElement {
  std::string name;
  std::size_t start = 0;
  std::string text;  // the element with its children
};

// The elements named one of `names` whose attribute id is `id` (written id="x" or id='x', blanks
// around '=' allowed), in file order. Only the element's own text is cut out for parsing.
std::vector<FoundElement> elements_with_id(const std::string& text, const std::string& id,
                                           std::initializer_list<const char*> names) {
  std::vector<FoundElement> out;
  for (std::size_t at = text.find(id); at != std::string::npos; at = text.find(id, at + 1)) {
    const std::size_t end = at + id.size();
    if (at == 0 || end >= text.size()) continue;
    const char quote = text[at - 1];
    if ((quote != '"' && quote != '\'') || text[end] != quote) continue;
    std::size_t k = at - 1;  // back over '=' and blanks to the attribute name
    while (k > 0 && std::isspace(static_cast<unsigned char>(text[k - 1]))) --k;
    if (k == 0 || text[k - 1] != '=') continue;
    --k;
    while (k > 0 && std::isspace(static_cast<unsigned char>(text[k - 1]))) --k;
    if (k < 3 || text.compare(k - 2, 2, "id") != 0 || !std::isspace(static_cast<unsigned char>(text[k - 3]))) continue;
    const std::size_t open = text.rfind('<', at);
    if (open == std::string::npos || text.find('>', open) < at) continue;  // not inside a start tag
    std::size_t name_end = open + 1;
    while (name_end < text.size() && (std::isalnum(static_cast<unsigned char>(text[name_end])) != 0)) ++name_end;
    const std::string name = text.substr(open + 1, name_end - open - 1);
    if (std::none_of(names.begin(), names.end(), [&](const char* n) { return name == n; })) continue;
    const std::size_t tag_end = text.find('>', end);
    if (tag_end == std::string::npos) continue;
    std::size_t close = tag_end + 1;  // a self-closing tag, or up to its closing tag
    if (text[tag_end - 1] != '/') {
      const std::size_t closing = text.find("</" + name, tag_end);
      const std::size_t closing_end = closing == std::string::npos ? closing : text.find('>', closing);
      // Never closed: the rest of the file, for the parser to name the fault.
      close = closing_end == std::string::npos ? text.size() : closing_end + 1;
    }
    out.push_back({name, open, text.substr(open, close - open)});
  }
  return out;
}

struct LoadedFile {
  std::string path;
  std::string text;
};

pugi::xml_node parse_element(pugi::xml_document& doc, const LoadedFile& file, const FoundElement& e) {
  const pugi::xml_parse_result parsed = doc.load_buffer(e.text.data(), e.text.size());
  if (!parsed)
    throw NetError(file.path + ":" + std::to_string(line_at(file.text, e.start)) + ": <" + e.name +
                   "> is not well-formed XML: " + parsed.description());
  return doc.document_element();
}

// The edges of <route id="route_id"> in any of the files (empty: none, e.g. a route distribution).
std::vector<std::string> named_route(const std::vector<LoadedFile>& files, const std::string& route_id) {
  for (const LoadedFile& f : files)
    for (const FoundElement& e : elements_with_id(f.text, route_id, {"route"})) {
      pugi::xml_document doc;
      return blank_separated(parse_element(doc, f, e).attribute("edges").value());
    }
  return {};
}

// A flow's vehicles are "<flow id>.<index>": the flow's id, when `id` has that form.
std::optional<std::string> flow_of(const std::string& id) {
  const std::size_t dot = id.rfind('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == id.size()) return std::nullopt;
  for (std::size_t i = dot + 1; i < id.size(); ++i)
    if (std::isdigit(static_cast<unsigned char>(id[i])) == 0) return std::nullopt;
  return id.substr(0, dot);
}

}  // namespace

std::optional<RouteFileVehicle> find_route_file_vehicle(const std::vector<std::string>& paths, const std::string& id,
                                                        bool include_flows) {
  if (id.empty()) return std::nullopt;
  std::vector<LoadedFile> files;
  for (const std::string& path : paths) files.push_back({path, read_net_file(path)});
  const std::optional<std::string> flow = include_flows ? flow_of(id) : std::nullopt;
  for (const LoadedFile& f : files) {
    std::vector<FoundElement> found = elements_with_id(f.text, id, {"vehicle", "trip"});
    if (found.empty() && flow) found = elements_with_id(f.text, *flow, {"flow"});
    if (found.empty()) continue;
    const FoundElement& e = found.front();  // SUMO itself refuses a second definition of an id
    pugi::xml_document doc;
    const pugi::xml_node node = parse_element(doc, f, e);
    RouteFileVehicle v;
    v.id = node.attribute("id").value();
    v.kind = e.name;
    v.file = f.path;
    v.line = line_at(f.text, e.start);
    v.type = node.attribute("type").value();
    if (!v.type.empty())
      for (const LoadedFile& t : files) {
        const std::vector<FoundElement> types = elements_with_id(t.text, v.type, {"vType"});
        if (types.empty()) continue;
        pugi::xml_document type_doc;
        if (const char* c = parse_element(type_doc, t, types.front()).attribute("vClass").value(); *c != '\0') v.vclass = c;
        break;
      }
    v.depart = e.name == "flow" ? node.attribute("begin").value() : node.attribute("depart").value();
    v.depart_lane = node.attribute("departLane").value();
    v.depart_pos = node.attribute("departPos").value();
    v.depart_speed = node.attribute("departSpeed").value();
    for (pugi::xml_node stop : node.children("stop")) (void)stop, ++v.stops;
    if (const pugi::xml_node inline_route = node.child("route")) {
      v.edges = blank_separated(inline_route.attribute("edges").value());
      for (pugi::xml_node stop : inline_route.children("stop")) (void)stop, ++v.stops;
    } else if (const char* route = node.attribute("route").value(); *route != '\0') {
      v.edges = named_route(files, route);
    }
    return v;
  }
  return std::nullopt;
}

}  // namespace signalsim::sumo
