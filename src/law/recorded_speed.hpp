// A run's speeds as the law's rules read them (law/speed_bounds.hpp): the speed the ego had at each
// recorded step, by the front's route position. lower(s) is the least speed of the steps bracketing s
// (at a position where the ego stood, 0), so a rule's activation scan never assumes more speed than
// the decider saw at any step; max_planned(from, to) the greatest speed of the steps in and around
// [from, to]. Queries are binary searches on the samples sorted by position.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "law/speed_bounds.hpp"

namespace signalsim::law {

class RecordedSpeed : public SpeedBounds {
 public:
  /// One (front position [m], speed [m/s]) per recorded step, in any order.
  explicit RecordedSpeed(std::vector<std::pair<double, double>> samples);

  double lower(double s) const override;
  std::string lower_reason(double s) const override;
  double max_planned(double from, double to) const override;

 private:
  std::pair<std::size_t, std::size_t> bracket(double from, double to) const;  // sample index range
  std::vector<double> s_, v_;
};

}  // namespace signalsim::law
