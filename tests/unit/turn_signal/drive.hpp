// Drives a TurnSignalDecider along a route in small steps, as the step loop does.
#pragma once

#include <algorithm>

#include "route_sketch.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim::test {

class Drive {
 public:
  Drive(const RouteMap& route, TurnSignalParameters params, double s_front = 0.0, double speed = 0.0)
      : route_(route), decider_(std::move(params)), s_front_(s_front), speed_(speed) {
    last_ = decider_.decide(route_, sketch_ego_front(s_front_, speed_));
  }

  /// Steps the front forward to `s_front` (at most `step` metres per cycle) and returns the decision
  /// of the last cycle, taken exactly at `s_front`.
  const TurnSignalDecision& to_front(double s_front, double step = 0.5) {
    while (s_front_ < s_front) {
      s_front_ = std::min(s_front, s_front_ + step);
      last_ = decider_.decide(route_, sketch_ego_front(s_front_, speed_));
    }
    return last_;
  }
  const TurnSignalDecision& to_base(double s_base, double step = 0.5) { return to_front(s_base + kB2F, step); }

  const TurnSignalDecision& last() const { return last_; }
  const TurnSignalDecider& decider() const { return decider_; }
  void set_speed(double speed) { speed_ = speed; }

 private:
  const RouteMap& route_;
  TurnSignalDecider decider_;
  double s_front_;
  double speed_;
  TurnSignalDecision last_;
};

}  // namespace signalsim::test
