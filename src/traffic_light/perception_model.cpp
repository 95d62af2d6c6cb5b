// The perception model's faults (algorithm in perception_model.hpp): per step, nothing, a message
// without the light, or the light's detections, delivered after the latency.
#include "traffic_light/perception_model.hpp"

#include "core/time_ns.hpp"
#include "traffic_light/seeded_stream.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace signalsim {

namespace {

using seeded::stream_seed;
using seeded::uniform01;

constexpr std::array<SignalColor, 4> kConfusableColors = {SignalColor::Unknown, SignalColor::Red, SignalColor::Amber,
                                                          SignalColor::Green};

SignalColor other_color(SignalColor truth, double u) {
  std::array<SignalColor, 4> choices{};
  std::size_t n = 0;
  for (SignalColor c : kConfusableColors) {
    if (c != truth) choices[n++] = c;
  }
  const auto index = std::min(static_cast<std::size_t>(u * static_cast<double>(n)), n - 1);
  return choices[index];
}

void validate_intervals(const std::vector<PerceptionModelParameters::Blackout>& intervals, const char* name) {
  for (std::size_t i = 0; i < intervals.size(); ++i) {
    const auto& b = intervals[i];
    if (!std::isfinite(b.start) || !std::isfinite(b.end) || b.end < b.start) {
      throw std::invalid_argument(std::string("perception parameter ") + name + "[" + std::to_string(i) +
                                  "] must be finite with start <= end");
    }
  }
}

bool in_any(const std::vector<PerceptionModelParameters::Blackout>& intervals, std::int64_t now_ns) {
  return std::any_of(intervals.begin(), intervals.end(),
                     [&](const auto& b) { return to_ns(b.start) <= now_ns && now_ns <= to_ns(b.end); });
}

}  // namespace

void validate(const PerceptionModelParameters& p) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("perception parameter " + what); };
  if (std::isnan(p.detection_range) || p.detection_range < 0.0) fail("detection_range must be >= 0");
  if (!(p.dropout_probability >= 0.0 && p.dropout_probability <= 1.0)) fail("dropout_probability must be in [0, 1]");
  if (!std::isfinite(p.latency) || p.latency < 0.0) fail("latency must be finite and >= 0");
  if (p.detections_per_light < 1) fail("detections_per_light must be >= 1");
  if (!std::isfinite(p.confidence_noise) || p.confidence_noise < 0.0) fail("confidence_noise must be finite and >= 0");
  if (!(p.misclassification_probability >= 0.0 && p.misclassification_probability <= 1.0)) {
    fail("misclassification_probability must be in [0, 1]");
  }
  validate_intervals(p.blackouts, "blackouts");
  if (!(p.omission_probability >= 0.0 && p.omission_probability <= 1.0)) fail("omission_probability must be in [0, 1]");
  validate_intervals(p.omissions, "omissions");
}

PerceptionModel::PerceptionModel(const PerceptionModelParameters& params) : params_(params) {
  validate(params_);
  latency_ns_ = to_ns(params_.latency);
  reset();
}

void PerceptionModel::reset() {
  dropout_rng_.seed(stream_seed(params_.seed, seeded::kCameraDropoutStream));
  misclassification_rng_.seed(stream_seed(params_.seed, seeded::kMisclassificationStream));
  confidence_rng_.seed(stream_seed(params_.seed, seeded::kConfidenceStream));
  omission_rng_.seed(stream_seed(params_.seed, seeded::kOmissionStream));
  queue_.clear();
  last_now_ns_.reset();
}

// One capture of the light: every detection of every bulb, with misclassification and confidence noise.
SignalObservation PerceptionModel::detect(const std::vector<SignalElement>& truth, double now) {
  SignalObservation obs;
  obs.stamp = now;
  obs.elements.reserve(truth.size() * static_cast<std::size_t>(params_.detections_per_light));
  for (int k = 0; k < params_.detections_per_light; ++k) {
    for (const SignalElement& e : truth) {
      SignalElement det = e;
      if (params_.misclassification_probability > 0.0) {
        const double u_mis = uniform01(misclassification_rng_);
        const double u_which = uniform01(misclassification_rng_);
        if (u_mis < params_.misclassification_probability) det.color = other_color(e.color, u_which);
      }
      if (params_.confidence_noise > 0.0) {
        const double u_conf = uniform01(confidence_rng_);
        det.confidence = std::clamp(e.confidence + params_.confidence_noise * (2.0 * u_conf - 1.0), 0.0, 1.0);
      }
      obs.elements.push_back(det);
    }
  }
  return obs;
}

SignalDelivery PerceptionModel::observe(const std::vector<SignalElement>& truth, double distance_to_light,
                                        double now) {
  if (!std::isfinite(now)) throw std::invalid_argument("PerceptionModel::observe: now is not finite");
  if (std::isnan(distance_to_light)) throw std::invalid_argument("PerceptionModel::observe: distance is NaN");
  const std::int64_t now_ns = to_ns(now);
  if (last_now_ns_ && now_ns < *last_now_ns_) {
    throw std::invalid_argument("PerceptionModel::observe: time went backwards");
  }
  last_now_ns_ = now_ns;

  // Capture. Each stream feeds one fault only, so a fault that is off draws nothing from its stream:
  // the draws it would make could not change any outcome (u < 0 never holds; zero noise adds none).
  const double u_drop = params_.dropout_probability > 0.0 ? uniform01(dropout_rng_) : 1.0;
  const double u_omit = params_.omission_probability > 0.0 ? uniform01(omission_rng_) : 1.0;
  const bool in_range = std::abs(distance_to_light) <= params_.detection_range;
  const bool dropped = u_drop < params_.dropout_probability;
  if (!in_any(params_.blackouts, now_ns) && in_range && !dropped) {
    // docs/behaviour.md §L1.3: a message is published, with or without this light.
    SignalDelivery capture;
    if (in_any(params_.omissions, now_ns) || u_omit < params_.omission_probability) {
      capture.missing_from_message = true;
    } else {
      capture.observation = detect(truth, now);
    }
    // Without latency a capture is due at once and nothing waits (every earlier one was delivered).
    if (latency_ns_ == 0 && queue_.empty()) return capture;
    queue_.push_back({now_ns + latency_ns_, std::move(capture)});
  }

  // Delivery: the newest due capture wins.
  SignalDelivery delivered;
  while (!queue_.empty() && queue_.front().due_ns <= now_ns) {
    delivered = std::move(queue_.front().delivery);
    queue_.pop_front();
  }
  return delivered;
}

}  // namespace signalsim
