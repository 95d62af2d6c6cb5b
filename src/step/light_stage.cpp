#include "step/light_stage.hpp"

#include <utility>

namespace signalsim {
namespace {

constexpr double kDeadLine = -2.0;  // [m] docs/behaviour.md §L1.2 step 3.1: past this the light is behind

// Each light's perception draws from its own seeded streams, so a capture of one light is never
// delivered for another and adding a light does not change the draws of the others.
PerceptionModelParameters perception_for(PerceptionModelParameters p, std::size_t index) {
  p.seed ^= 0x9E3779B97F4A7C15ULL * (index + 1);
  return p;
}

// Each light's V2I channel has its own stream too (a message of one light never reaches another).
V2iChannelParameters channel_for(V2iChannelParameters p, std::size_t index) {
  p.seed ^= 0x9E3779B97F4A7C15ULL * (index + 1);
  return p;
}

}  // namespace

std::vector<SignalPrediction> v2i_predictions(const std::vector<sumo::LightProgram>& programs,
                                              const sumo::LightTiming& timing, const sumo::ApproachLight& light) {
  std::vector<SignalPrediction> out;
  const sumo::LightProgram* program = sumo::find_program(programs, timing.program);
  if (!program) return out;
  for (const sumo::PhasePrediction& phase : sumo::predict_phases(*program, timing.phase, timing.next_switch))
    if (auto elements = sumo::signal_elements(phase.state, light)) out.push_back({phase.stamp, std::move(*elements)});
  return out;
}

TrafficLightStage::TrafficLightStage(std::vector<sumo::ApproachLight> lights, const TrafficLightJudgeParameters& judge,
                                     const PerceptionModelParameters& perception, double horizon,
                                     V2iChannelParameters v2i)
    : judge_params_(judge), horizon_(horizon), v2i_(std::move(v2i)) {
  for (std::size_t i = 0; i < lights.size(); ++i) {
    lights_.emplace_back(std::move(lights[i]), PerceptionModel(perception_for(perception, i)));
    // The channel counts a message while the judge would count a camera result (tl_state_timeout).
    if (judge_params_.v2i.use_remaining_time) {
      V2iChannelParameters channel = channel_for(v2i_, i);
      channel.max_age = judge_params_.tl_state_timeout;
      lights_.back().v2i.emplace(channel);
    }
  }
}

const sumo::ApproachLight* TrafficLightStage::next_light() const {
  for (std::size_t i = first_; i < lights_.size(); ++i)
    if (!lights_[i].dropped) return &lights_[i].light;
  return nullptr;
}

// The signal elements a state shows the ego: worked out again only when the light's state changed.
const std::optional<std::vector<SignalElement>>& TrafficLightStage::Tracked::truth_of(const std::string& state) {
  if (!truth_known || state != truth_state) {
    truth = sumo::signal_elements(state, light);
    truth_state = state;
    truth_known = true;
  }
  return truth;
}

const std::string& TrafficLightStage::Tracked::describe(const std::vector<SignalElement>& elements) {
  if (!described || elements != described_elements) {
    described_text = sumo::describe_elements(elements);
    described_elements = elements;
    described = true;
  }
  return described_text;
}

void TrafficLightStage::demand(double s_front, ObservationDemand& want) const {
  bool window_empty = true;
  for (std::size_t i = first_; i < lights_.size(); ++i) {
    const Tracked& t = lights_[i];
    if (t.dropped) continue;
    if (t.light.s_stop_line - s_front > horizon_) {  // route order: the rest are further ahead
      if (window_empty) want.light(t.light.tls_id);  // the next light, for the timeline row
      break;
    }
    window_empty = false;
    LightDemand& light = want.light(t.light.tls_id);
    if (t.v2i) {
      light.timing = true;
      if (!t.programs) light.programs = true;
    }
  }
}

std::vector<LightStep> TrafficLightStage::step(double now, double s_front, double speed, double accel,
                                               const StepObservation& seen) {
  std::vector<LightStep> out;
  std::size_t in_window = 0;  // an upper bound (dropped lights counted): one allocation a step
  while (first_ + in_window < lights_.size() && lights_[first_ + in_window].light.s_stop_line - s_front <= horizon_)
    ++in_window;
  out.reserve(in_window);
  for (std::size_t i = first_; i < lights_.size(); ++i) {
    Tracked& t = lights_[i];
    if (t.dropped) continue;
    const double front_to_line = t.light.s_stop_line - s_front;
    if (front_to_line > horizon_) break;  // route order: the rest are further ahead
    LightStep step;
    step.light = &t.light;
    step.front_to_stop_line = front_to_line;
    const LightReading& reading = *seen.light(t.light.tls_id);  // demanded: in the window
    const std::string& state = reading.state;
    step.own_state = t.light.link_index >= 0 && static_cast<std::size_t>(t.light.link_index) < state.size()
                         ? state[static_cast<std::size_t>(t.light.link_index)]
                         : '?';
    // docs/behaviour.md §S3: an 'o'/'O' link is not regulating: no judge, SUMO's right of way applies.
    if (const auto& truth = t.truth_of(state)) {
      SignalDelivery delivery = t.perception.observe(*truth, front_to_line, now);
      if (delivery.observation) step.observed = t.describe(delivery.observation->elements);
      if (delivery.missing_from_message) step.observed = kMissingFromMessage;
      // A light judge under test gets a message without its light as one with nothing recognised.
      if (delivery.delivered() && keep_delivered_) {
        step.delivered = true;
        if (delivery.observation) step.elements = delivery.observation->elements;
      }
      if (!t.judge) t.judge.emplace(judge_params_);
      TrafficLightJudgeInput in;
      in.now = now;
      in.distance_to_stop_point = distance_to_stop_point(front_to_line, judge_params_.stop_margin);
      in.velocity = speed;
      in.acceleration = accel;
      in.observation = std::move(delivery.observation);  // not used again
      in.missing_from_message = delivery.missing_from_message;
      in.is_vehicle_stopped = is_vehicle_stopped(speed);
      in.turn_direction = sumo::judge_turn_direction(t.light.direction);
      in.is_turn_lane = t.light.direction == TurnDirection::Left || t.light.direction == TurnDirection::Right;
      in.has_static_arrow = t.light.has_arrow;
      if (t.v2i) {  // docs/behaviour.md §L1.7: the program once, the timing every step
        if (!t.programs) t.programs = *reading.programs;
        in.predictions = t.v2i->step(v2i_predictions(*t.programs, *reading.timing, t.light), now);
      }
      step.result = t.judge->step(in);
      step.judged = true;
    }
    // Behind the dead line (GO_OUT, or an unregulated light) the light is done.
    if ((step.judged && step.result.state == JudgeState::GoOut) || front_to_line < kDeadLine) {
      t.dropped = true;
      t.judge.reset();
    }
    out.push_back(std::move(step));
  }
  while (first_ < lights_.size() && lights_[first_].dropped) ++first_;
  return out;
}

bool light_decides_next_junction(const RouteMap& route, double s_front, const std::vector<LightStep>& lights) {
  if (route.empty()) return false;
  const std::size_t here = route.index_at(s_front);
  const auto stop_signal = [](char c) { return c == 'r' || c == 'u' || c == 'y' || c == 'Y'; };
  // Within reach of the line of a light the ego stops for, whatever lanes lie between (a stub
  // approach behind a tiny junction): SUMO's stopline gap would hold the ego 1 m short there.
  for (const LightStep& l : lights)
    if (stop_signal(l.own_state) && l.result.stop_point_distance && l.front_to_stop_line > 0.0 &&
        l.front_to_stop_line <= kStoplineGapReach)
      return true;
  if (route.at(here).is_internal) return false;  // inside a junction: its right of way is SUMO's
  for (const LightStep& l : lights) {
    if (l.light->route_index != here) continue;
    return stop_signal(l.own_state);
  }
  return false;
}

}  // namespace signalsim
