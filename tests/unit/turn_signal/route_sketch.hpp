// Synthetic routes for the roundabout tests: lanelets drawn like a turtle (straights and arcs), placed
// on s in order, with SUMO-like ids (":N1_2_0" internal lanes, "r01_0" ring lanes).
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "map/route_map.hpp"
#include "turn_signal/turn_signal_info.hpp"
#include "turn_signal/turn_signal_parameters.hpp"
#include "test_helpers.hpp"  // kB2F

namespace signalsim::test {

class RouteSketch {
 public:
  explicit RouteSketch(Vec2 start = {0.0, 0.0}, double heading = 0.0) : position_(start), heading_(heading) {}

  /// A straight lanelet of `length` metres.
  Lanelet& straight(const std::string& lane_id, double length) {
    std::vector<Vec2> points;
    const int segments = std::max(1, static_cast<int>(std::ceil(length / 5.0)));
    for (int i = 0; i <= segments; ++i) {
      const double d = length * i / segments;
      points.push_back({position_.x + d * std::cos(heading_), position_.y + d * std::sin(heading_)});
    }
    position_ = points.back();
    return add(lane_id, std::move(points));
  }

  /// A circular arc of `radius`, turning `angle_deg` (positive: left / counter-clockwise).
  Lanelet& arc(const std::string& lane_id, double radius, double angle_deg) {
    const double sweep = angle_deg * std::numbers::pi / 180.0;
    const int segments = std::max(4, static_cast<int>(std::ceil(std::abs(sweep) * radius / 0.5)));
    const double sign = sweep >= 0.0 ? 1.0 : -1.0;
    std::vector<Vec2> points;
    for (int i = 0; i <= segments; ++i) {
      const double theta = std::abs(sweep) * i / segments;
      const double along = radius * std::sin(theta);
      const double left = sign * radius * (1.0 - std::cos(theta));
      points.push_back({position_.x + along * std::cos(heading_) - left * std::sin(heading_),
                        position_.y + along * std::sin(heading_) + left * std::cos(heading_)});
    }
    position_ = points.back();
    heading_ += sweep;
    return add(lane_id, std::move(points));
  }

  Lanelet& at(std::size_t index) { return lanelets_.at(index); }
  std::size_t size() const { return lanelets_.size(); }

  RouteMap build() const { return RouteMap(lanelets_); }

 private:
  Lanelet& add(const std::string& lane_id, std::vector<Vec2> points) {
    Lanelet l;
    l.lane_id = lane_id;
    l.edge_id = lane_id.substr(0, lane_id.rfind('_'));
    l.is_internal = !lane_id.empty() && lane_id.front() == ':';
    if (l.is_internal) l.junction_id = l.edge_id.substr(1, l.edge_id.rfind('_') - 1);
    l.shape = Polyline(std::move(points));
    l.length = l.shape.length();
    l.s_start = lanelets_.empty() ? 0.0 : lanelets_.back().s_end();
    l.speed_limit = 8.0;
    lanelets_.push_back(std::move(l));
    return lanelets_.back();
  }

