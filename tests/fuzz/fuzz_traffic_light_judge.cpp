// libFuzzer target: the traffic-light judge (src/traffic_light/traffic_light_judge, docs/behaviour.md
// §L1.2) on random parameters and observation sequences. Documented failures: std::invalid_argument
// from the constructor (validate) and from step() for a non-finite input (the state is then
// unchanged). Anything else is a finding.
//
// Invariants asserted every step, from the per-step algorithm in traffic_light_judge.hpp
// (latch = is_prev_state_stop; "before"/"after" the step):
//   I1  no stop point                 -> None, state and latch unchanged.
//   I2  GO_OUT before                 -> None; after: APPROACH iff d > 1.0 m; latch unchanged.
//   I3  APPROACH and d < -2.0 m       -> None, GO_OUT after, latch unchanged.
//   I4  state changes only as I2/I3 say (APPROACH -> GO_OUT needs d < -2, GO_OUT -> APPROACH d > 1);
//       GO_OUT never gives Pass, Stop or EmergencyStop.
//   I5  restart suppression          -> Stop at distance 0, latch unchanged, raw stop signal.
//   I6  Pass                          -> latch false after.
//   I7  Stop / EmergencyStop (not I5) -> latch true after, stop point = d, to_be_stopped.
//   I8  stop latch: latched before, still APPROACH with d >= -2, stop signal now -> a stop again
//       (no hysteresis, no pass judge), of the same kind as the latched one (Stop vs Emergency
//       fixed when the stop was first inserted).
//   I9  a newly inserted stop is Stop when stoppable (zone Stoppable/OptionalZone/Slow), else
//       EmergencyStop; Pass with a zone only as PassThroughYellow, with the pass judge on and the
//       latch false before.
//   I10 not to_be_stopped in APPROACH (no I5) -> Pass; elapsed >= 0; timer only with a stop signal.
//   I11 the stop-signal timer, tracked here: cleared by a GO_OUT step, a dead-line step and an
//       evaluated step without a stop signal, started at the first stop-signal step after that. A
//       stop signal with the timer cleared has elapsed 0; for normal time ranges (|now|, the start
//       and the hysteresis within 1e6 s) elapsed is max(0, now - start) in integer nanoseconds.
//   I12 hysteresis: to_be_stopped without the latch before and without a V2I stop needs a stop
//       signal held strictly longer than stop_time_hysteresis (integer nanoseconds, normal ranges).
//   I13 explain() of every step's result (the reason line, kept apart from the decision) never
//       throws and names the decision first: "<decision>: ..." or "<decision> (...): ...".
// Doubles: mostly in a step's range, sometimes any finite double (ConsumeFloatingPoint: huge
// values) or one of NaN, +-infinity, -0.0, denorm_min (special_double, fuzz_common.hpp).
#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include "fuzz_common.hpp"
#include "traffic_light/traffic_light_judge.hpp"
#include "traffic_light/traffic_light_judge_explain.hpp"

using namespace signalsim;

