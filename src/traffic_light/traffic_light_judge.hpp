// The traffic-light judge: stop, pass or emergency stop for one light group and its stop line,
// reproducing Autoware's behavior-velocity traffic-light module (docs/behaviour.md §L1-§L2) on the route
// coordinate. No SUMO types; the caller supplies distances, ego state and signal observations.
//
// One TrafficLightJudge is one Autoware scene module: one stop line and one light group. The caller
// (scenario layer) creates it when the light enters the ego's horizon and drops it afterwards
// (docs/behaviour.md §L1.1). All state lives in this object: the APPROACH/GO_OUT state, the stop-signal timer,
// the stop latch, the last received observation and the arrow-aware yellow tracker.
//
// ---------------------------------------------------------------------------------------------
// Per-step algorithm of step(in)                            (docs/behaviour.md §L1.2; "d" = in.distance_to_stop_point)
// ---------------------------------------------------------------------------------------------
//   if in.observation:                      // a result was delivered this step (docs/behaviour.md §L1.3)
//       received := in.observation          // like the node's signal map: kept until replaced
//   else if in.missing_from_message:        // a message was delivered without this light
//       received := none                    // the map is rebuilt from each message; stamp kept
//   if d is empty:                          // STEP 1: the path does not cross the stop line
//       return None                         //   no state change
//   judge_dist := calc_judge_line_dist_with_jerk_limit(v, a0, max_accel, max_jerk,
//                                                      delay_response_time)      (docs/behaviour.md §L2.2)
//   yellow_lamp_line := v * yellow_lamp_period                                 (docs/behaviour.md §L2.3)
//   if state == APPROACH:                   // STEP 3
//       if d < -2.0 m:                                                           (3.1)
//           state := GO_OUT; clear timer; clear release clock; return None
//       is_stop := IS_STOP_SIGNAL()                                              (3.3)
//       if is_stop: start timer at now unless running   else: clear timer        (3.4)
//       elapsed := timer running ? max(0, now - start) : 0
//       to_be_stopped := is_stop and (is_prev_state_stop or elapsed > stop_time_hysteresis)  (3.5)
//       if v2i.use_remaining_time:                                               (3.6, §L1.7)
//           to_be_stopped := to_be_stopped or WILL_TURN_RED(d, v, in.predictions)  (v2i_rule.hpp)
//       if in.is_vehicle_stopped and min_behind < d < max_behind and is_stop:    (3.7, §L1.6)
//           return Stop at the ego's own position (restart_suppressed; latch untouched)
//       if is_stop or to_be_stopped: clear release clock                        (signalsim, below)
//       else if is_prev_state_stop:         // a decided stop sees no stop signal
//           t_go := verdict is Go/ArrowAwareYellowPass ? stamp : now
//           start release clock at t_go unless running
//           if t_go - release_start < stop_release_confirmation_time:
//               to_be_stopped := true       // held: release_pending (the latched stop stands)
//           else: clear release clock       // released below, as the reference does
//       if not to_be_stopped:                                                    (3.8, 3.9)
//           is_prev_state_stop := false; return Pass
//       ZONE := classify(judge_dist < d, v < yellow_light_stop_velocity,        (3.10, §L2.3, §L2.6)
//                        d < yellow_lamp_line)
//       if enable_pass_judge and not stoppable and not is_prev_state_stop and reachable:
//           return Pass                                  // "can pass through during yellow lamp"
//       if not is_prev_state_stop:                       // a new stop is inserted
//           latched := stoppable ? Stop : EmergencyStop  // Decisions: dilemma zone -> emergency
//       is_prev_state_stop := true; return latched at distance d
//   else (GO_OUT):                          // STEP 4
//       if d > 1.0 m: state := APPROACH     // re-arm
//       clear timer; clear release clock; return None
//
//   IS_STOP_SIGNAL():                                                       (docs/behaviour.md §L1.3, §L1.8)
//       previous := looking
//       if received: stamp := received.stamp; looking := highest_confidence_per_shape(received)
//       else: looking := []                 // left out of the latest message (stamp untouched)
//       if stamp unset:               return not is_simulation     // row 1: never received
//       if now - stamp > tl_state_timeout:  return true            // row 2: timed out
//       if enable_arrow_aware_yellow_passing:                      // row 3 (docs/behaviour.md §L1.8)
//           if is_yellow(looking):
//               if yellow_state == NotYellow and previous not empty:
//                   yellow_state := has_green_circle(previous) ? FromGreen : FromNonGreen
//               if yellow_state == FromGreen and is_turn_lane and has_static_arrow: return false
//           else: yellow_state := NotYellow
//       return is_traffic_signal_stop(turn_direction, looking)     // row 4 (docs/behaviour.md §L1.4)
//
// Choices where the reference leaves room (all documented at their members below):
// - Time. Times are rounded to integer nanoseconds (as rclcpp::Time) before any comparison, so at a
//   0.1 s step the second STOP cycle has elapsed exactly 0.1 s (not > 0.1: pass) and the third
//   0.2 s (stop) however the caller's clock accumulated rounding error (docs/behaviour.md §L1.5). The same
//   holds for the timeout: age 1.0 s is not timed out, 1.1 s is. Times beyond +-4e9 s (any
//   finite stamp, `now` or parameter) saturate there, so every difference is defined.
// - Observations. An absent observation means "nothing new was delivered": the last one stays in
//   force and ages towards the timeout (the node keeps the last message). An observation with no
//   elements means "delivered, nothing recognised" and is a stop signal (docs/behaviour.md §L1.3 notes).
//   A message delivered without this light (missing_from_message) clears what was received but not
//   its stamp: a stop signal while the stamp is fresh, timed out later, never received if there was
//   none (docs/behaviour.md §L1.3, the reference's updateTrafficSignal).
// - Stop vs EmergencyStop is fixed when a stop is first inserted and held while the latch holds, so
//   the last metres of a normal stop (where the judge line, with its 0.5 s dead time, exceeds d)
//   are not relabelled as an emergency. A stop inserted while not stoppable is an EmergencyStop also
//   with enable_pass_judge = false (the planner must relax its limits there too).
// - Stop release confirmation (signalsim's own parameter, beyond the reference; 0 = the reference).
//   The reference releases a decided stop at the first cycle without a stop signal (step 3.9), so
//   one misread green cancels it and, near the line, the next red is judged afresh by the pass
//   judge (docs/behaviour.md §L1.2 consequences, §L2.6), which may pass through on red.
//   "Decided" is the judge's latched stop: is_prev_state_stop, set where a Stop or EmergencyStop is
//   returned at step 3.10 (a restart suppression, 3.7, neither sets nor needs it). While it holds, a
//   cycle with no stop signal (IS_STOP_SIGNAL false and no V2I stop) keeps the stop, at the latched
//   level and at the stop point, until the go evidence has lasted stop_release_confirmation_time
//   without a break (>=, integer nanoseconds: at a 0.1 s step and 0.5 s the sixth go cycle
//   releases). The evidence is timed by the capture stamp of the observation looked at, so a green
//   kept in force over dropouts (absent observations) adds no time. A stop signal restarts the
//   clock: a red/amber/unknown reading, nothing recognised, and a timeout (row 2: the observation
//   older than tl_state_timeout), as does a V2I stop. Never received (row 1) with is_simulation is a
//   go verdict without a stamp and is timed by `now`; without is_simulation it is a stop signal. A
//   stop not yet decided (hysteresis running) is not held: a go cycle passes at once. GO_OUT,
//   the dead line and reset() clear the clock; with 0 every go cycle releases at once.
// - V2I (docs/behaviour.md §L1.7): in.predictions are the predictions in force this step (the V2I channel's,
//   scenario/light_stage); the rule is OR-ed in after the hysteresis, so a green light can give a
//   stop, which the pass judge still classifies. RTC (docs/behaviour.md §L1.5; disabled path = activated :=
//   safe) is not modelled.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "traffic_light/signal_elements.hpp"
#include "traffic_light/v2i_rule.hpp"

