#include "traffic_light/traffic_light_judge.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <stdexcept>

#include "traffic_light/judge_line.hpp"

namespace signalsim {

namespace {

// docs/behaviour.md §L1.2 / §L4 hard-coded constants.
constexpr double kDeadLine = -2.0;          // APPROACH -> GO_OUT when d < -2.0 m
constexpr double kRestartLength = 1.0;      // GO_OUT -> APPROACH when d > +1.0 m
constexpr double kStopVelocityEps = 1e-3;   // isVehicleStopped(0.0)

// Times are compared in integer nanoseconds, like rclcpp::Time (docs/behaviour.md §L1.5 choice). Saturated
// at +-4e18 ns (about 127 years): llround of a larger finite time is unspecified, and the
// difference of two saturated times (now - stamp, now - timer start) stays within int64 (fuzzing
// found `now - stamp` overflowing for a stamp of 1e300 s).
constexpr double kMaxNs = 4e18;
std::int64_t to_ns(double seconds) {
  return static_cast<std::int64_t>(std::llround(std::clamp(seconds * 1e9, -kMaxNs, kMaxNs)));
}

__attribute__((format(printf, 1, 2))) std::string strf(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return std::string(buffer);
}

void require_finite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("TrafficLightJudge: ") + name + " is not finite");
  }
}

std::string describe_elements(const std::vector<SignalElement>& elements) {
  if (elements.empty()) return "[nothing recognised]";
  std::string s = "[";
  for (std::size_t i = 0; i < elements.size(); ++i) {
    if (i > 0) s += ", ";
    s += to_string(elements[i].color);
    s += ' ';
    s += to_string(elements[i].shape);
  }
  return s + "]";
}

}  // namespace

void validate(const TrafficLightJudgeParameters& p) {
  const auto fail = [](const char* what) {
    throw std::invalid_argument(std::string("traffic_light parameter ") + what);
  };
  const auto finite = [&](double v, const char* name) {
    if (!std::isfinite(v)) fail((std::string(name) + " is not finite").c_str());
  };
  finite(p.stop_margin, "stop_margin");
  finite(p.tl_state_timeout, "tl_state_timeout");
  finite(p.stop_time_hysteresis, "stop_time_hysteresis");
  finite(p.yellow_lamp_period, "yellow_lamp_period");
  finite(p.yellow_light_stop_velocity, "yellow_light_stop_velocity");
  finite(p.restart_suppression.min_behind_distance_to_stop, "restart_suppression.min_behind_distance_to_stop");
  finite(p.restart_suppression.max_behind_distance_to_stop, "restart_suppression.max_behind_distance_to_stop");
  finite(p.max_accel, "max_accel");
  finite(p.max_jerk, "max_jerk");
  finite(p.delay_response_time, "delay_response_time");
  finite(p.stop_release_confirmation_time, "stop_release_confirmation_time");
  if (p.tl_state_timeout < 0.0) fail("tl_state_timeout is negative");
  if (p.stop_time_hysteresis < 0.0) fail("stop_time_hysteresis is negative");
  if (p.yellow_lamp_period < 0.0) fail("yellow_lamp_period is negative");
  if (p.delay_response_time < 0.0) fail("delay_response_time is negative");
  if (p.stop_release_confirmation_time < 0.0) fail("stop_release_confirmation_time is negative");
  if (p.max_accel == 0.0) fail("max_accel is zero");
  if (p.max_jerk == 0.0) fail("max_jerk is zero");
  if (p.restart_suppression.min_behind_distance_to_stop > p.restart_suppression.max_behind_distance_to_stop) {
    fail("restart_suppression.min_behind_distance_to_stop exceeds max_behind_distance_to_stop");
  }
  validate(p.v2i);
}

double distance_to_stop_point(double front_to_stop_line, double stop_margin) {
  return front_to_stop_line - stop_margin;  // docs/behaviour.md §L9.2
}

// Autoware compares the signed speed (`v >= stop_velocity` means moving): a reversing ego counts as
// stopped.
bool is_vehicle_stopped(double velocity) { return velocity < kStopVelocityEps; }

TrafficLightJudge::TrafficLightJudge(const TrafficLightJudgeParameters& params) : params_(params) {
  validate(params_);
  hysteresis_ns_ = to_ns(params_.stop_time_hysteresis);
  timeout_ns_ = to_ns(params_.tl_state_timeout);
  release_confirmation_ns_ = to_ns(params_.stop_release_confirmation_time);
}

