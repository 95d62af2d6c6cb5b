#include "scenario/light_stage.hpp"

namespace signalsim {

TrafficLightStage::TrafficLightStage(std::vector<sumo::ApproachLight> lights, const TrafficLightJudgeParameters& judge,
                                     const PerceptionModelParameters& perception, double horizon)
    : lights_(std::move(lights)), judge_params_(judge), perception_(perception), horizon_(horizon) {}

LightStep TrafficLightStage::step(double now, double s_front, double speed, double accel, const std::string& state) {
  LightStep out;
  const sumo::ApproachLight* light = current();
  if (!light) return out;
  out.light = light;
  out.own_state = light->link_index >= 0 && static_cast<std::size_t>(light->link_index) < state.size()
                      ? state[static_cast<std::size_t>(light->link_index)]
                      : '?';
  out.front_to_stop_line = light->s_stop_line - s_front;
  if (out.front_to_stop_line > horizon_) return out;  // not on the path window yet

  // spec SUMO §3: an 'o'/'O' link is not regulating: the judge stays out, SUMO's right of way applies.
  const auto truth = sumo::signal_elements(state, *light);
  if (!truth) return out;
  // Perception: what a camera delivers of the true state (spec TLJ Decisions: perception model).
  const auto observation = perception_.observe(*truth, out.front_to_stop_line, now);
  if (observation) out.observed = sumo::describe_elements(observation->elements);

  if (!judge_) judge_.emplace(judge_params_);
  TrafficLightJudgeInput in;
  in.now = now;
  in.distance_to_stop_point = distance_to_stop_point(out.front_to_stop_line, judge_params_.stop_margin);
  in.velocity = speed;
  in.acceleration = accel;
  in.observation = observation;
  in.is_vehicle_stopped = is_vehicle_stopped(speed);
  in.turn_direction = sumo::judge_turn_direction(light->direction);
  in.is_turn_lane = light->direction == TurnDirection::Left || light->direction == TurnDirection::Right;
  in.has_static_arrow = light->has_arrow;
  out.result = judge_->step(in);
  out.judged = true;
  if (out.result.state == JudgeState::GoOut) {  // past the stop line: on to the next light
    judge_.reset();
    ++next_;
  }
  return out;
}

}  // namespace signalsim
