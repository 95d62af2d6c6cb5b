// The traffic-light judge's decision (algorithm in traffic_light_judge.hpp): one step as short functions,
// each a numbered part of docs/behaviour.md §L1.2. It formats no text: explain()
// (traffic_light_judge_explain.cpp) says why a step decided what it did.
#include "traffic_light/traffic_light_judge.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/time_ns.hpp"
#include "traffic_light/judge_line.hpp"

namespace signalsim {

namespace {

// docs/behaviour.md §L1.6 isVehicleStopped(0.0).
constexpr double kStopVelocityEps = 1e-3;

void require_finite(double value, const char* name) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(std::string("TrafficLightJudge: ") + name + " is not finite");
  }
}

void require_finite_input(const TrafficLightJudgeInput& in) {
  require_finite(in.now, "now");
  require_finite(in.velocity, "velocity");
  require_finite(in.acceleration, "acceleration");
  if (in.distance_to_stop_point) require_finite(*in.distance_to_stop_point, "distance_to_stop_point");
  if (in.observation) require_finite(in.observation->stamp, "observation stamp");
  if (in.observation && in.missing_from_message) {
    throw std::invalid_argument("TrafficLightJudge: an observation cannot be missing from its message");
  }
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
  // Left out of the latest message (or never received), nothing is looked at and the stamp stays.
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
  require_finite_input(in);  // before touching any state
  const std::int64_t now_ns = to_ns(in.now);
  // docs/behaviour.md §L1.3: the node's map holds only the groups of the latest message.
  if (in.observation) {
    received_ = *in.observation;
  } else if (in.missing_from_message) {
    received_.reset();
  }

  TrafficLightJudgeResult r;
  r.previous_state = state_;
  r.was_prev_state_stop = is_prev_state_stop_;
  // docs/behaviour.md §L1.2 STEP 1: without a stop point nothing is decided and nothing changes.
  if (in.distance_to_stop_point) {
    measure(in, r);
    if (state_ == JudgeState::GoOut) {
      step_go_out(r.distance);
    } else if (r.distance < kJudgeDeadLine) {
      enter_go_out();
    } else {
      approach(in, now_ns, r);
    }
  }
  r.state = state_;
  r.is_prev_state_stop = is_prev_state_stop_;
  r.yellow_state = yellow_state_;
  return r;
}

// docs/behaviour.md §L1.2 STEP 2; §L2.2-§L2.5 quantities reported every step with a stop point.
void TrafficLightJudge::measure(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) const {
  r.distance = *in.distance_to_stop_point;
  r.judge_dist = calc_judge_line_dist_with_jerk_limit(in.velocity, in.acceleration, params_.max_accel,
                                                      params_.max_jerk, params_.delay_response_time);
  r.yellow_lamp_line = in.velocity * params_.yellow_lamp_period;
}

// docs/behaviour.md §L1.2 STEP 4: never a stop in GO_OUT; re-armed beyond the restart length.
void TrafficLightJudge::step_go_out(double d) {
  if (d > kJudgeRestartLength) state_ = JudgeState::Approach;
  stop_signal_start_ns_.reset();
  release_start_ns_.reset();
}

// docs/behaviour.md §L1.2 3.1: the dead line.
void TrafficLightJudge::enter_go_out() {
  state_ = JudgeState::GoOut;
  stop_signal_start_ns_.reset();
  release_start_ns_.reset();
}

// docs/behaviour.md §L1.2 3.3-3.10: APPROACH with d at or beyond the dead line always decides.
void TrafficLightJudge::approach(const TrafficLightJudgeInput& in, std::int64_t now_ns, TrafficLightJudgeResult& r) {
  r.is_stop_signal = is_stop_signal(in, now_ns, r.verdict);  // 3.3
  r.looked_at = looking_;
  r.missing_from_message = stamp_ns_ && !received_;
  if (stamp_ns_) r.signal_age = static_cast<double>(now_ns - *stamp_ns_) * 1e-9;
  const std::int64_t elapsed_ns = run_stop_signal_timer(r.is_stop_signal, now_ns);  // 3.4
  r.stop_signal_elapsed = static_cast<double>(elapsed_ns) * 1e-9;
  // 3.5 / §L1.5: strictly greater, in integer nanoseconds.
  bool to_be_stopped = r.is_stop_signal && (is_prev_state_stop_ || elapsed_ns > hysteresis_ns_);
  if (v2i_asks_stop(in, r)) to_be_stopped = true;
  if (hold_latched_stop(to_be_stopped, now_ns, r)) to_be_stopped = true;
  r.to_be_stopped = to_be_stopped;

  if (suppress_restart(in, r)) return;
  if (!to_be_stopped) {  // 3.8 / 3.9: RTC disabled, activated := safe := !to_be_stopped.
    is_prev_state_stop_ = false;
    r.decision = JudgeDecision::Pass;
    return;
  }
  judge_stop(in, r);
}

