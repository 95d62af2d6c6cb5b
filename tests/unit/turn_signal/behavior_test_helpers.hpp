// Small builders shared by the behaviour-signal unit tests (request and same_info: test_helpers.hpp).
#pragma once

#include "turn_signal/behavior_signal.hpp"
#include "turn_signal/turn_signal_info.hpp"
#include "test_helpers.hpp"  // request, same_info

namespace signalsim::test {

inline const BehaviorSignalParameters kParams{};  // the defaults

/// Ego with its front bumper at s_front.
inline EgoOnRoute ego_front(double s_front, double speed = 5.0, double b2f = kB2F) {
  return EgoOnRoute{.s_front = s_front, .s_base = s_front - b2f, .speed = speed};
}

/// An avoidance-style request: line [100, 120], raw shift a -> b, path [0, 300], lane +-1.6 m.
inline BehaviorSignalInput shift_input(double a = 0.0, double b = 2.0) {
  BehaviorSignalInput in;
  in.shift_line = {100.0, 120.0, a, b};
  in.path_front = 0.0;
  in.path_back = 300.0;
  in.current_shift_length = a;
  in.source = RequestSource::Avoidance;
  in.lane.left_half_width = 1.6;
  in.lane.right_half_width = 1.6;
  return in;
}

inline bool is_none(const TurnSignalInfo& info, const BehaviorSignalInput& in) {
  return info.turn == TurnIndicator::NoCommand && info.hazard == HazardLights::NoCommand &&
         info.desired_start == in.path_front && info.required_start == in.path_front &&
         info.desired_end == in.path_back && info.required_end == in.path_back;
}

inline bool is_empty(const TurnSignalInfo& info) {
  return info.turn == TurnIndicator::NoCommand && info.hazard == HazardLights::NoCommand &&
         info.source == RequestSource::None && info.desired_start == 0.0 && info.desired_end == 0.0 &&
         info.required_start == 0.0 && info.required_end == 0.0;
}

}  // namespace signalsim::test
