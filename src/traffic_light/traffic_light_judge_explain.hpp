// The traffic-light judge's reason line: why one step of TrafficLightJudge decided what it did, as one
// human-readable line for logs and tests. Kept apart from the decision (traffic_light_judge.cpp) so
// that a step formats no text: no run output writes the line.
#pragma once

#include <string>

#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {

/// The reason line of one step: `result` as TrafficLightJudge::step(`input`) returned it, for a judge
/// made with `params`. Starts with the decision's name ("none", "pass", "stop", "emergency_stop"),
/// then why: the state change, the signal verdict (with the elements looked at), the hysteresis,
/// the pass judge's zone, the V2I rule and a held release, as they applied. A pure function (the
/// V2I rule, itself pure, is evaluated again for its horizon); never throws for a step's result.
std::string explain(const TrafficLightJudgeResult& result, const TrafficLightJudgeInput& input,
                    const TrafficLightJudgeParameters& params);

}  // namespace signalsim
