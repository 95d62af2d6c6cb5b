// The traffic-light stage of the step loop: which light the ego is approaching, what perception
// delivers of it, and what the judge decides (spec TLJ §1.1: one judge per light, created when the
// light comes within the horizon, dropped once the ego is past it, GO_OUT).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "sumo/approach_lights.hpp"
#include "traffic_light/perception_model.hpp"
#include "traffic_light/traffic_light_judge.hpp"

namespace signalsim {

struct LightStep {
  const sumo::ApproachLight* light = nullptr;  ///< the light being approached; null when none is left
  char own_state = 0;                 ///< true state of the ego's link
  bool judged = false;                ///< the judge ran (light within the horizon and regulating)
  std::string observed;               ///< what perception delivered this step ("" = nothing)
  double front_to_stop_line = 0.0;    ///< [m]
  TrafficLightJudgeResult result;
};

class TrafficLightStage {
 public:
  TrafficLightStage(std::vector<sumo::ApproachLight> lights, const TrafficLightJudgeParameters& judge,
                    const PerceptionModelParameters& perception, double horizon);

  /// The light the ego approaches now (null once every light is behind).
  const sumo::ApproachLight* current() const { return next_ < lights_.size() ? &lights_[next_] : nullptr; }

  /// One step: `state` is the current light's live state string (empty when there is none).
  LightStep step(double now, double s_front, double speed, double accel, const std::string& state);

 private:
  std::vector<sumo::ApproachLight> lights_;
  std::size_t next_ = 0;
  TrafficLightJudgeParameters judge_params_;
  PerceptionModel perception_;
  std::optional<TrafficLightJudge> judge_;
  double horizon_;
};

}  // namespace signalsim
