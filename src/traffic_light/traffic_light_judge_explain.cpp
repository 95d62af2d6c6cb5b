// explain(): the judge's reason line from a step's result, input and parameters (header). One function
// per part of the line: the state change, the signal, the zone, the V2I rule, the latch, a held release.
#include "traffic_light/traffic_light_judge_explain.hpp"

#include <cstdarg>
#include <cstdio>

namespace signalsim {

namespace {

__attribute__((format(printf, 1, 2))) std::string strf(const char* format, ...) {
  char buffer[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(buffer, sizeof(buffer), format, args);
  va_end(args);
  return std::string(buffer);
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

// A step that decided None: no stop point, GO_OUT, or the dead line crossed.
std::string explain_none(const TrafficLightJudgeResult& r, const TrafficLightJudgeInput& in) {
  if (!in.distance_to_stop_point) return "none: the path does not cross the stop line";
  const double d = *in.distance_to_stop_point;
  if (r.previous_state == JudgeState::GoOut) {
    if (r.state == JudgeState::Approach) {
      return strf("none: GO_OUT -> APPROACH (re-armed, d = %.2f m > %.1f m)", d, kJudgeRestartLength);
    }
    return strf("none: GO_OUT (re-arms when d > %.1f m)", kJudgeRestartLength);
  }
  return strf("none: APPROACH -> GO_OUT (d = %.2f m < %.1f m)", d, kJudgeDeadLine);
}

// Why the signal says what it says (IS_STOP_SIGNAL's row, docs/behaviour.md §L1.3).
std::string explain_signal(const TrafficLightJudgeResult& r, const TrafficLightJudgeInput& in,
                           const TrafficLightJudgeParameters& p) {
  switch (r.verdict) {
    case SignalVerdict::NeverReceived:
      return p.is_simulation ? "signal never received (is_simulation)" : "signal never received (real-vehicle rule)";
    case SignalVerdict::TimedOut:
      return strf("signal timed out (age %.3f s > tl_state_timeout %.3f s)", r.signal_age, p.tl_state_timeout);
    case SignalVerdict::ArrowAwareYellowPass:
      return "yellow after green on a turn lane with a static arrow (arrow-aware yellow passing)";
    case SignalVerdict::Go:
      return "go signal " + describe_elements(r.looked_at) + " for a " + std::string(to_string(in.turn_direction)) +
             " lane";
    case SignalVerdict::Stop:
      if (r.missing_from_message) return "stop signal: the light was left out of the latest message";
      return "stop signal " + describe_elements(r.looked_at) + " for a " + std::string(to_string(in.turn_direction)) +
             " lane";
    case SignalVerdict::NotEvaluated:
      break;
  }
  return "";
}

// The pass judge's zone (docs/behaviour.md §L2.6).
std::string explain_zone(const TrafficLightJudgeResult& r, const TrafficLightJudgeInput& in,
                         const TrafficLightJudgeParameters& p) {
  const double d = r.distance;
  switch (r.zone) {
    case JudgeZone::Stoppable:
      return strf("stoppable (judge line %.2f m < d %.2f m)", r.judge_dist, d);
    case JudgeZone::OptionalZone:
      return strf("optional zone (judge line %.2f m < d %.2f m < yellow lamp line %.2f m)", r.judge_dist, d,
                  r.yellow_lamp_line);
    case JudgeZone::Slow:
      return strf("slow (v %.2f m/s < yellow_light_stop_velocity %.2f m/s)", in.velocity,
                  p.yellow_light_stop_velocity);
    case JudgeZone::PassThroughYellow:
      return strf("can pass through during yellow lamp (judge line %.2f m >= d %.2f m < yellow lamp line %.2f m)",
                  r.judge_dist, d, r.yellow_lamp_line);
    case JudgeZone::DilemmaZone:
      return strf("dilemma zone: cannot pass through during yellow lamp (judge line %.2f m >= d %.2f m >= "
                  "yellow lamp line %.2f m)",
                  r.judge_dist, d, r.yellow_lamp_line);
    case JudgeZone::None:
      break;
  }
  return "";
}

// The V2I rule when it asked for the stop (docs/behaviour.md §L1.7); its horizon is evaluated again.
std::string explain_v2i(const TrafficLightJudgeResult& r, const TrafficLightJudgeInput& in,
                        const TrafficLightJudgeParameters& p) {
  if (!r.v2i_stop) return "";
  const V2iVerdict v2i = will_turn_red_before_reaching_stop_line(r.distance, in.velocity, in.now, in.turn_direction,
                                                                 in.predictions, p.v2i);
  return strf("; V2I: red in %.2f s < horizon %.2f s (t_pass %.2f s + %.2f s)", r.v2i_time_to_red.value_or(0.0),
              v2i.horizon, v2i.t_pass, p.v2i.last_time_allowed_to_pass);
}

// Why a stop is of its kind: latched earlier, or inserted while not stoppable with the pass judge off.
std::string explain_latch(const TrafficLightJudgeResult& r, const TrafficLightJudgeParameters& p) {
  if (r.was_prev_state_stop) return " (latched " + std::string(to_string(r.decision)) + " since an earlier step)";
  const bool stoppable = r.zone == JudgeZone::Stoppable || r.zone == JudgeZone::OptionalZone ||
                         r.zone == JudgeZone::Slow;
  return !p.enable_pass_judge && !stoppable ? " (pass judge disabled)" : "";
}

}  // namespace

std::string explain(const TrafficLightJudgeResult& r, const TrafficLightJudgeInput& in,
                    const TrafficLightJudgeParameters& p) {
  if (r.decision == JudgeDecision::None) return explain_none(r, in);
  const std::string signal = explain_signal(r, in, p);
  if (r.restart_suppressed) {
    const auto& rs = p.restart_suppression;
    return strf("stop: restart suppressed (stopped at d = %.2f m within (%.2f, %.2f) m); ", r.distance,
                rs.min_behind_distance_to_stop, rs.max_behind_distance_to_stop) + signal;
  }
  if (r.decision == JudgeDecision::Pass && r.zone == JudgeZone::None) {  // no stop asked for
    if (!r.is_stop_signal) return "pass: " + signal;
    return strf("pass: stop signal held %.3f s, not > stop_time_hysteresis %.3f s; ", r.stop_signal_elapsed,
                p.stop_time_hysteresis) + signal;
  }
  const std::string zone = explain_zone(r, in, p);
  if (r.decision == JudgeDecision::Pass) return "pass: " + zone + "; " + signal + explain_v2i(r, in, p);
  std::string hold;
  if (r.release_pending) {
    hold = strf("; release pending: no stop signal for %.3f s < stop_release_confirmation_time %.3f s",
                r.release_elapsed, p.stop_release_confirmation_time);
  }
  return std::string(to_string(r.decision)) + explain_latch(r, p) + ": " + zone + "; " + signal +
         explain_v2i(r, in, p) + hold;
}

}  // namespace signalsim
