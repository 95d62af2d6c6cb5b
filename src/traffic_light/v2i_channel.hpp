// The V2I channel: SUMO's predictions of a light (docs/behaviour.md §L1.7 `predictions[]`) delivered to the
// judge through a seeded fault model of the same kind as the camera's (perception_model.hpp), with
// the faults a radio link has: per-step dropout, latency and scheduled blackouts.
//
// Per call of step(predictions, now):
//   draw u_drop                                        (one draw per call, always)
//   captured := now not in any blackout and not (u_drop < dropout_probability)
//   if captured: queue (due = now + latency, message {predictions, stamp = now})
//   the newest queued message whose due time <= now is delivered and kept (older due ones dropped)
//   in force := the kept message while now - its stamp <= max_age, else nothing
//   return the predictions in force (empty: V2I says nothing this step)
//
// A lost channel never makes the judge stop by itself: it only takes the predictions away, so the
// judge decides on the camera alone (the kept message stops counting once older than max_age,
// the judge's tl_state_timeout). The stamps inside a message are absolute, so a late message tells
// the same switch times, with less time left. Determinism: its own std::mt19937_64 stream (index 4
// of the seed, see seeded_stream.hpp): the camera's streams are untouched whether V2I is on or off.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "traffic_light/perception_model.hpp"
#include "traffic_light/signal_elements.hpp"

namespace signalsim {

struct V2iChannelParameters {
  std::uint64_t seed = 0;              ///< seeds the dropout stream
  double dropout_probability = 0.0;    ///< [0, 1] a step's message is lost
  double latency = 0.0;                ///< [s] >= 0: a message sent at t arrives at the first step with now >= t + latency
  std::vector<PerceptionModelParameters::Blackout> blackouts;  ///< [s] nothing sent in these closed intervals
  double max_age = 1.0;                ///< [s] a delivered message counts while now - stamp <= max_age
};

/// Throws std::invalid_argument naming the first bad member.
void validate(const V2iChannelParameters& params);

class V2iChannel {
 public:
  /// Throws std::invalid_argument if validate(params) does.
  explicit V2iChannel(const V2iChannelParameters& params = {});

  /// One step (algorithm above). Throws std::invalid_argument if now is not finite or earlier than
  /// in the previous call (the state is then unchanged).
  std::vector<SignalPrediction> step(const std::vector<SignalPrediction>& predictions, double now);

  /// The stamp (send time) of the message in force after the last step, if any.
  std::optional<double> stamp_in_force() const { return in_force_stamp_; }

  const V2iChannelParameters& parameters() const { return params_; }

 private:
  struct Message {
    std::int64_t due_ns = 0;
    std::int64_t stamp_ns = 0;
    double stamp = 0.0;
    std::vector<SignalPrediction> predictions;
  };
  V2iChannelParameters params_;
  std::int64_t latency_ns_ = 0;
  std::int64_t max_age_ns_ = 0;
  std::mt19937_64 dropout_rng_;
  std::deque<Message> queue_;
  std::optional<Message> kept_;
  std::optional<double> in_force_stamp_;
  std::optional<std::int64_t> last_now_ns_;
};

}  // namespace signalsim
