// Seeded perception model between SUMO's true light state and the judge (docs/behaviour.md §L0:
// "Perception model"). SUMO knows the true state; a real vehicle does not. This is how "never
// received", "timed out" and "left out of the message" (docs/behaviour.md §L1.3) happen in a
// simulation. It delivers one of three things a step (SignalDelivery): nothing (no message arrived),
// a message without this light, or the light's observation.
//
// Per call of observe(truth, distance_to_light, now):
//   draw u_drop                                        (one draw per call, if dropout_probability > 0)
//   draw u_omit                                        (one draw per call, if omission_probability > 0)
//   captured := now not in any blackout and |distance_to_light| <= detection_range
//               and not (u_drop < dropout_probability)
//   if captured and (now in an omission or u_omit < omission_probability):
//       queue (due = now + latency, a message without this light, stamp = now)
//   else if captured:
//       for k in 1..detections_per_light, for each true element e (in order):
//           detection := e
//           if misclassification_probability > 0: draw u_mis, u_which;
//               if u_mis < misclassification_probability:
//                   detection.color := another color of {Unknown, Red, Amber, Green}, chosen by u_which
//           if confidence_noise > 0: draw u_conf;
//               detection.confidence := clamp(e.confidence + confidence_noise * (2 u_conf - 1), 0, 1)
//       queue (due = now + latency, observation {detections, stamp = now})
//   deliver the newest queued entry whose due time <= now (older due ones are superseded and
//   dropped); nothing if none is due.
//
// Determinism: four std::mt19937_64 streams (dropout, misclassification, confidence, omission; their
// indices in seeded_stream.hpp), each seeded with splitmix64 of (seed, stream index). The standard
// fixes mt19937_64's output for a given seed, and uniforms are made here from raw 64-bit draws
// ((x >> 11) * 2^-53), so a sequence is identical on every platform and library version. Separate streams keep, e.g., the dropout pattern unchanged
// when only the misclassification probability changes; they are also why a fault that is off may skip
// its draws: its stream feeds nothing else, and a draw could not change its outcome (u < 0 never
// holds, zero noise adds nothing). Times are compared in integer nanoseconds.
//
// With all faults off (the defaults) the true elements pass through unchanged with stamp = now.
#pragma once

#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <random>
#include <vector>

#include "traffic_light/signal_elements.hpp"

namespace signalsim {

struct PerceptionModelParameters {
  /// A closed time interval [start, end] (simulation seconds) in which nothing is captured.
  struct Blackout {
    double start = 0.0;  ///< [s]
    double end = 0.0;    ///< [s], >= start
  };

  std::uint64_t seed = 0;  ///< seeds all random streams
  /// [m] the light is captured only when |distance_to_light| <= detection_range (infinite: always).
  double detection_range = std::numeric_limits<double>::infinity();
  double dropout_probability = 0.0;  ///< [0, 1] probability that a step captures nothing at all
  double latency = 0.0;  ///< [s] >= 0: a capture at t is delivered at the first step with now >= t + latency
  int detections_per_light = 1;  ///< >= 1: detections of every bulb per capture (e.g. cameras)
  /// [-] >= 0: half-width of the uniform noise added to each detection's confidence (then clamped
  /// to [0, 1]); 0 leaves the true confidence untouched.
  double confidence_noise = 0.0;
  /// [0, 1] per detection: probability that its color is replaced by another one of
  /// {Unknown, Red, Amber, Green} (uniformly); the shape is kept.
  double misclassification_probability = 0.0;
  std::vector<Blackout> blackouts;  ///< scheduled blackouts, e.g. occlusion or a camera failure
  /// [0, 1] per captured message: probability that it is delivered without this light (the light is
  /// left out, not unrecognised: docs/behaviour.md §L1.3).
  double omission_probability = 0.0;
  /// Scheduled intervals [start, end] (simulation seconds) in which every captured message is
  /// delivered without this light.
  std::vector<Blackout> omissions;
};

/// What perception delivers for one light group in one step (docs/behaviour.md §L1.3): nothing (both
/// members empty: no message arrived, the last one stays in force), a message without the group
/// (`missing_from_message`), or the group's observation.
struct SignalDelivery {
  std::optional<SignalObservation> observation;  ///< the group as the delivered message holds it
  bool missing_from_message = false;  ///< a message was delivered without the group (observation empty)

  bool delivered() const { return observation.has_value() || missing_from_message; }
  friend bool operator==(const SignalDelivery&, const SignalDelivery&) = default;
};

/// Throws std::invalid_argument naming the first bad member (NaN range, probability outside
/// [0, 1], negative or non-finite latency/noise, detections_per_light < 1, blackout or omission end
/// < start).
void validate(const PerceptionModelParameters& params);

class PerceptionModel {
 public:
  /// Throws std::invalid_argument if validate(params) does.
  explicit PerceptionModel(const PerceptionModelParameters& params = {});

  /// One simulation step (algorithm above). `truth`: the true elements of the light group;
  /// `distance_to_light`: ego to the light [m] (the caller's choice of reference, e.g. to the stop
  /// line); `now`: simulation time [s]. Returns what is delivered this step.
  /// Throws std::invalid_argument if now is not finite, distance_to_light is NaN, or now is earlier
  /// than in the previous call (the state is then unchanged).
  SignalDelivery observe(const std::vector<SignalElement>& truth, double distance_to_light, double now);

  /// Back to the freshly constructed state: streams re-seeded, queue emptied.
  void reset();

  /// Number of captured messages not yet delivered.
  std::size_t pending() const { return queue_.size(); }

  const PerceptionModelParameters& parameters() const { return params_; }

 private:
  struct Pending {
    std::int64_t due_ns;
    SignalDelivery delivery;
  };

  SignalObservation detect(const std::vector<SignalElement>& truth, double now);

  PerceptionModelParameters params_;
  std::int64_t latency_ns_ = 0;
  std::mt19937_64 dropout_rng_;
  std::mt19937_64 misclassification_rng_;
  std::mt19937_64 confidence_rng_;
  std::mt19937_64 omission_rng_;
  std::deque<Pending> queue_;
  std::optional<std::int64_t> last_now_ns_;
};

}  // namespace signalsim
