#include "traffic_light/v2i_channel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/time_ns.hpp"
#include "traffic_light/seeded_stream.hpp"

namespace signalsim {

void validate(const V2iChannelParameters& p) {
  const auto fail = [](const std::string& what) { throw std::invalid_argument("v2i channel parameter " + what); };
  if (!(p.dropout_probability >= 0.0 && p.dropout_probability <= 1.0)) fail("dropout_probability must be in [0, 1]");
  if (!std::isfinite(p.latency) || p.latency < 0.0) fail("latency must be finite and >= 0");
  if (!std::isfinite(p.max_age) || p.max_age < 0.0) fail("max_age must be finite and >= 0");
  for (std::size_t i = 0; i < p.blackouts.size(); ++i) {
    const auto& b = p.blackouts[i];
    if (!std::isfinite(b.start) || !std::isfinite(b.end) || b.end < b.start)
      fail("blackouts[" + std::to_string(i) + "] must be finite with start <= end");
  }
}

V2iChannel::V2iChannel(const V2iChannelParameters& params) : params_(params) {
  validate(params_);
  latency_ns_ = to_ns(params_.latency);
  max_age_ns_ = to_ns(params_.max_age);
  dropout_rng_.seed(seeded::stream_seed(params_.seed, seeded::kV2iDropoutStream));
}

std::vector<SignalPrediction> V2iChannel::step(const std::vector<SignalPrediction>& predictions, double now) {
  if (!std::isfinite(now)) throw std::invalid_argument("V2iChannel::step: now is not finite");
  const std::int64_t now_ns = to_ns(now);
  if (last_now_ns_ && now_ns < *last_now_ns_) throw std::invalid_argument("V2iChannel::step: time went backwards");
  last_now_ns_ = now_ns;

  // Send.
  const double u_drop = seeded::uniform01(dropout_rng_);
  const bool blacked_out = std::any_of(params_.blackouts.begin(), params_.blackouts.end(), [&](const auto& b) {
    return to_ns(b.start) <= now_ns && now_ns <= to_ns(b.end);
  });
  if (!blacked_out && !(u_drop < params_.dropout_probability))
    queue_.push_back({now_ns + latency_ns_, now_ns, now, predictions});

  // Receive: the newest due message replaces the kept one.
  while (!queue_.empty() && queue_.front().due_ns <= now_ns) {
    kept_ = std::move(queue_.front());
    queue_.pop_front();
  }
  in_force_stamp_.reset();
  if (!kept_ || now_ns - kept_->stamp_ns > max_age_ns_) return {};
  in_force_stamp_ = kept_->stamp;
  return kept_->predictions;
}

}  // namespace signalsim
