// The ego's defaults: the one home of the numbers a scenario's ego has when it names none, which
// every struct that carries a piece of the ego starts from (scenario/, session/, the planners, the
// decider, the generator). Autoware's default car at 50 km/h, with SUMO's passenger vType where SUMO
// sets the value (docs/scenario.md `ego`).
#pragma once

namespace signalsim::vehicle_defaults {

inline constexpr double kMaxSpeed = 13.89;        ///< [m/s] 50 km/h
inline constexpr double kLength = 4.5;            ///< [m] Autoware's default car
inline constexpr double kWidth = 1.8;             ///< [m] SUMO's DEFAULT_VEHTYPE
/// Rear-axle centre (base_link) to front bumper [m]: the rear axle 0.8 m ahead of the rear bumper.
inline constexpr double kBaseLinkToFront = 3.7;
/// base_link_to_front / length, for a length given without base_link_to_front.
inline constexpr double kBaseLinkShare = kBaseLinkToFront / kLength;
/// The ego vType's decel in SUMO [m/s^2]: the most SUMO brakes with speed-mode bit 2, and its
/// look-ahead for lane choices.
inline constexpr double kSumoDecel = 4.5;

}  // namespace signalsim::vehicle_defaults
