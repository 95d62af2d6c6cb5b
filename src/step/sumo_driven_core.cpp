// The observation of a SUMO-driven run; see sumo_driven_core.hpp for the rules.
#include "step/sumo_driven_core.hpp"

#include <string>
#include <utility>

#include "session/sumo_session.hpp"
#include "step/light_outcomes.hpp"
#include "step/stuck_watch.hpp"

namespace signalsim {
namespace {

constexpr double kLeftBehind = 2.0;          // [m] past its stop line a light is left behind (docs/behaviour.md §L1.2)
constexpr double kLightWindow = 300.0;       // [m] lights ahead whose states are followed

// SUMO stops for these on its own (red, yellow); a rest at a green link (yielding) is no stop at the light.
bool asks_to_stop(char state) { return state == 'r' || state == 'u' || state == 'y' || state == 'Y'; }

char link_state(const LightReading* reading, int link_index) {
  if (!reading || link_index < 0 || static_cast<std::size_t>(link_index) >= reading->state.size()) return 0;
  return reading->state[static_cast<std::size_t>(link_index)];
}

// Extends the last off-plan stretch or starts one.
void note_off_plan(RunRecord& record, const TimelineRow& row, const std::string& planned, bool continues) {
  if (continues && !record.off_plan.empty() && record.off_plan.back().lane == row.lane) {
    record.off_plan.back().s_to = row.s_front;
    ++record.off_plan.back().steps;
    return;
  }
  record.off_plan.push_back({row.lane, planned, row.s_front, row.s_front, 1});
}

}  // namespace

std::size_t LightWatch::nearest_after(double s_front) const {
  std::size_t k = nearest_;
  while (k < lights_.size() && s_front > lights_[k].s_stop_line + kLeftBehind) ++k;
  return k;
}

// The lights within the window ahead of the last nearest one, and the nearest after this row when it
// lies beyond the window.
void LightWatch::demand(double s_front, ObservationDemand& want) const {
  for (std::size_t k = nearest_; k < lights_.size(); ++k) {
    if (lights_[k].s_stop_line + kCrossingTolerance > s_front + kLightWindow) break;
    want.light(lights_[k].tls_id);
  }
  const std::size_t nearest = nearest_after(s_front);
  if (nearest < lights_.size()) want.light(lights_[nearest].tls_id);
}

void LightWatch::observe(const TimelineRow& row, const StepObservation& seen, RunRecord& record) {
  // Red crossings: the state each light had at the previous row is the one the step began with.
  for (std::size_t k = nearest_; k < lights_.size(); ++k) {
    const sumo::ApproachLight& light = lights_[k];
    if (light.s_stop_line + kCrossingTolerance > row.s_front + kLightWindow) break;
    if (have_previous_ && crossed_on_red(previous_front_, row.s_front, light.s_stop_line, states_[k]))
      record.red_violations.push_back({light.tls_id, row.time, row.s_front});
    states_[k] = link_state(seen.light(light.tls_id), light.link_index);
  }
  nearest_ = nearest_after(row.s_front);
  if (nearest_ < lights_.size() && lights_[nearest_].s_stop_line + kCrossingTolerance > row.s_front + kLightWindow)
    states_[nearest_] = link_state(seen.light(lights_[nearest_].tls_id), lights_[nearest_].link_index);
  // A stop: at rest on the nearest light's approach lanelet while its link asks to stop.
  const bool at_rest = row.speed < kRestSpeed;
  if (at_rest && !resting_ && nearest_ < lights_.size()) {
    const sumo::ApproachLight& light = lights_[nearest_];
    if (row.s_front >= route_.at(light.route_index).s_start && asks_to_stop(states_[nearest_])) {
      const double stop_s = light.s_stop_line - stop_margin_;
      LightStop stop;
      stop.tl_id = light.tls_id;
      stop.time = row.time;
      stop.stop_s = stop_s;
      stop.rest_s = row.s_front;
      stop.error = row.s_front - stop_s;
      stop.by_judge = false;
      record.stops.push_back(stop);
      resting_ = true;
    }
  }
  if (!at_rest) resting_ = false;
  previous_front_ = row.s_front;
  have_previous_ = true;
}

SumoDrivenCore::SumoDrivenCore(CoreSetup setup)
    : route_(setup.route),
      end_time_(run_end_time(setup.scenario, setup.start_time)),
      lights_(std::move(setup.lights), setup.route, setup.scenario.run_params.judge.stop_margin),
      locator_(setup.route, setup.scenario.ego.depart_pos) {
  record_.driver = Driver::Sumo;
  record_.base_link_to_front = setup.scenario.ego.base_link_to_front;
  record_.sumo = std::move(setup.sumo);
}

ObservationDemand SumoDrivenCore::demand(const sumo::EgoState& ego) {
  place_ = locator_.locate(ego.lane, ego.edge, ego.lane_pos);
  ObservationDemand want;
  want.signals = true;
  lights_.demand(place_.s_front, want);
  return want;
}

Commands SumoDrivenCore::step(const StepObservation&) { 
  Commands c;
  c.drive = false;
  return c;
}

bool SumoDrivenCore::record(const StepObservation& seen, const StepFeedback& feedback) {
  const sumo::EgoState& observed = seen.ego;
  if (!place_.on_route) ++record_.off_route_steps;  // the lane is not on the route: s held (counted)
  const int signals = seen.signals.value_or(0);
  const EgoOnRoute ego{place_.s_front, place_.s_front - record_.base_link_to_front, observed.speed};
  TimelineRow row = timeline_row(observed, ego, observed.lateral_offset, std::nullopt, blinker_of_signals(signals),
                                 RequestSource::Sumo, nullptr, std::nullopt);
  row.sumo_signals = signals;
  lights_.observe(row, seen, record_);
  if (const sumo::ApproachLight* light = lights_.nearest()) {
    row.tl_id = light->tls_id;
    row.tl_state = lights_.nearest_state();
  }
  const bool off_plan = place_.on_route && !place_.on_plan;
  if (off_plan) note_off_plan(record_, row, route_.at(place_.index).lane_id, previous_off_plan_);
  previous_off_plan_ = off_plan;
  events_.record(row, {}, record_);  // the blinker's changes (no judge, no lane-change phases)
  record_.rows.push_back(std::move(row));
  if (!feedback.alive) {
    record_.arrived = true;
    return true;
  }
  return feedback.time >= end_time_ - 1e-9;
}

RunRecord SumoDrivenCore::finish(int collisions) {
  record_.collisions = collisions;
  return std::move(record_);
}

}  // namespace signalsim
