// The C ABI's values made from the SUT values; see c_abi_values.hpp.
#include "sut/c_abi_values.hpp"

#include <cmath>
#include <limits>

namespace signalsim {
namespace {

ss_roundabout_role c_roundabout_role(RoundaboutRole r) {
  switch (r) {
    case RoundaboutRole::Entry: return SS_ROUNDABOUT_ENTRY;
    case RoundaboutRole::Internal: return SS_ROUNDABOUT_INTERNAL;
    case RoundaboutRole::Exit: return SS_ROUNDABOUT_EXIT;
    case RoundaboutRole::None: break;
  }
  return SS_ROUNDABOUT_NONE;
}

ss_module c_module(RequestSource source) {
  switch (source) {
    case RequestSource::LaneChange: return SS_MODULE_LANE_CHANGE;
    case RequestSource::Avoidance: return SS_MODULE_AVOIDANCE;
    case RequestSource::PullOut: return SS_MODULE_PULL_OUT;
    case RequestSource::PullOver: return SS_MODULE_PULL_OVER;
    default: break;
  }
  return SS_MODULE_NONE;
}

// The signal element's texts: static strings, so a step's elements point to nothing of the step.
ss_signal_element c_element(const SignalElement& e) {
  return {to_string(e.color).data(), to_string(e.shape).data(), to_string(e.status).data(), e.confidence};
}

}  // namespace

ss_turn_direction c_turn_direction(TurnDirection d) {
  switch (d) {
    case TurnDirection::Straight: return SS_TURN_STRAIGHT;
    case TurnDirection::Left: return SS_TURN_LEFT;
    case TurnDirection::Right: return SS_TURN_RIGHT;
    case TurnDirection::None: break;
  }
  return SS_TURN_NONE;
}

bool blinker_from_c(int value, Blinker& out) {
  switch (value) {
    case SS_BLINKER_NONE: out = Blinker::None; return true;
    case SS_BLINKER_LEFT: out = Blinker::Left; return true;
    case SS_BLINKER_RIGHT: out = Blinker::Right; return true;
    case SS_BLINKER_HAZARD: out = Blinker::Hazard; return true;
    default: return false;
  }
}

const char* CRun::keep(const std::string& text) { return texts_.emplace_back(text).c_str(); }

CRun::CRun(const SutRun& run) {
  for (const auto& [name, value] : run.parameters) parameters_.push_back({keep(name), keep(value)});
  const std::size_t n = run.route ? run.route->size() : 0;
  tags_.resize(n);
  centerlines_.resize(n);
  successors_.resize(n);
  lanelets_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Lanelet& l = run.route->at(i);
    for (const auto& [key, value] : l.params) tags_[i].push_back({keep(key), keep(value)});
    for (const Vec2& p : l.shape.points()) centerlines_[i].push_back({p.x, p.y});
    for (TurnDirection d : l.successor_turn_directions) successors_[i].push_back(c_turn_direction(d));
    ss_lanelet& c = lanelets_[i];
    c.id = keep(l.lane_id);
    c.edge_id = keep(l.edge_id);
    c.junction_id = keep(l.junction_id);
    c.s_start = l.s_start;
    c.s_end = l.s_end();
    c.length = l.length;
    c.speed_limit = l.speed_limit;
    c.turn_direction = c_turn_direction(l.turn_direction);
    c.roundabout_role = c_roundabout_role(l.roundabout_role);
    c.roundabout_id = keep(l.roundabout_id);
    c.turn_signal_distance = l.turn_signal_distance.value_or(std::numeric_limits<double>::quiet_NaN());
    c.tags = tags_[i].data();
    c.tag_count = tags_[i].size();
    c.centerline = centerlines_[i].data();
    c.centerline_size = centerlines_[i].size();
    c.successor_turn_directions = successors_[i].data();
    c.successor_turn_direction_count = successors_[i].size();
    c.leaves_ring_at_end = l.leaves_ring_at_end ? 1 : 0;
  }
  for (const SutShiftLine& s : run.shift_lines)
    shift_lines_.push_back({c_module(s.module), keep(s.edge_id), s.s_start, s.s_end, s.shift});
  run_.scenario = keep(run.scenario);
  run_.step_length = run.step_length;
  run_.vehicle_length = run.vehicle_length;
  run_.base_link_to_front = run.base_link_to_front;
  run_.parameters = parameters_.data();
  run_.parameter_count = parameters_.size();
  run_.lanelets = lanelets_.data();
  run_.lanelet_count = lanelets_.size();
  run_.shift_lines = shift_lines_.data();
  run_.shift_line_count = shift_lines_.size();
}

const ss_step& CStep::fill(const SutStep& step) {
  step_.time = step.time;
  const SutEgo& e = step.ego;
  step_.ego = {e.x, e.y, e.yaw, e.speed, e.accel, e.s_front, e.s_base};
  step_.window_first = step.window.first;
  step_.window_last = step.window.last;
  const TurnSignalInfo& r = step.request;
  step_.request = {c_module(r.source),
                   static_cast<ss_turn_indicator>(r.turn),
                   static_cast<ss_hazard>(r.hazard),
                   r.desired_start,
                   r.desired_end,
                   r.required_start,
                   r.required_end};
  lights_.clear();
  elements_.clear();
  for (const SutLight& l : step.lights)
    for (const SignalElement& e : l.elements) elements_.push_back(c_element(e));
  std::size_t first = 0;
  for (const SutLight& l : step.lights) {
    lights_.push_back({l.tls_id.c_str(), l.link_index, l.route_index, l.stop_line_s, l.distance, l.delivered ? 1 : 0,
                       elements_.data() + first, l.elements.size(),
                       l.time_to_red.value_or(std::numeric_limits<double>::quiet_NaN())});
    first += l.elements.size();
  }
  step_.lights = lights_.data();
  step_.light_count = lights_.size();
  return step_;
}

}  // namespace signalsim
