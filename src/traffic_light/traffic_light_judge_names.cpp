// Names of the judge's enums (traffic_light_judge.hpp), as the timeline, events and reasons spell them.
#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {

std::string_view to_string(JudgeState s) {
  switch (s) {
    case JudgeState::Approach: return "APPROACH";
    case JudgeState::GoOut: return "GO_OUT";
  }
  return "invalid";
}

std::string_view to_string(JudgeDecision d) {
  switch (d) {
    case JudgeDecision::None: return "none";
    case JudgeDecision::Pass: return "pass";
    case JudgeDecision::Stop: return "stop";
    case JudgeDecision::EmergencyStop: return "emergency_stop";
  }
  return "invalid";
}

std::string_view to_string(JudgeZone z) {
  switch (z) {
    case JudgeZone::None: return "none";
    case JudgeZone::Stoppable: return "stoppable";
    case JudgeZone::OptionalZone: return "optional_zone";
    case JudgeZone::PassThroughYellow: return "pass_through_yellow";
    case JudgeZone::DilemmaZone: return "dilemma_zone";
    case JudgeZone::Slow: return "slow";
  }
  return "invalid";
}

std::string_view to_string(SignalVerdict v) {
  switch (v) {
    case SignalVerdict::NotEvaluated: return "not_evaluated";
    case SignalVerdict::NeverReceived: return "never_received";
    case SignalVerdict::TimedOut: return "timed_out";
    case SignalVerdict::ArrowAwareYellowPass: return "arrow_aware_yellow_pass";
    case SignalVerdict::Go: return "go";
    case SignalVerdict::Stop: return "stop";
  }
  return "invalid";
}

std::string_view to_string(YellowState y) {
  switch (y) {
    case YellowState::NotYellow: return "not_yellow";
    case YellowState::FromGreen: return "from_green";
    case YellowState::FromNonGreen: return "from_non_green";
  }
  return "invalid";
}

}  // namespace signalsim