// docs/behaviour.md §L1.2 3.4: the stop-signal timer; any non-stop cycle clears it (§L1.5). Returns the
// time the stop signal has persisted [ns], 0 without one.
std::int64_t TrafficLightJudge::run_stop_signal_timer(bool is_stop, std::int64_t now_ns) {
  if (is_stop) {
    if (!stop_signal_start_ns_) stop_signal_start_ns_ = now_ns;
  } else {
    stop_signal_start_ns_.reset();
  }
  return stop_signal_start_ns_ ? std::max<std::int64_t>(0, now_ns - *stop_signal_start_ns_) : 0;
}

// docs/behaviour.md §L1.2 3.6 / §L1.7: V2I, OR-ed in without hysteresis (only with use_remaining_time).
bool TrafficLightJudge::v2i_asks_stop(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) const {
  if (!params_.v2i.use_remaining_time) return false;
  const V2iVerdict v2i = will_turn_red_before_reaching_stop_line(r.distance, in.velocity, in.now, in.turn_direction,
                                                                 in.predictions, params_.v2i);
  r.v2i_stop = v2i.turns_red;
  r.v2i_time_to_red = v2i.time_to_red;
  return v2i.turns_red;
}

// signalsim, beyond the reference (stop_release_confirmation_time, header): a latched stop is held
// until no stop signal has been looked at for that long; a stop signal restarts the clock. True when
// the stop is held this step.
bool TrafficLightJudge::hold_latched_stop(bool to_be_stopped, std::int64_t now_ns, TrafficLightJudgeResult& r) {
  if (to_be_stopped || r.is_stop_signal) {
    release_start_ns_.reset();
    return false;
  }
  if (!is_prev_state_stop_) return false;
  // The go evidence's time: the capture stamp of the observation looked at (a stale one adds
  // nothing); never received (no stamp) counts by the clock.
  const bool observed = r.verdict == SignalVerdict::Go || r.verdict == SignalVerdict::ArrowAwareYellowPass;
  const std::int64_t evidence_ns = observed ? *stamp_ns_ : now_ns;
  if (!release_start_ns_) release_start_ns_ = evidence_ns;
  const std::int64_t confirmed_ns = std::max<std::int64_t>(0, evidence_ns - *release_start_ns_);
  r.release_elapsed = static_cast<double>(confirmed_ns) * 1e-9;
  if (confirmed_ns < release_confirmation_ns_) {
    r.release_pending = true;
    return true;
  }
  release_start_ns_.reset();
  return false;
}

// docs/behaviour.md §L1.2 3.7 / §L1.6: restart suppression (raw is_stop; latch not updated). True when
// it decided the step: a stop where the ego stands.
bool TrafficLightJudge::suppress_restart(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) const {
  const auto& rs = params_.restart_suppression;
  const double d = r.distance;
  if (!(in.is_vehicle_stopped && rs.min_behind_distance_to_stop < d && d < rs.max_behind_distance_to_stop &&
        r.is_stop_signal)) {
    return false;
  }
  r.decision = JudgeDecision::Stop;
  r.restart_suppressed = true;
  r.stop_point_distance = 0.0;
  return true;
}

// docs/behaviour.md §L1.2 3.10 / §L2.3 `isPassthrough` (strict inequalities) and the §L2.6 zones: a stop
// is asked for; the pass judge may still pass, otherwise the stop is latched.
void TrafficLightJudge::judge_stop(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) {
  const double d = r.distance;
  const bool distance_stoppable = r.judge_dist < d;
  const bool slow_velocity = in.velocity < params_.yellow_light_stop_velocity;
  const bool stoppable = distance_stoppable || slow_velocity;
  const bool reachable = d < r.yellow_lamp_line;
  if (distance_stoppable) {
    r.zone = reachable ? JudgeZone::OptionalZone : JudgeZone::Stoppable;
  } else if (slow_velocity) {
    r.zone = JudgeZone::Slow;
  } else {
    r.zone = reachable ? JudgeZone::PassThroughYellow : JudgeZone::DilemmaZone;
  }

  if (params_.enable_pass_judge && !stoppable && !is_prev_state_stop_ && reachable) {
    r.decision = JudgeDecision::Pass;  // no stop inserted; the latch stays false
    return;
  }
  // A new stop is inserted: fix Stop vs EmergencyStop (Decisions: dilemma zone -> emergency).
  if (!is_prev_state_stop_) latched_decision_ = stoppable ? JudgeDecision::Stop : JudgeDecision::EmergencyStop;
  is_prev_state_stop_ = true;
  r.decision = latched_decision_;
  r.stop_point_distance = d;
}

}  // namespace signalsim
