// The expectations the rules imply for a route, derived from the rules alone (docs/behaviour.md §T4-§T6, §T8.2;
// docs/behaviour.md §L) and the ego's speed (speed_bounds.hpp), never from running signalsim. SUMO-free.
// `signalsim generate` writes them into scenario files with the predicted speed (speed_profile.hpp); a
// run judges its own record by them with its recorded speeds (recorded_speed.hpp, report/law_verdicts),
// where a lane change approved in the run is guaranteed from its approval until base_link ends the
// motion (sections.hpp maneuver_section) and a roundabout entry with entry persistence may be on to
// the end of its exit.
//
// Per section X (sections.hpp) two stretches of the front bumper's route position:
//   possible   P(X) = [early, desired end]: where X's request can be valid at all
//                early  turn / entry: start - search at the upper speed (or the lanelet's
//                       turn_signal_distance); exit: its desired start (§T5.3); lane change: its
//                       earliest start - max(v_upper * search_time, minimum_search_distance)
//                desired end: base_link leaves X (front at end + base_link_to_front; a lane change
//                       ends before the front leaves its edge)
//   guaranteed G(X) = [late, desired end], narrowed by every other section Y of another side (or a
//              lane change) whose P(Y) overlaps it:
//                late   turn / entry: the front position from which start - s < search at the lower
//                       speed holds for every later s (so the stored desired start, §T4.4, is passed
//                       there whatever the ego's speed); exit: its desired start; never before the
//                       departure
//                Y before X (it starts first): G starts after Y's desired end (Y may win until then)
//                Y after X, by module (§T6.1 RESOLVE takes one request per module):
//                  lane change        G ends before base_link reaches X's start: X's required end
//                                     (§T7) is not before it, and until then PRIOR_WINS keeps X (§T6.2;
//                                     the lane change's required start moves with the ego)
//                  same module        FIRST_ACTIVE pops X at its required end (§T4.3), the same
//                                     bound; but an exit X is hidden by a later entry Y from Y's
//                                     early activation on (entries queue first, §T12.1.7)
//                  other module       PRIOR_WINS keeps X until the front reaches Y's required
//                                     start (Y's start), whichever request is prior (§T6.2)
// Emitted expectations (all numbers rounded inwards to 0.1 m after a kMargin):
//   blinker_through_junction / _lanelet with lead = start - G start, when G covers X to its end and
//   the section is one junction (or lanelet); else blinker_on over G (when at least 1 m); else none.
//   no_blinker over every stretch of at least `straight` metres outside all P and lane changes.
//   blinker_never for a side no section can ask for (hazard always: the ego never backs up);
//   never_runs_red when the route has lights; arrives always.
#pragma once

#include <string>
#include <vector>

#include "core/vehicle_defaults.hpp"
#include "law/sections.hpp"
#include "law/speed_profile.hpp"

namespace signalsim::law {

/// [m] kept from every rule's boundary (numeric noise, the step's discrete positions).
inline constexpr double kMargin = 0.5;
/// [s] the generated scenarios' step_length.
inline constexpr double kStepLength = 0.1;

struct RuleParameters {
  double search_time = 3.0;              ///< turn_signal_search_time [s]
  double minimum_search_distance = 10.0; ///< turn_signal_minimum_search_distance [m]
  double base_link_to_front = vehicle_defaults::kBaseLinkToFront;  ///< [m]
  double straight = 50.0;                ///< [m] shortest stretch given a no_blinker
  double step_length = kStepLength;      ///< [s] the run's step (a stated stretch holds a step)
};

struct LightFact {
  std::string id;       ///< tls id
  double stop_line = 0.0;  ///< route s
};

struct RouteFacts {
  double depart_front = 0.0;  ///< route s of the front at departure
  double route_end = 0.0;     ///< route length [m]
  std::vector<LightFact> lights;
};

struct GeneratedExpectation {
  enum class Kind { ThroughJunction, ThroughLanelet, BlinkerOn, NoBlinker, BlinkerNever, NeverRunsRed, Arrives };
  Kind kind = Kind::Arrives;
  std::string target;       ///< junction or lanelet id
  std::string blinker;      ///< left, right, hazard
  double lead = 0.0;        ///< [m]
  double from_s = 0.0;      ///< [m]
  double to_s = 0.0;        ///< [m]
  std::string why;          ///< where the numbers come from (the file's comment)
  /// The section a blinker expectation serves (index into the sections given); -1 for the others.
  int section = -1;
};

/// One section's stretches, for the file's comment and for tests.
struct SectionWindows {
  double possible_from = 0.0, possible_to = 0.0;
  double guaranteed_from = 0.0, guaranteed_to = 0.0;
  std::string from_why, to_why;
};

struct Derivation {
  std::vector<GeneratedExpectation> expectations;
  std::vector<SectionWindows> windows;  ///< per section, same order as the sections
  std::vector<std::string> notes;       ///< sections left without a blinker expectation, and why
};

Derivation derive_expectations(const std::vector<Section>& sections, const RouteFacts& facts,
                               const SpeedBounds& speed, const RuleParameters& params);

/// Rounding used for every number written: down / up to 0.1 m (with a tolerance of 1e-6).
double floor_tenth(double v);
double ceil_tenth(double v);

}  // namespace signalsim::law
