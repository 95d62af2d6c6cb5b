// NetData: what a NetIndex holds: the elements read so far, their lookup tables, the defects, and,
// until the whole net is read, the net's text and where its elements are, to read more (NetSource). The elements are
// read by NetLoader (net_loading.cpp) and on demand by the `read_*` functions (net_on_demand.cpp).
// Private to signalsim_sumo.
#pragma once

#include <atomic>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "net/net_index.hpp"
#include "net/net_source.hpp"
#include "net/net_xml_reading.hpp"

namespace signalsim::sumo {

struct NetData {
  std::string path;
  bool lefthand = false;
  std::size_t edge_count = 0;  ///< edges with an id, the repeated ones once: known from the scan

  // Storage with stable addresses: lookups hand out pointers while more elements are read.
  std::deque<NetEdge> edges;                   // in the order read
  std::vector<std::ptrdiff_t> edge_offsets;    // the file offset of each of `edges`
  std::unordered_map<std::string, std::size_t> edge_by_id;
  std::unordered_map<std::string, std::pair<std::size_t, std::size_t>> lane_by_id;  // edge, lane
  std::unordered_map<std::string, NetJunction> junctions;
  std::unordered_map<std::string, std::vector<NetConnection>> connections_by_from_lane;
  /// The first connection in the file through each internal lane, with its offset.
  std::unordered_map<std::string, std::pair<std::ptrdiff_t, NetConnection>> connection_by_via;
  std::vector<NetRoundabout> roundabouts;
  std::unordered_map<std::string, std::size_t> roundabout_by_edge;
  std::vector<NetTlLogic> tl_logics;
  std::unordered_map<std::string, std::size_t> tl_logic_by_id;
  DefectLog log;

  /// Null once every element is read (then the lookups below need no lock).
  std::unique_ptr<NetSource> source;
  std::atomic<bool> whole = false;
  std::mutex reading;  // held while elements are read, and by lookups until `whole`

  // Built when the whole net is read.
  std::vector<std::reference_wrapper<const NetEdge>> edges_in_file_order;
  std::vector<NetDefect> defects_in_file_order;

  // ---- on demand (net_on_demand.cpp); each is a no-op once the element is read ----
  /// The edge `id`, with every edge before it in the file that defines one of its lane ids.
  void read_edge(const std::string& id);
  /// Every edge defining lane `id`.
  void read_lane(const std::string& id);
  void read_junction(const std::string& id);
  /// Every connection with `from` = `edge_id`.
  void read_connections_from_edge(const std::string& edge_id);
  /// Every connection whose from-lane is `lane_id` ("<from>_<fromLane>").
  void read_connections_from_lane(const std::string& lane_id);
  /// Every connection with `via` = `lane_id`.
  void read_connections_via(const std::string& lane_id);
  /// Everything a defect against this element could come from.
  void read_defects_of(NetElement kind, const std::string& id);
  /// Every element not read yet; then the text is freed.
  void read_whole_net();
  /// After every element is read: the whole-net lists, and the text freed.
  void finish_whole_net();
};

}  // namespace signalsim::sumo
