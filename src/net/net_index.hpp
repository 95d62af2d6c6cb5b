// NetIndex: everything signalsim needs from a SUMO .net.xml (plain or gzip), parsed with pugixml.
//
// libsumo 1.15 has no API for roundabouts, junction types or <stopOffset> (docs/behaviour.md §S2), so the net
// file is read directly. All lookups are hash-map based: O(1) in the size of the net.
//
// Reading on demand: load parses the whole file (so a file that is not XML fails at once) and notes
// where each edge, junction and connection is; then it frees the parsed document and keeps the
// text, and an element's values (lanes, shapes, params, ...) are parsed from its stretch of the text
// when a lookup first needs them (net_source.hpp); light programs and roundabouts are read at load.
// A run reads the elements of its route, a fraction of a city net. Every answer, defects included,
// is the one a reading of the whole file in order gives: a lookup reads everything its answer
// depends on (net_on_demand.cpp). The whole-net queries (edges(), defects()) read the whole net.
// Lookups may be called from several threads (a lock while elements are read). To share one index
// between the runs of a process: load_shared (net_index_cache.hpp).
//
// Loading rule: whatever SUMO 1.15 loads, NetIndex loads. Only a file that is not a net at all (not
// XML, no <net> root, unreadable, a bad `lefthand`) throws NetError. A value signalsim reads that
// cannot be used as written (a number that does not parse, a missing attribute, a malformed shape,
// an unknown `dir`, a repeated id, lane indices that are not 0..n-1 on a normal edge) is recorded as
// a NetDefect against its element, with its line; build_route refuses a route that uses the element.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/polyline.hpp"

namespace signalsim::sumo {

/// Thrown for an unreadable, malformed or inconsistent net. what() = "<file>: <reason>".
class NetError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct NetLane {
  std::string id;                              ///< "<edge>_<index>"
  int index = 0;                               ///< position in NetEdge::lanes, 0 = rightmost
  double speed = 13.89;                        ///< [m/s]
  double length = 0.0;                         ///< [m], the unit of SUMO lane positions
  double width = 3.2;                          ///< [m]
  Polyline shape;
  std::map<std::string, std::string> params;   ///< <param key value>
  double stop_offset = 0.0;                    ///< lane <stopOffset value> (else the edge's) [m]
  bool allows_passenger = true;                ///< from `allow` / `disallow`: a passenger car may use it
  std::string allow, disallow;                 ///< as written (lane_permits: another vehicle class)
};

struct NetEdge {
  std::string id;
  std::string from_junction;                   ///< empty for internal edges
  std::string to_junction;
  bool is_internal = false;                    ///< function="internal"
  std::vector<NetLane> lanes;                  ///< by index
  std::map<std::string, std::string> params;
  double stop_offset = 0.0;                    ///< edge-level <stopOffset value> [m]
  std::string bidi;                            ///< `bidi`: the edge in the other direction on the same road
};

struct NetConnection {
  std::string from_edge;
  std::string to_edge;
  int from_lane = 0;
  int to_lane = 0;
  std::string via;        ///< internal lane id, empty when the net has no internal links
  char dir = 's';         ///< s t T l r L R (T: U-turn in left-hand nets; 'i' invalid)
  char state = 'M';       ///< static link state
  std::string tl;         ///< traffic-light id, empty when unsignalised
  int link_index = -1;    ///< index into the light's state string
};

struct NetRoundabout {
  std::vector<std::string> nodes;
  std::vector<std::string> edges;
};

struct NetPhase {
  double duration = 0.0;
  std::string state;
};

struct NetTlLogic {
  std::string id;
  std::string program_id;
  std::string type;
  double offset = 0.0;
  std::vector<NetPhase> phases;
};

struct NetJunction {
  std::string id;
  std::string type;       ///< priority, traffic_light, internal, dead_end, ...
  double x = 0.0;
  double y = 0.0;
};

/// An element of the net file that cannot be used as written. Recorded at load; fatal only for a
/// route that uses the element (build_route), so a defect elsewhere in a city net costs nothing.
struct NetDefect {
  std::string element;          ///< "lane ':9_17_1'", "connection '12' -> '86'"
  std::string reason;           ///< "attribute 'length' is not a number: 'nan'"
  int line = 0;                 ///< 1-based line of the element in the (inflated) net file
  /// False for a defect in a value no route reads (the lane indices of an internal edge, whose
  /// lanes are found by id): it is listed (inspect) but never refuses a route.
  bool affects_routes = true;
};

/// What a defect is recorded against (its id is the element's id; a connection's is its from-lane).
enum class NetElement { Edge, Lane, Junction, TlLogic };

/// The key of an element in NetIndex's defect lookup.
std::string defect_key(NetElement kind, const std::string& id);

/// Whether a passenger car may use a lane with these `allow` / `disallow` attributes.
bool passenger_allowed(const std::string& allow, const std::string& disallow);
/// Whether vehicles of SUMO class `vclass` ("passenger", "bus", "truck", ...) may use the lane.
bool lane_permits(const NetLane& lane, const std::string& vclass);

class NetIndex;

/// Why SUMO 1.15 cannot drive a vehicle on `edge`, or empty: a bidirectional edge (`bidi`) where it
/// or its partner has more than one lane. SUMO 1.15's MSLane::getBidiLane asserts
/// `bidiEdge->getLanes().size() == 1` and aborts the process (SIGABRT) when a vehicle is inserted
/// on such an edge or enters it (seen on DLR's Doerpfeldstr net; plain `sumo` aborts too).
std::string sumo_cannot_drive(const NetIndex& net, const NetEdge& edge);

struct NetData;

/// How NetIndex::load reads the elements: when a lookup needs them (a run), or all at load (for a
/// whole-net use such as `inspect` or `generate`: the same index, without the scan for on demand).
enum class NetReading { OnDemand, Whole };

class NetIndex {
 public:
  /// Reads `path` (gzip detected by its magic bytes, not its name). Throws NetError.
  static NetIndex load(const std::string& path, NetReading reading = NetReading::OnDemand);
  /// The index of `path` from the process's NetIndexCache (net_index_cache.hpp): loaded once per
  /// process while the file is unchanged, shared by every run on it. Throws NetError as load.
  static std::shared_ptr<const NetIndex> load_shared(const std::string& path);

