// NetLoader: reads one element of a .net.xml (<edge> with its lanes, <junction>, <connection>,
// <roundabout>, <tlLogic>) into NetData, recording its defects (net_loading.cpp). Whether elements
// are read all at once or on demand, each is read by these functions, once.
// Private to signalsim_sumo.
#pragma once

#include <pugixml.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "net/net_data.hpp"

namespace signalsim::sumo {

class NetLoader {
 public:
  explicit NetLoader(NetData& net) : net_(net), log_(net.log), first_(net.source->first_definitions) {}

  void edge(pugi::xml_node node);
  void junction(pugi::xml_node node);
  void connection(pugi::xml_node node);
  void roundabout(pugi::xml_node node);
  void tl_logic(pugi::xml_node node);

 private:
  std::map<std::string, std::string> params(pugi::xml_node parent, const std::string& owner_what,
                                            const DefectOwner& owner);
  std::optional<double> stop_offset(pugi::xml_node parent, const std::string& owner_what, const DefectOwner& owner);
  NetLane lane(pugi::xml_node node, const NetEdge& edge, const DefectOwner& edge_owner);
  std::vector<std::size_t> lane_order(const XmlElement& e, const NetEdge& edge,
                                      const std::vector<std::optional<int>>& indices);

  NetData& net_;
  DefectLog& log_;
  FirstDefinitions& first_;
};

}  // namespace signalsim::sumo