void TrafficLightJudge::reset() {
  state_ = JudgeState::Approach;
  is_prev_state_stop_ = false;
  latched_decision_ = JudgeDecision::Stop;
  stop_signal_start_ns_.reset();
  release_start_ns_.reset();
  received_.reset();
  stamp_ns_.reset();
  looking_.clear();
  yellow_state_ = YellowState::NotYellow;
}

// docs/behaviour.md §L1.3 decision table, with the arrow-aware override of §L1.8 as row 3.
bool TrafficLightJudge::is_stop_signal(const TrafficLightJudgeInput& in, std::int64_t now_ns,
                                       SignalVerdict& verdict) {
  // What was looked at last step becomes `previous`; looking_ is refilled in the other buffer (two
  // buffers swapped each step: no allocation once they have grown).
  std::swap(previous_looking_, looking_);
  const std::vector<SignalElement>& previous = previous_looking_;
  // updateTrafficSignal: the module looks up the node's latest observation (docs/behaviour.md §L1.3).
  if (received_) {
    stamp_ns_ = to_ns(received_->stamp);
    highest_confidence_per_shape(received_->elements, looking_);  // Decision: highest reliability
  } else {
    looking_.clear();
  }

  // Row 1: never received since creation.
  if (!stamp_ns_) {
    verdict = SignalVerdict::NeverReceived;
    return !params_.is_simulation;
  }
  // Row 2: timed out (strictly greater).
  if (now_ns - *stamp_ns_ > timeout_ns_) {
    verdict = SignalVerdict::TimedOut;
    return true;
  }
  // Row 3: arrow-aware yellow passing (docs/behaviour.md §L1.8). No tracking when disabled.
  if (params_.enable_arrow_aware_yellow_passing) {
    if (is_yellow(looking_)) {
      if (yellow_state_ == YellowState::NotYellow && !previous.empty()) {
        yellow_state_ = has_green_circle(previous) ? YellowState::FromGreen : YellowState::FromNonGreen;
      }
      if (yellow_state_ == YellowState::FromGreen && in.is_turn_lane && in.has_static_arrow) {
        verdict = SignalVerdict::ArrowAwareYellowPass;
        return false;
      }
    } else {
      yellow_state_ = YellowState::NotYellow;
    }
  }
  // Row 4: color and arrow matching (docs/behaviour.md §L1.4).
  const bool stop = is_traffic_signal_stop(in.turn_direction, looking_);
  verdict = stop ? SignalVerdict::Stop : SignalVerdict::Go;
  return stop;
}