namespace signalsim {

/// Parameters, Autoware names and defaults (docs/behaviour.md §L4), overridden by the signalsim Decisions.
struct TrafficLightJudgeParameters {
  /// Bounds of `d` within which a stopped ego keeps standing instead of creeping to the stop point
  /// (docs/behaviour.md §L1.6). Both bounds are exclusive.
  struct RestartSuppression {
    double min_behind_distance_to_stop = 0.5;  ///< [m]
    double max_behind_distance_to_stop = 1.0;  ///< [m]

    bool operator==(const RestartSuppression&) const = default;
  };

  double stop_margin = 0.0;  ///< [m] front bumper to stop line at standstill; see distance_to_stop_point()
  double tl_state_timeout = 1.0;          ///< [s] observation age (now - stamp) beyond which -> stop
  double stop_time_hysteresis = 0.1;      ///< [s] a stop signal must persist strictly longer than this
  double yellow_lamp_period = 2.75;       ///< [s] assumed yellow duration for the yellow lamp line
  double yellow_light_stop_velocity = 2.0;  ///< [m/s] below: always stoppable (Decision; newest ref 1.0)
  bool enable_pass_judge = true;          ///< false: a stop request always stops (docs/behaviour.md §L2.3)
  bool is_simulation = true;              ///< never received -> pass (true) / stop (false) (Decision)
  RestartSuppression restart_suppression;  ///< docs/behaviour.md §L1.6
  bool enable_arrow_aware_yellow_passing = false;  ///< docs/behaviour.md §L1.8 (corrected: autoware_launch ships false)
  double max_accel = -2.8;            ///< [m/s^2] a_s of the judge line, negative (common param)
  double max_jerk = -5.0;             ///< [m/s^3] j_s of the judge line, negative (common param)
  double delay_response_time = 0.5;   ///< [s] t_d of the judge line (common param)
  V2iParameters v2i;                  ///< docs/behaviour.md §L1.7 (off by default)
  /// [s] >= 0, signalsim's own (beyond the reference): a latched stop is released only after no stop
  /// signal for this long without a break (see "Stop release confirmation" above); 0: the reference.
  double stop_release_confirmation_time = 0.0;

