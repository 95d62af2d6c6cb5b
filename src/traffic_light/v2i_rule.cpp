#include "traffic_light/v2i_rule.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace signalsim {

void validate(const V2iParameters& p) {
  const auto check = [](double v, const char* name) {
    if (!std::isfinite(v) || v < 0.0)
      throw std::invalid_argument(std::string("traffic_light parameter v2i.") + name + " must be finite and >= 0");
  };
  check(p.last_time_allowed_to_pass, "last_time_allowed_to_pass");
  check(p.velocity_threshold, "velocity_threshold");
  check(p.required_time_to_departure, "required_time_to_departure");
}

V2iVerdict will_turn_red_before_reaching_stop_line(double d, double v, double now, LaneTurnDirection turn_direction,
                                                   const std::vector<SignalPrediction>& predictions,
                                                   const V2iParameters& params) {
  V2iVerdict r;
  // docs/behaviour.md §L1.7: the time to reach the stop point, or the time to get going when (nearly) at rest.
  r.t_pass = v > params.velocity_threshold ? d / v : params.required_time_to_departure;
  r.horizon = r.t_pass + params.last_time_allowed_to_pass;
  for (const SignalPrediction& p : predictions) {
    if (!is_traffic_signal_red_stop(turn_direction, p.elements)) continue;
    const double remaining = p.stamp - now;
    if (!r.time_to_red || remaining < *r.time_to_red) r.time_to_red = remaining;
    if (remaining < r.horizon) r.turns_red = true;  // strict, as the reference
  }
  return r;
}

}  // namespace signalsim
