// judge_curves.csv: the dilemma-zone curves of the traffic-light judge as the run used them (its
// parameters), over the speed: what `python/signalsim-plot`'s dilemma.png draws instead of computing the
// judge's formulas again (docs/outputs.md "judge_curves.csv").
#pragma once

#include <string>

#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {

/// [m/s] the curves' speed range (0 to this, kJudgeCurveSpeedStep apart): 144 km/h.
inline constexpr double kJudgeCurveTopSpeed = 40.0;
inline constexpr double kJudgeCurveSpeedStep = 0.1;  ///< [m/s]

/// The CSV text: `speed,judge_distance,yellow_lamp_line`, one row per speed from 0 to
/// kJudgeCurveTopSpeed: calc_judge_line_dist_with_jerk_limit at that speed and zero acceleration
/// (docs/behaviour.md §L2.2) and speed x yellow_lamp_period (§L2.3), 3 decimals.
std::string judge_curves_csv(const TrafficLightJudgeParameters& params);

}  // namespace signalsim