  bool operator==(const TrafficLightJudgeParameters&) const = default;
};

/// Throws std::invalid_argument naming the first bad member: a non-finite value, a negative
/// time (tl_state_timeout, stop_time_hysteresis, yellow_lamp_period, delay_response_time,
/// stop_release_confirmation_time),
/// max_accel == 0 or max_jerk == 0 (divisors of §L2.2), or min_behind > max_behind.
/// Signs of max_accel/max_jerk are not checked (upstream test fixtures use +1.0).
void validate(const TrafficLightJudgeParameters& params);

/// docs/behaviour.md §L9.2: d = (s_line - stop_margin) - s_front, i.e. the front-referenced distance to the
/// stop line minus the margin. Equals Autoware's base_link-referenced distance to the stop point.
double distance_to_stop_point(double front_to_stop_line, double stop_margin);

/// Autoware's PlannerData::isVehicleStopped(0.0): only the newest speed sample, v < 1e-3 m/s, signed
/// (docs/behaviour.md §L1.6; a reversing ego counts as stopped, as in Autoware). Offered to the caller for TrafficLightJudgeInput::is_vehicle_stopped.
bool is_vehicle_stopped(double velocity);

/// Module state (docs/behaviour.md §L1.2). There is no STOPPED or PASSED state.
enum class JudgeState : std::uint8_t { Approach, GoOut };

/// What the judge asks of the velocity planner this step.
enum class JudgeDecision : std::uint8_t {
  None,           ///< no stop point on the path, or GO_OUT: the judge does not constrain the ego
  Pass,           ///< go: no stop signal (after hysteresis), or "can pass through during yellow"
  Stop,           ///< stop at stop_point_distance with the normal limits (stoppable / optional zone)
  EmergencyStop,  ///< stop at stop_point_distance relaxing the limits (dilemma zone, Decision)
};

/// Classification of a stop request by the pass judge (docs/behaviour.md §L2.3, §L2.6). None when the pass
/// judge was not consulted this step (no stop requested).
enum class JudgeZone : std::uint8_t {
  None,
  Stoppable,          ///< judge_dist < d, d >= yellow lamp line: normal stop
  OptionalZone,       ///< judge_dist < d and d < yellow lamp line: can do either; stops (Decision)
  PassThroughYellow,  ///< cannot stop (and not slow), d < yellow lamp line: pass
  DilemmaZone,        ///< cannot stop (and not slow), d >= yellow lamp line: emergency stop
  Slow,               ///< judge_dist >= d but v < yellow_light_stop_velocity: always stoppable
};

/// How IS_STOP_SIGNAL reached its answer (docs/behaviour.md §L1.3 table).
enum class SignalVerdict : std::uint8_t {
  NotEvaluated,         ///< IS_STOP_SIGNAL did not run this step (no stop point, GO_OUT)
  NeverReceived,        ///< row 1: go with is_simulation, stop without
  TimedOut,             ///< row 2: stop
  ArrowAwareYellowPass, ///< row 3: go (docs/behaviour.md §L1.8)
  Go,                   ///< row 4: green circle or matching green arrow
  Stop,                 ///< row 4: anything else
};

/// Arrow-aware yellow tracker (docs/behaviour.md §L1.8; the fork's kFromRedArrow is kFromNonGreen).
enum class YellowState : std::uint8_t { NotYellow, FromGreen, FromNonGreen };

std::string_view to_string(JudgeState s);
std::string_view to_string(JudgeDecision d);
std::string_view to_string(JudgeZone z);
std::string_view to_string(SignalVerdict v);
std::string_view to_string(YellowState y);

/// Everything the judge needs for one step.
struct TrafficLightJudgeInput {
  double now = 0.0;  ///< [s] simulation time; should not decrease
  /// [m] signed distance base_link -> stop point (= distance_to_stop_point(front->line, margin));
  /// > 0 ahead. Empty when the ego's path does not cross this stop line (docs/behaviour.md §L1.2 STEP 1).
  std::optional<double> distance_to_stop_point;
  double velocity = 0.0;      ///< [m/s] v, signed, not clamped (docs/behaviour.md §L2.1)
  double acceleration = 0.0;  ///< [m/s^2] a0, positive = speeding up (docs/behaviour.md §L2.1)
  /// The perception result delivered this step, if any. Absent: nothing new (the previous one stays
  /// in force and ages), unless missing_from_message. Present with no elements: delivered but
  /// nothing recognised (stop).
  std::optional<SignalObservation> observation;
  /// A message was delivered this step without this light (docs/behaviour.md §L1.3): what was received
  /// is dropped, its stamp kept. Only with no observation.
  bool missing_from_message = false;
  bool is_vehicle_stopped = false;  ///< see is_vehicle_stopped(v) (docs/behaviour.md §L1.6)
  LaneTurnDirection turn_direction = LaneTurnDirection::Else;  ///< of the lane owning the light
  bool is_turn_lane = false;      ///< lane turn_direction is left/right (docs/behaviour.md §L1.8 map fact)
  bool has_static_arrow = false;  ///< the light has an arrow bulb (docs/behaviour.md §L1.8 map fact)
  /// The V2I predictions in force this step (docs/behaviour.md §L1.7); empty: V2I says nothing. Used only
  /// with v2i.use_remaining_time.
  std::vector<SignalPrediction> predictions;
};

/// docs/behaviour.md §L1.2: APPROACH -> GO_OUT when d < this [m] (the dead line, 3.1); GO_OUT -> APPROACH
/// when d > kJudgeRestartLength [m] (STEP 4).
inline constexpr double kJudgeDeadLine = -2.0;
inline constexpr double kJudgeRestartLength = 1.0;

/// Result of one step. Distances are relative to base_link (same reference as `d`).
struct TrafficLightJudgeResult {
  JudgeDecision decision = JudgeDecision::None;
  JudgeZone zone = JudgeZone::None;
  JudgeState state = JudgeState::Approach;  ///< state after this step
  JudgeState previous_state = JudgeState::Approach;  ///< state before this step
  bool was_prev_state_stop = false;                   ///< the stop latch before this step
  SignalVerdict verdict = SignalVerdict::NotEvaluated;
  bool is_stop_signal = false;   ///< raw IS_STOP_SIGNAL (before hysteresis); false if not evaluated
  bool to_be_stopped = false;    ///< after hysteresis and latch (step 3.5)
  double stop_signal_elapsed = 0.0;  ///< [s] how long the stop signal has persisted (0 if none)
  bool restart_suppressed = false;   ///< step 3.7 fired (docs/behaviour.md §L1.6)
  bool is_prev_state_stop = false;   ///< the stop latch after this step
  YellowState yellow_state = YellowState::NotYellow;  ///< tracker after this step
  double distance = 0.0;          ///< [m] d this step (0 when there is no stop point)
  double judge_dist = 0.0;        ///< [m] jerk-limited judge line (docs/behaviour.md §L2.2); 0 without stop point
  double yellow_lamp_line = 0.0;  ///< [m] v * yellow_lamp_period (docs/behaviour.md §L2.5)
  /// [m] where the planner must bring base_link to rest, relative to base_link: d for Stop and
  /// EmergencyStop, 0 for a restart suppression (stay here); empty otherwise.
  std::optional<double> stop_point_distance;
  /// docs/behaviour.md §L1.7, with v2i.use_remaining_time only: the V2I rule held this step (OR-ed into
  /// to_be_stopped), and the earliest red stop the predictions tell, minus now [s] (empty: none).
  bool v2i_stop = false;
  std::optional<double> v2i_time_to_red;
  /// stop_release_confirmation_time > 0 only: a latched stop saw no stop signal this cycle and is held
  /// (decision Stop/EmergencyStop as latched), and how long the go evidence has lasted [s].
  bool release_pending = false;
  double release_elapsed = 0.0;
  /// When IS_STOP_SIGNAL ran (verdict not NotEvaluated): the reduced elements it looked at, and the
  /// age of their observation, now - stamp [s] (0 when never received). For explain().
  std::vector<SignalElement> looked_at;
  double signal_age = 0.0;
  /// When IS_STOP_SIGNAL ran: the light was left out of the latest delivered message, so nothing was
  /// looked at (docs/behaviour.md §L1.3).
  bool missing_from_message = false;
};

class TrafficLightJudge {
 public:
  /// Throws std::invalid_argument if validate(params) does.
  explicit TrafficLightJudge(const TrafficLightJudgeParameters& params = {});

