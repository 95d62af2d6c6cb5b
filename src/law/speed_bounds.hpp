// What the law's rules ask of the ego's speed along its route (law/expectation_rules.hpp): the lowest
// speed it can have at a front position (activation of a turn or an entry, docs/behaviour.md §T4.4),
// why, and the highest speed over a stretch (the possible windows' search distances). Two answers:
// the predicted profile of `signalsim generate` (law/speed_profile.hpp) and a run's recorded speeds
// (law/recorded_speed.hpp).
#pragma once

#include <string>

namespace signalsim::law {

class SpeedBounds {
 public:
  virtual ~SpeedBounds() = default;
  /// [m/s] the lowest speed the ego can have with the front at s.
  virtual double lower(double s) const = 0;
  /// Why lower(s) is what it is (for the expectation's comment or the verdict's detail).
  virtual std::string lower_reason(double s) const = 0;
  /// [m/s] the highest speed (without slack) over front positions [from, to].
  virtual double max_planned(double from, double to) const = 0;
};

}  // namespace signalsim::law
