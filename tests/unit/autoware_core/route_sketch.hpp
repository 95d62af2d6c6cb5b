// Synthetic routes for the autoware_core plugin's tests, in the C ABI's vocabulary: straight lanes
// and circular arcs chained end to end, placed on s, as the ss_lanelet array an ss_run carries.
#pragma once

#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "signalsim/decider_plugin.h"

namespace signalsim::test {

class RouteSketch {
 public:
  /// A straight lane of `length` [m] with `points` centerline points.
  RouteSketch& straight(const std::string& id, double length, ss_turn_direction turn = SS_TURN_NONE,
                        ss_roundabout_role role = SS_ROUNDABOUT_NONE, int points = 2) {
    std::vector<ss_point> line;
    for (int k = 0; k < points; ++k) {
      const double d = length * k / (points - 1);
      line.push_back({x_ + d * std::cos(heading_), y_ + d * std::sin(heading_)});
    }
    return add(id, line, turn, role);
  }

  /// A circular arc of `radius` [m] turning `angle_deg` (left positive) with `points` points.
  RouteSketch& arc(const std::string& id, double radius, double angle_deg, int points,
                   ss_turn_direction turn = SS_TURN_NONE, ss_roundabout_role role = SS_ROUNDABOUT_NONE) {
    const double sign = angle_deg > 0 ? 1.0 : -1.0;
    const double cx = x_ - sign * radius * std::sin(heading_), cy = y_ + sign * radius * std::cos(heading_);
    std::vector<ss_point> line;
    for (int k = 0; k < points; ++k) {
      const double h = heading_ + angle_deg * kDeg * k / (points - 1);
      line.push_back({cx + sign * radius * std::sin(h), cy - sign * radius * std::cos(h)});
    }
    heading_ += angle_deg * kDeg;
    return add(id, line, turn, role);
  }

  /// The lanelet added last gets the turn_signal_distance attribute.
  RouteSketch& turn_signal_distance(double metres) {
    lanes_.back().turn_signal_distance = metres;
    return *this;
  }

  /// Route s of a lanelet's start.
  double s_start(const std::string& id) const {
    for (const ss_lanelet& l : lanes_) {
      if (id == l.id) return l.s_start;
    }
    return NAN;
  }

  /// The ss_run of this route (valid while the sketch lives and is not changed).
  ss_run run(double base_link_to_front = 3.7) const {
    ss_run r{};
    r.scenario = "sketch";
    r.step_length = 0.1;
    r.vehicle_length = 4.5;
    r.base_link_to_front = base_link_to_front;
    r.lanelets = lanes_.data();
    r.lanelet_count = lanes_.size();
    return r;
  }

  /// Clears every roundabout role (to show the rule does not read them).
  RouteSketch without_roundabout_roles() const {
    RouteSketch copy = *this;
    for (std::size_t i = 0; i < copy.lanes_.size(); ++i) {
      copy.lanes_[i].roundabout_role = SS_ROUNDABOUT_NONE;
      copy.lanes_[i].centerline = copy.lines_[i].data();
      copy.lanes_[i].id = copy.ids_[i].c_str();
      copy.lanes_[i].edge_id = copy.lanes_[i].id;
    }
    return copy;
  }

 private:
  static constexpr double kDeg = 3.14159265358979323846 / 180.0;

  RouteSketch& add(const std::string& id, const std::vector<ss_point>& line, ss_turn_direction turn,
                   ss_roundabout_role role) {
    ids_.push_back(id);
    lines_.push_back(line);
    double length = 0.0;
    for (std::size_t k = 1; k < line.size(); ++k) {
      length += std::hypot(line[k].x - line[k - 1].x, line[k].y - line[k - 1].y);
    }
    ss_lanelet l{};
    l.id = ids_.back().c_str();
    l.edge_id = l.id;
    l.junction_id = "";
    l.s_start = s_;
    l.s_end = s_ + length;
    l.length = length;
    l.speed_limit = 13.89;
    l.turn_direction = turn;
    l.roundabout_role = role;
    l.roundabout_id = "";
    l.turn_signal_distance = NAN;
    l.centerline = lines_.back().data();
    l.centerline_size = lines_.back().size();
    lanes_.push_back(l);
    s_ += length;
    x_ = line.back().x;
    y_ = line.back().y;
    return *this;
  }

  std::deque<std::string> ids_;
  std::deque<std::vector<ss_point>> lines_;
  std::vector<ss_lanelet> lanes_;
  double x_ = 0.0, y_ = 0.0, heading_ = 0.0, s_ = 0.0;
};

}  // namespace signalsim::test