TrafficLightJudgeResult TrafficLightJudge::step(const TrafficLightJudgeInput& in) {
  // Validate before touching any state.
  require_finite(in.now, "now");
  require_finite(in.velocity, "velocity");
  require_finite(in.acceleration, "acceleration");
  if (in.distance_to_stop_point) require_finite(*in.distance_to_stop_point, "distance_to_stop_point");
  if (in.observation) require_finite(in.observation->stamp, "observation stamp");

  const std::int64_t now_ns = to_ns(in.now);
  if (in.observation) received_ = *in.observation;

  TrafficLightJudgeResult r;
  const auto finish = [&]() {
    r.state = state_;
    r.is_prev_state_stop = is_prev_state_stop_;
    r.yellow_state = yellow_state_;
    return r;
  };

  // docs/behaviour.md §L1.2 STEP 1.
  if (!in.distance_to_stop_point) {
    if (explain_) r.reason = "none: the path does not cross the stop line";
    return finish();
  }

  // docs/behaviour.md §L1.2 STEP 2; §L2.2-§L2.5 quantities reported every step with a stop point.
  const double d = *in.distance_to_stop_point;
  const double v = in.velocity;
  r.distance = d;
  r.judge_dist = calc_judge_line_dist_with_jerk_limit(v, in.acceleration, params_.max_accel, params_.max_jerk,
                                                      params_.delay_response_time);
  r.yellow_lamp_line = v * params_.yellow_lamp_period;

  if (state_ == JudgeState::GoOut) {
    // docs/behaviour.md §L1.2 STEP 4: never a stop in GO_OUT.
    if (d > kRestartLength) {
      state_ = JudgeState::Approach;
      if (explain_) r.reason = strf("none: GO_OUT -> APPROACH (re-armed, d = %.2f m > %.1f m)", d, kRestartLength);
    } else if (explain_) {
      r.reason = strf("none: GO_OUT (re-arms when d > %.1f m)", kRestartLength);
    }
    stop_signal_start_ns_.reset();
    release_start_ns_.reset();
    return finish();
  }

  // docs/behaviour.md §L1.2 3.1: dead line.
  if (d < kDeadLine) {
    state_ = JudgeState::GoOut;
    stop_signal_start_ns_.reset();
    release_start_ns_.reset();
    if (explain_) r.reason = strf("none: APPROACH -> GO_OUT (d = %.2f m < %.1f m)", d, kDeadLine);
    return finish();
  }

  // docs/behaviour.md §L1.2 3.3.
  SignalVerdict verdict = SignalVerdict::NotEvaluated;
  const bool is_stop = is_stop_signal(in, now_ns, verdict);
  r.verdict = verdict;
  r.is_stop_signal = is_stop;

  // docs/behaviour.md §L1.2 3.4: the stop-signal timer; any non-stop cycle clears it (docs/behaviour.md §L1.5).
  if (is_stop) {
    if (!stop_signal_start_ns_) stop_signal_start_ns_ = now_ns;
  } else {
    stop_signal_start_ns_.reset();
  }
  const std::int64_t elapsed_ns = stop_signal_start_ns_ ? std::max<std::int64_t>(0, now_ns - *stop_signal_start_ns_) : 0;
  r.stop_signal_elapsed = static_cast<double>(elapsed_ns) * 1e-9;

  // docs/behaviour.md §L1.2 3.5 / §L1.5: strictly greater, in integer nanoseconds.
  bool to_be_stopped = is_stop && (is_prev_state_stop_ || elapsed_ns > hysteresis_ns_);

  // docs/behaviour.md §L1.2 3.6 / §L1.7: V2I, OR-ed in without hysteresis.
  std::string v2i_text;
  if (params_.v2i.use_remaining_time) {
    const V2iVerdict v2i = will_turn_red_before_reaching_stop_line(d, v, in.now, in.turn_direction, in.predictions,
                                                                   params_.v2i);
    r.v2i_stop = v2i.turns_red;
    r.v2i_time_to_red = v2i.time_to_red;
    if (v2i.turns_red) {
      if (explain_)
        v2i_text = strf("; V2I: red in %.2f s < horizon %.2f s (t_pass %.2f s + %.2f s)", *v2i.time_to_red, v2i.horizon,
                      v2i.t_pass, params_.v2i.last_time_allowed_to_pass);
      to_be_stopped = true;
    }
  }
  // signalsim, beyond the reference (stop_release_confirmation_time, header): a latched stop is held
  // until no stop signal has been looked at for that long; a stop signal restarts the clock.
  std::string hold_text;
  if (to_be_stopped || is_stop) {
    release_start_ns_.reset();
  } else if (is_prev_state_stop_) {
    // The go evidence's time: the capture stamp of the observation looked at (a stale one adds
    // nothing); never received (no stamp) counts by the clock.
    const bool observed = verdict == SignalVerdict::Go || verdict == SignalVerdict::ArrowAwareYellowPass;
    const std::int64_t evidence_ns = observed ? *stamp_ns_ : now_ns;
    if (!release_start_ns_) release_start_ns_ = evidence_ns;
    const std::int64_t confirmed_ns = std::max<std::int64_t>(0, evidence_ns - *release_start_ns_);
    r.release_elapsed = static_cast<double>(confirmed_ns) * 1e-9;
    if (confirmed_ns < release_confirmation_ns_) {
      r.release_pending = true;
      to_be_stopped = true;
      if (explain_)
        hold_text = strf("; release pending: no stop signal for %.3f s < stop_release_confirmation_time %.3f s",
                       r.release_elapsed, params_.stop_release_confirmation_time);
    } else {
      release_start_ns_.reset();
    }
  }
  r.to_be_stopped = to_be_stopped;

  // Why the signal says what it says, for the reason line.
  std::string signal_text;
  switch (explain_ ? verdict : SignalVerdict::NotEvaluated) {
    case SignalVerdict::NeverReceived:
      signal_text = params_.is_simulation ? "signal never received (is_simulation)"
                                          : "signal never received (real-vehicle rule)";
      break;
    case SignalVerdict::TimedOut:
      signal_text = strf("signal timed out (age %.3f s > tl_state_timeout %.3f s)",
                         static_cast<double>(now_ns - *stamp_ns_) * 1e-9, params_.tl_state_timeout);
      break;
    case SignalVerdict::ArrowAwareYellowPass:
      signal_text = "yellow after green on a turn lane with a static arrow (arrow-aware yellow passing)";
      break;
    case SignalVerdict::Go:
      signal_text = "go signal " + describe_elements(looking_) + " for a " +
                    std::string(to_string(in.turn_direction)) + " lane";
      break;
    case SignalVerdict::Stop:
      signal_text = "stop signal " + describe_elements(looking_) + " for a " +
                    std::string(to_string(in.turn_direction)) + " lane";
      break;
    case SignalVerdict::NotEvaluated:
      break;
  }

  // docs/behaviour.md §L1.2 3.7 / §L1.6: restart suppression (raw is_stop; latch not updated).
  const auto& rs = params_.restart_suppression;
  if (in.is_vehicle_stopped && rs.min_behind_distance_to_stop < d && d < rs.max_behind_distance_to_stop && is_stop) {
    r.decision = JudgeDecision::Stop;
    r.restart_suppressed = true;
    r.stop_point_distance = 0.0;
    if (explain_) {
      r.reason = strf("stop: restart suppressed (stopped at d = %.2f m within (%.2f, %.2f) m); ", d,
                      rs.min_behind_distance_to_stop, rs.max_behind_distance_to_stop) + signal_text;
    }
    return finish();
  }

  // docs/behaviour.md §L1.2 3.8 / 3.9: RTC disabled, activated := safe := !to_be_stopped.
  if (!to_be_stopped) {
    is_prev_state_stop_ = false;
    r.decision = JudgeDecision::Pass;
    if (explain_ && is_stop) {
      r.reason = strf("pass: stop signal held %.3f s, not > stop_time_hysteresis %.3f s; ", r.stop_signal_elapsed,
                      params_.stop_time_hysteresis) + signal_text;
    } else if (explain_) {
      r.reason = "pass: " + signal_text;
    }
    return finish();
  }

  // docs/behaviour.md §L1.2 3.10 / §L2.3 `isPassthrough`: strict inequalities.
  const bool distance_stoppable = r.judge_dist < d;
  const bool slow_velocity = v < params_.yellow_light_stop_velocity;
  const bool stoppable = distance_stoppable || slow_velocity;
  const bool reachable = d < r.yellow_lamp_line;

  // docs/behaviour.md §L2.6 zones.
  if (distance_stoppable) {
    r.zone = reachable ? JudgeZone::OptionalZone : JudgeZone::Stoppable;
  } else if (slow_velocity) {
    r.zone = JudgeZone::Slow;
  } else {
    r.zone = reachable ? JudgeZone::PassThroughYellow : JudgeZone::DilemmaZone;
  }

  std::string zone_text;
  switch (explain_ ? r.zone : JudgeZone::None) {
    case JudgeZone::Stoppable:
      zone_text = strf("stoppable (judge line %.2f m < d %.2f m)", r.judge_dist, d);
      break;
    case JudgeZone::OptionalZone:
      zone_text = strf("optional zone (judge line %.2f m < d %.2f m < yellow lamp line %.2f m)", r.judge_dist, d,
                       r.yellow_lamp_line);
      break;
    case JudgeZone::Slow:
      zone_text = strf("slow (v %.2f m/s < yellow_light_stop_velocity %.2f m/s)", v, params_.yellow_light_stop_velocity);
      break;
    case JudgeZone::PassThroughYellow:
      zone_text = strf("can pass through during yellow lamp (judge line %.2f m >= d %.2f m < yellow lamp line %.2f m)",
                       r.judge_dist, d, r.yellow_lamp_line);
      break;
    case JudgeZone::DilemmaZone:
      zone_text = strf("dilemma zone: cannot pass through during yellow lamp (judge line %.2f m >= d %.2f m >= "
                       "yellow lamp line %.2f m)",
                       r.judge_dist, d, r.yellow_lamp_line);
      break;
    case JudgeZone::None:
      break;
  }

  if (params_.enable_pass_judge && !stoppable && !is_prev_state_stop_ && reachable) {
    // PASS: no stop inserted; the latch stays false.
    r.decision = JudgeDecision::Pass;
    if (explain_) r.reason = "pass: " + zone_text + "; " + signal_text + v2i_text;
    return finish();
  }

  std::string latch_text;
  if (!is_prev_state_stop_) {
    // A new stop is inserted: fix Stop vs EmergencyStop (Decisions: dilemma zone -> emergency).
    latched_decision_ = stoppable ? JudgeDecision::Stop : JudgeDecision::EmergencyStop;
    if (!params_.enable_pass_judge && !stoppable) latch_text = " (pass judge disabled)";
  } else if (explain_) {
    latch_text = strf(" (latched %s since an earlier step)", std::string(to_string(latched_decision_)).c_str());
  }
  is_prev_state_stop_ = true;
  r.decision = latched_decision_;
  r.stop_point_distance = d;
  if (explain_) {
    r.reason = std::string(to_string(latched_decision_)) + latch_text + ": " + zone_text + "; " + signal_text +
               v2i_text + hold_text;
  }
  return finish();
}

}  // namespace signalsim