namespace {

double any_double(FuzzedDataProvider& in, double lo, double hi) {
  switch (in.ConsumeIntegralInRange<int>(0, 8)) {
    case 0: return in.ConsumeFloatingPoint<double>();  // any finite double: huge, tiny
    case 1: return in.ConsumeIntegralInRange<int>(-4, 4) * 0.5;
    case 2: return fuzz::special_double(in);  // NaN, +-inf, -0.0, denorm_min
    default: return in.ConsumeFloatingPointInRange<double>(lo, hi);
  }
}

// Times within which the judge's nanoseconds are plain llround(t * 1e9): no saturation at +-4e9 s
// and exact through the double elapsed it reports.
constexpr double kNormalTime = 1e6;  // [s]
bool normal_time(double t) { return std::abs(t) <= kNormalTime; }
std::int64_t ns(double seconds) { return std::llround(seconds * 1e9); }

SignalElement element(FuzzedDataProvider& in) {
  SignalElement e;
  e.color = static_cast<SignalColor>(in.ConsumeIntegralInRange<int>(0, 4));
  e.shape = static_cast<SignalShape>(in.ConsumeIntegralInRange<int>(0, 10));
  e.status = static_cast<SignalStatus>(in.ConsumeIntegralInRange<int>(0, 3));
  e.confidence = in.ConsumeBool() ? 1.0 : any_double(in, 0.0, 1.0);
  return e;
}

std::vector<SignalElement> elements(FuzzedDataProvider& in) {
  std::vector<SignalElement> v(in.ConsumeIntegralInRange<std::size_t>(0, 4));
  for (auto& e : v) e = element(in);
  return v;
}

TrafficLightJudgeParameters parameters(FuzzedDataProvider& in) {
  TrafficLightJudgeParameters p;
  if (in.ConsumeBool()) return p;  // the defaults, half of the time
  p.stop_margin = any_double(in, 0.0, 5.0);
  p.tl_state_timeout = any_double(in, 0.0, 3.0);
  p.stop_time_hysteresis = any_double(in, 0.0, 1.0);
  p.yellow_lamp_period = any_double(in, 0.0, 5.0);
  p.yellow_light_stop_velocity = any_double(in, 0.0, 5.0);
  p.enable_pass_judge = in.ConsumeBool();
  p.is_simulation = in.ConsumeBool();
  p.restart_suppression.min_behind_distance_to_stop = any_double(in, -1.0, 2.0);
  p.restart_suppression.max_behind_distance_to_stop = any_double(in, -1.0, 2.0);
  p.enable_arrow_aware_yellow_passing = in.ConsumeBool();
  p.max_accel = any_double(in, -10.0, 1.0);
  p.max_jerk = any_double(in, -10.0, 1.0);
  p.delay_response_time = any_double(in, 0.0, 2.0);
  p.v2i.use_remaining_time = in.ConsumeBool();
  p.v2i.last_time_allowed_to_pass = any_double(in, 0.0, 5.0);
  p.v2i.velocity_threshold = any_double(in, 0.0, 2.0);
  p.v2i.required_time_to_departure = any_double(in, 0.0, 5.0);
  return p;
}

/// I13: the reason line starts with the decision's name and a ':' or ' (' after it.
bool names_the_decision(const std::string& reason, JudgeDecision decision) {
  const std::string name(to_string(decision));
  return reason.compare(0, name.size(), name) == 0 &&
         (reason.compare(name.size(), 1, ":") == 0 || reason.compare(name.size(), 2, " (") == 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  const TrafficLightJudgeParameters params = parameters(in);
  std::optional<TrafficLightJudge> made;
  try {
    made.emplace(params);
  } catch (const std::invalid_argument&) {
    return 0;
  }
  TrafficLightJudge& judge = *made;

  double now = 0.0;
  double d = in.ConsumeFloatingPointInRange<double>(-5.0, 200.0);
  double v = in.ConsumeFloatingPointInRange<double>(0.0, 20.0);
  // Latched decision as the target tracks it (I8): set when a stop is first inserted.
  std::optional<JudgeDecision> latched;
  // The stop-signal timer as the target tracks it (I11): cleared, or running since timer_start.
  bool timer_cleared = true;
  double timer_start = 0.0;
  for (int step = 0; step < 400 && in.remaining_bytes() > 0; ++step) {
    TrafficLightJudgeInput x;
    // Time: mostly forward by a step, sometimes a jump or any double (then step() may throw).
    switch (in.ConsumeIntegralInRange<int>(0, 9)) {
      case 0: now = any_double(in, -10.0, 1e4); break;
      case 1: now += in.ConsumeFloatingPointInRange<double>(0.0, 5.0); break;
      default: now += 0.1;
    }
    x.now = now;
    // The ego: mostly a smooth approach, sometimes a jump anywhere.
    if (in.ConsumeIntegralInRange<int>(0, 9) == 0) {
      d = any_double(in, -10.0, 300.0);
      v = any_double(in, -1.0, 25.0);
    } else {
      v = std::max(0.0, v + in.ConsumeFloatingPointInRange<double>(-0.6, 0.3));
      d -= v * 0.1;
    }
    if (in.ConsumeIntegralInRange<int>(0, 19) != 0) x.distance_to_stop_point = d;
    x.velocity = v;
    x.acceleration = any_double(in, -5.0, 3.0);
    if (in.ConsumeBool()) {
      SignalObservation o;
      o.elements = elements(in);
      o.stamp = in.ConsumeBool() ? now : any_double(in, now - 3.0, now + 0.5);
      x.observation = o;
    } else {
      x.missing_from_message = in.ConsumeBool();  // a message without the light (docs/behaviour.md §L1.3)
    }
    x.is_vehicle_stopped = in.ConsumeBool() ? is_vehicle_stopped(v) : in.ConsumeBool();
    x.turn_direction = static_cast<LaneTurnDirection>(in.ConsumeIntegralInRange<int>(0, 3));
    x.is_turn_lane = in.ConsumeBool();
    x.has_static_arrow = in.ConsumeBool();
    if (params.v2i.use_remaining_time) {
      const std::size_t n = in.ConsumeIntegralInRange<std::size_t>(0, 3);
      for (std::size_t k = 0; k < n; ++k)
        x.predictions.push_back({any_double(in, now - 1.0, now + 20.0), elements(in)});
    }

    const JudgeState state_before = judge.state();
    const bool latch_before = judge.is_prev_state_stop();
    const YellowState yellow_before = judge.yellow_state();
    TrafficLightJudgeResult r;
    try {
      r = judge.step(x);
    } catch (const std::invalid_argument&) {
      // Only for a non-finite input, and the state is unchanged.
      const bool finite = std::isfinite(x.now) && std::isfinite(x.velocity) && std::isfinite(x.acceleration) &&
                          (!x.distance_to_stop_point || std::isfinite(*x.distance_to_stop_point)) &&
                          (!x.observation || std::isfinite(x.observation->stamp));
      FUZZ_ASSERT(!finite);
      FUZZ_ASSERT(judge.state() == state_before && judge.is_prev_state_stop() == latch_before &&
                  judge.yellow_state() == yellow_before);
      if (!std::isfinite(now)) now = 0.0;
      if (!std::isfinite(d)) d = 50.0;
      if (!std::isfinite(v)) v = 10.0;
      continue;
    }
    FUZZ_ASSERT(names_the_decision(explain(r, x, params), r.decision));  // I13
    const bool latch_after = judge.is_prev_state_stop();
    FUZZ_ASSERT(r.state == judge.state() && r.is_prev_state_stop == latch_after);
    FUZZ_ASSERT(r.stop_signal_elapsed >= 0.0);
    const bool is_stop_decision = r.decision == JudgeDecision::Stop || r.decision == JudgeDecision::EmergencyStop;

    if (!x.distance_to_stop_point) {  // I1
      FUZZ_ASSERT(r.decision == JudgeDecision::None && r.state == state_before && latch_after == latch_before);
      continue;
    }
    const double dd = *x.distance_to_stop_point;
    FUZZ_ASSERT(r.distance == dd);
    if (state_before == JudgeState::GoOut) {  // I2
      FUZZ_ASSERT(r.decision == JudgeDecision::None);
      FUZZ_ASSERT((r.state == JudgeState::Approach) == (dd > 1.0));
      FUZZ_ASSERT(latch_after == latch_before);
      timer_cleared = true;  // I11
      continue;
    }
    if (dd < -2.0) {  // I3
      FUZZ_ASSERT(r.decision == JudgeDecision::None && r.state == JudgeState::GoOut && latch_after == latch_before);
      timer_cleared = true;  // I11
      continue;
    }
    // I4: APPROACH, d >= -2: stays APPROACH and decides.
    FUZZ_ASSERT(r.state == JudgeState::Approach);
    FUZZ_ASSERT(r.decision != JudgeDecision::None);
    FUZZ_ASSERT(r.verdict != SignalVerdict::NotEvaluated);
    FUZZ_ASSERT(!r.is_stop_signal || r.stop_signal_elapsed >= 0.0);
    FUZZ_ASSERT(r.is_stop_signal || r.stop_signal_elapsed == 0.0);

    // I11: the timer. An evaluated step clears it without a stop signal, starts it with one.
    if (r.is_stop_signal) {
      if (timer_cleared) {
        FUZZ_ASSERT(r.stop_signal_elapsed == 0.0);
        timer_start = x.now;
        timer_cleared = false;
      }
      const bool normal = normal_time(x.now) && normal_time(timer_start) && normal_time(params.stop_time_hysteresis);
      if (normal) {
        const std::int64_t elapsed_ns = std::max<std::int64_t>(0, ns(x.now) - ns(timer_start));
        FUZZ_ASSERT(r.stop_signal_elapsed == static_cast<double>(elapsed_ns) * 1e-9);
        // I12: the hysteresis, strictly greater.
        if (r.to_be_stopped && !latch_before && !r.v2i_stop) FUZZ_ASSERT(elapsed_ns > ns(params.stop_time_hysteresis));
      }
    } else {
      timer_cleared = true;
    }
    // I12: without the latch and V2I only a stop signal can ask for a stop.
    if (r.to_be_stopped && !latch_before && !r.v2i_stop) FUZZ_ASSERT(r.is_stop_signal);

    if (r.restart_suppressed) {  // I5
      FUZZ_ASSERT(r.decision == JudgeDecision::Stop && r.stop_point_distance && *r.stop_point_distance == 0.0);
      FUZZ_ASSERT(latch_after == latch_before && r.is_stop_signal && x.is_vehicle_stopped);
      continue;
    }
    if (r.decision == JudgeDecision::Pass) {  // I6
      FUZZ_ASSERT(!latch_after && !r.stop_point_distance);
      if (r.zone != JudgeZone::None) {  // I9 (pass judge)
        FUZZ_ASSERT(r.zone == JudgeZone::PassThroughYellow && params.enable_pass_judge && !latch_before);
        FUZZ_ASSERT(r.to_be_stopped);
      } else {
        FUZZ_ASSERT(!r.to_be_stopped);  // I10
      }
      latched.reset();
    } else {  // I7
      FUZZ_ASSERT(is_stop_decision && latch_after && r.to_be_stopped);
      FUZZ_ASSERT(r.stop_point_distance && *r.stop_point_distance == dd);
      if (latch_before) {
        FUZZ_ASSERT(latched);                 // I8: the target saw the stop that set the latch
        FUZZ_ASSERT(r.decision == *latched);  //     and the kind is held
      } else {                                // I9: newly inserted
        const bool stoppable = r.zone == JudgeZone::Stoppable || r.zone == JudgeZone::OptionalZone ||
                               r.zone == JudgeZone::Slow;
        FUZZ_ASSERT(r.decision == (stoppable ? JudgeDecision::Stop : JudgeDecision::EmergencyStop));
      }
      latched = r.decision;
    }
    if (latch_before && r.is_stop_signal) FUZZ_ASSERT(is_stop_decision);  // I8: no hysteresis, no pass judge
    if (!r.to_be_stopped) FUZZ_ASSERT(r.decision == JudgeDecision::Pass);  // I10
  }
  return 0;
}
