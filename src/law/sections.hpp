// The stretches of a route that ask for a blinker, as the law reads them from the rules
// (docs/behaviour.md §T4, §T5, §T8.2) and the route's lanelets (docs/behaviour.md §S3). SUMO-free and pure.
// The turns and roundabout connections are the decider's own (turn_signal/signal_sections.hpp).
//
//   turn              a group of consecutive turn lanelets (left/right) outside roundabouts, the
//                     grouping of docs/behaviour.md §T4.2; the intersection module's request (search distance
//                     turn_signal_intersection_search_distance, or the front lanelet's
//                     turn_signal_distance)
//   roundabout_entry  consecutive entry lanelets of one roundabout; the roundabout module's entry
//                     request (§T5.2): turn_signal_roundabout_on_entry, or left/right when the entry's
//                     exit_turn_signal_left/right lists the exit the route takes; none: no request
//   roundabout_exit   consecutive exit lanelets; turn_signal_roundabout_on_exit from the front
//                     reaching the start of the enable_exit_turn_signal chain before it (§T5.3; Japan's
//                     previous-exit marking sets that chain, turn_signal/exit_signal_marking)
//   lane_change       a lane change the route needs (behaviour module, §T8.2): its blinker may be on
//                     (either side) from max(v * turn_signal_search_time,
//                     turn_signal_minimum_search_distance) before its earliest start until the front
//                     leaves its edge
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "map/route_map.hpp"

namespace signalsim::law {

enum class Side { None, Left, Right, Either };  ///< Either: a lane change (its side is not modelled)
const char* to_string(Side side);               ///< "none", "left", "right", "either"

enum class SectionKind { Turn, RoundaboutEntry, RoundaboutExit, LaneChange };
const char* to_string(SectionKind kind);        ///< "turn", "roundabout_entry", ...

/// The request module a section belongs to (docs/behaviour.md §T3.2: I, Rb, B).
enum class Module { Intersection, Roundabout, Behavior };
Module module_of(SectionKind kind);

/// What blinker_through_* can name for a section (the expectation spans).
struct SpanTarget {
  std::string junction;  ///< the section is exactly the route's one stretch through this junction
  std::string lanelet;   ///< else: the section is this one lanelet (on the route once)
};

struct Section {
  SectionKind kind = SectionKind::Turn;
  Side side = Side::None;
  std::string id;                     ///< junction id (turns, roundabouts), edge id (lane change)
  std::vector<std::string> lanelets;  ///< lane ids in route order (lane change: the edge's lane)
  double start = 0.0;                 ///< route s of the first lanelet's start [m] (lane change: the edge's)
  double end = 0.0;                   ///< route s of the last lanelet's end [m]
  SpanTarget target;
  /// Turn / entry: the search distance's constant part [m] and whether the lanelet overrides the
  /// whole search distance (turn_signal_distance, docs/behaviour.md §T4.3).
  double search_distance = 30.0;
  std::optional<double> search_override;
  /// Entry with entry_persistence: route s of the end of the exit the route takes (its desired end).
  std::optional<double> persistent_end;
  /// Exit: route s where its desired start lies (the enable_exit_turn_signal chain, else its start).
  double exit_desired_start = 0.0;
  /// Lane change: base_link's earliest start of the lateral motion (route s) [m]. A run's other
  /// maneuvers: the start of their lateral motion.
  double lane_change_at = 0.0;
  /// A run's maneuver (maneuver_section): its kind ("lane_change", "avoidance", "pull_out",
  /// "pull_over"), where base_link ends its lateral motion [m], and for a lane change approved in
  /// the run, the front's route s at its approval [m]; unset for the generator's sections.
  std::string maneuver;
  std::optional<double> motion_end;
  std::optional<double> approval_front;
};

struct SectionParameters {
  double intersection_search_distance = 30.0;  ///< turn_signal_intersection_search_distance [m]
  double roundabout_search_distance = 30.0;    ///< turn_signal_roundabout_search_distance [m]
  std::string on_entry = "None";               ///< turn_signal_roundabout_on_entry
  std::string on_exit = "Left";                ///< turn_signal_roundabout_on_exit
  /// turn_signal_roundabout_entry_indicator_persistence: an entry's request lasts to the end of the
  /// exit the route takes (docs/behaviour.md §T5.2), so its blinker may be on that far.
  bool entry_persistence = false;
};

/// A lane change the route's lane plan needs (scenario/route_planning LateralSegment).
struct LaneChangeFact {
  std::string edge;
  std::string lane;           ///< its planned lane
  double at = 0.0;            ///< base_link's earliest start of the lateral motion, route s [m]
  double edge_start = 0.0;    ///< route s of the edge's start [m]
  double edge_end = 0.0;      ///< route s of the edge's end [m]
};

/// A maneuver a run executed (report/law_verdicts reads it from the run's record).
struct ManeuverFact {
  std::string kind;                     ///< "lane_change", "avoidance", "pull_out", "pull_over"
  std::string edge, lane;               ///< the edge it is driven on, its lanelet
  Side side = Side::None;               ///< the motion's direction (left: moving left)
  double motion_start = 0.0;            ///< [m] base_link route s where the lateral motion starts
  double motion_end = 0.0;              ///< [m] where it ends
  double edge_start = 0.0, edge_end = 0.0;  ///< [m] route s of the edge's lanelet
  std::optional<double> approval_front;  ///< [m] lane change: the front's s at its approval
};

/// A run's maneuver as a section: a lane change approved in the run has its side and a guaranteed
/// stretch from its approval until base_link ends the motion (docs/behaviour.md §T8.2: the module
/// signals from before its approval until base_link passes the lateral end); any other maneuver (and
/// a lane change never approved) has side Either: only where its blinker may be on.
Section maneuver_section(const ManeuverFact& m);

/// Every section of the route, sorted by start (ties: route order). `route` must carry the
/// exit-signal marking when the parameters ask for it (scenario/route_planning prepare_route).
std::vector<Section> route_sections(const RouteMap& route, const SectionParameters& params,
                                    const std::vector<LaneChangeFact>& lane_changes);

}  // namespace signalsim::law
