// Small builders shared by the turn-signal unit tests.
#pragma once

#include "turn_signal/turn_signal_info.hpp"

namespace signalsim::test {

constexpr auto kLeft = TurnIndicator::EnableLeft;
constexpr auto kRight = TurnIndicator::EnableRight;
constexpr auto kDisable = TurnIndicator::Disable;
inline const TurnSignalInfo kEmpty{};
// BehaviorSignalParameters::base_link_to_front default (the behaviour modules' and the route sketches' ego)
constexpr double kB2F = 3.7;

constexpr double kBaseLinkToFront = 1.0;  // docs/behaviour.md §T9 setParameters(1.0, ...)

inline EgoOnRoute ego_at_base(double s_base, double base_link_to_front = kBaseLinkToFront) {
  return EgoOnRoute{.s_front = s_base + base_link_to_front, .s_base = s_base, .speed = 0.0};
}

inline TurnSignalInfo request(TurnIndicator turn, double desired_start, double desired_end, double required_start,
                              double required_end, RequestSource source = RequestSource::None) {
  return TurnSignalInfo{.turn = turn,
                        .hazard = HazardLights::NoCommand,
                        .source = source,
                        .desired_start = desired_start,
                        .desired_end = desired_end,
                        .required_start = required_start,
                        .required_end = required_end};
}

inline bool same_info(const TurnSignalInfo& a, const TurnSignalInfo& b) {
  return a.turn == b.turn && a.hazard == b.hazard && a.source == b.source && a.desired_start == b.desired_start &&
         a.desired_end == b.desired_end && a.required_start == b.required_start && a.required_end == b.required_end;
}

}  // namespace signalsim::test