  Vec2 position_;
  double heading_;
  std::vector<Lanelet> lanelets_;
};

constexpr double kApproachLength = 100.0;
constexpr double kOutLength = 100.0;
constexpr double kRingRadius = 20.0;
constexpr double kRingLaneDeg = 80.0;      // a ring lane between two ring junctions
constexpr double kRingInternalDeg = 10.0;  // the internal ring -> ring lane inside a ring junction
constexpr double kTurnRadius = 10.0;       // entry and exit arcs (right turns)
constexpr double kTurnDeg = 60.0;

/// Indices in a sketch made by add_roundabout().
struct RoundaboutIndices {
  std::size_t entry = 0;
  std::vector<std::size_t> ring;           ///< ring lanes and ring internal lanes, in order
  std::vector<std::size_t> ring_lanes;     ///< normal ring lanes only ("r01_0", ...)
  std::size_t exit = 0;
  std::size_t out = 0;                     ///< the normal lane after the exit
};

/// Appends: entry ":N0_0_0" -> ring lane "r01_0" [-> ":N1_2_0" -> "r12_0" ...] -> exit ":N<k>_1_0" ->
/// "out<k>_0" (`out_length` m), for the k-th exit (1-based). With another junction prefix P the ids are
/// ":P0_0_0", "Pr01_0", ..., "Pout<k>_0". An exit branches at every ring junction: ring lanes and ring
/// internal lanes have leaves_ring_at_end, as sumo/route_builder sets it.
/// The entry takes `approach_params` (the params of the approach lane, docs/behaviour.md §S3).
inline RoundaboutIndices add_roundabout(RouteSketch& sketch, int exit_number, const std::string& ring_id = "0",
                                        const std::string& prefix = "N",
                                        const std::map<std::string, std::string>& approach_params = {},
                                        double out_length = kOutLength) {
  RoundaboutIndices ix;
  const auto ring = [&](Lanelet& l, RoundaboutRole role) {
    l.roundabout_role = role;
    l.roundabout_id = ring_id;
    return &l;
  };
  const std::string normal = prefix == "N" ? "" : prefix;  // normal-lane prefix of a second roundabout
  ix.entry = sketch.size();
  Lanelet* entry = ring(sketch.arc(":" + prefix + "0_0_0", kTurnRadius, -kTurnDeg), RoundaboutRole::Entry);
  entry->params = approach_params;
  entry->turn_direction = TurnDirection::Right;
  for (int k = 1; k <= exit_number; ++k) {
    if (k > 1) {
      ix.ring.push_back(sketch.size());
      Lanelet* node = ring(sketch.arc(":" + prefix + std::to_string(k - 1) + "_2_0", kRingRadius, kRingInternalDeg),
                           RoundaboutRole::Internal);
      node->turn_direction = TurnDirection::Straight;
      node->leaves_ring_at_end = true;  // its junction has an exit (as sumo/route_builder marks it)
    }
    ix.ring.push_back(sketch.size());
    ix.ring_lanes.push_back(sketch.size());
    const std::string lane = normal + "r" + std::to_string(k - 1) + std::to_string(k) + "_0";
    ring(sketch.arc(lane, kRingRadius, kRingLaneDeg), RoundaboutRole::Internal)->leaves_ring_at_end = true;
  }
  ix.exit = sketch.size();
  ring(sketch.arc(":" + prefix + std::to_string(exit_number) + "_1_0", kTurnRadius, -kTurnDeg), RoundaboutRole::Exit)
      ->turn_direction = TurnDirection::Right;
  ix.out = sketch.size();
  sketch.straight(normal + "out" + std::to_string(exit_number) + "_0", out_length);
  return ix;
}

/// The standard route: approach "in0_0" (100 m), one roundabout, leaving at the k-th exit.
struct RoundaboutRoute {
  RouteSketch sketch;
  RoundaboutIndices ix;
};

inline RoundaboutRoute roundabout_route(int exit_number, const std::map<std::string, std::string>& approach_params = {}) {
  RoundaboutRoute r;
  Lanelet& approach = r.sketch.straight("in0_0", kApproachLength);
  approach.params = approach_params;
  r.ix = add_roundabout(r.sketch, exit_number, "0", "N", approach_params);
  return r;
}

/// Parameters with a given roundabout configuration; base_link_to_front 3.7 m (the default).
inline TurnSignalParameters roundabout_params(const std::string& on_entry, const std::string& on_exit,
                                              bool persistence = false) {
  TurnSignalParameters p;
  p.turn_signal_roundabout_on_entry = on_entry;
  p.turn_signal_roundabout_on_exit = on_exit;
  p.turn_signal_roundabout_entry_indicator_persistence = persistence;
  return p;
}

inline EgoOnRoute sketch_ego_front(double s_front, double speed = 0.0) {
  return EgoOnRoute{.s_front = s_front, .s_base = s_front - kB2F, .speed = speed};
}
inline EgoOnRoute sketch_ego_base(double s_base, double speed = 0.0) {
  return EgoOnRoute{.s_front = s_base + kB2F, .s_base = s_base, .speed = speed};
}

}  // namespace signalsim::test