  NetIndex();  ///< an empty net
  NetIndex(NetIndex&&) noexcept;
  NetIndex& operator=(NetIndex&&) noexcept;
  ~NetIndex();

  const std::string& path() const;
  bool lefthand() const;

  const NetEdge* edge(const std::string& id) const;
  const NetLane* lane(const std::string& id) const;
  /// Edge id of a lane id (the lane must exist).
  const NetEdge* edge_of_lane(const std::string& lane_id) const;
  const NetJunction* junction(const std::string& id) const;

  /// Connections leaving a (normal or internal) lane, in file order.
  const std::vector<NetConnection>& connections_from_lane(const std::string& lane_id) const;
  /// The connection whose via is this internal lane, if any (the first in the file).
  const NetConnection* connection_via(const std::string& internal_lane_id) const;

  const std::vector<NetRoundabout>& roundabouts() const;
  /// Index into roundabouts() of the roundabout listing this (normal) edge, if any.
  std::optional<std::size_t> roundabout_of_edge(const std::string& edge_id) const;

  /// Every program, in file order (several may share an id).
  const std::vector<NetTlLogic>& tl_logics() const;
  /// The first program in the file with this id.
  const NetTlLogic* tl_logic(const std::string& id) const;

  /// Edges with an id (a repeated id counted once), internal ones included.
  std::size_t edge_count() const;
  /// Every edge, internal ones included, in file order (for whole-net indexes such as generate's).
  /// Reads the whole net.
  const std::vector<std::reference_wrapper<const NetEdge>>& edges() const;

  /// Every defect in the net, in file order. Reads the whole net.
  const std::vector<NetDefect>& defects() const;
  /// The first defect that affects routes recorded against this element, or null.
  const NetDefect* defect(NetElement kind, const std::string& id) const;

 private:
  std::unique_ptr<NetData> data_;
};

}  // namespace signalsim::sumo