  /// Runs one planning cycle (algorithm at the top of this file) and returns its result. It formats
  /// no text: explain() (traffic_light_judge_explain.hpp) tells why, from the result.
  /// Throws std::invalid_argument if now, velocity, acceleration or a present distance is not
  /// finite, or if an observation comes with missing_from_message; the judge's state is then
  /// unchanged.
  TrafficLightJudgeResult step(const TrafficLightJudgeInput& in);

  /// Back to the state of a freshly constructed judge (APPROACH, nothing received).
  void reset();

  const TrafficLightJudgeParameters& parameters() const { return params_; }
  JudgeState state() const { return state_; }
  bool is_prev_state_stop() const { return is_prev_state_stop_; }
  YellowState yellow_state() const { return yellow_state_; }

 private:
  void measure(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) const;
  void step_go_out(double d);
  void enter_go_out();
  void approach(const TrafficLightJudgeInput& in, std::int64_t now_ns, TrafficLightJudgeResult& r);
  bool is_stop_signal(const TrafficLightJudgeInput& in, std::int64_t now_ns, SignalVerdict& verdict);
  std::int64_t run_stop_signal_timer(bool is_stop, std::int64_t now_ns);
  bool v2i_asks_stop(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) const;
  bool hold_latched_stop(bool to_be_stopped, std::int64_t now_ns, TrafficLightJudgeResult& r);
  bool suppress_restart(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r) const;
  void judge_stop(const TrafficLightJudgeInput& in, TrafficLightJudgeResult& r);

  TrafficLightJudgeParameters params_;
  std::int64_t hysteresis_ns_ = 0;
  std::int64_t timeout_ns_ = 0;

  JudgeState state_ = JudgeState::Approach;
  bool is_prev_state_stop_ = false;
  JudgeDecision latched_decision_ = JudgeDecision::Stop;  ///< Stop or EmergencyStop while latched
  std::optional<std::int64_t> stop_signal_start_ns_;       ///< the stop-signal timer
  std::int64_t release_confirmation_ns_ = 0;
  std::optional<std::int64_t> release_start_ns_;  ///< when the go evidence of a latched stop began

  std::optional<SignalObservation> received_;   ///< last delivered observation (node-level map); none
                                                ///< also after a message without this light
  std::optional<std::int64_t> stamp_ns_;        ///< stamp of the observation last looked at
  std::vector<SignalElement> looking_;          ///< reduced elements last looked at
  std::vector<SignalElement> previous_looking_;  ///< those of the step before (is_stop_signal's buffer)
  YellowState yellow_state_ = YellowState::NotYellow;
};

}  // namespace signalsim
