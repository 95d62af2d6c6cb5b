// A decider plugin that is signalsim's own turn-signal decider behind the C ABI
// (include/signalsim/decider_plugin.h): it rebuilds the route (a RouteMap) from ss_run's lanelets
// and the decider's parameters from ss_run's parameters, then each step calls TurnSignalDecider::decide
// with the ego and the merged request. Run in place of the reference, it must decide exactly as the
// reference does (tests/integration/sut_library_reference_test.sh): the proof that the ABI carries
// everything the reference decider reads.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <map>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

#include "map/route_map.hpp"
#include "signalsim/decider_plugin.h"
#include "turn_signal/turn_signal_decider.hpp"

namespace {
using namespace signalsim;

TurnDirection turn_direction(ss_turn_direction d) {
  switch (d) {
    case SS_TURN_STRAIGHT: return TurnDirection::Straight;
    case SS_TURN_LEFT: return TurnDirection::Left;
    case SS_TURN_RIGHT: return TurnDirection::Right;
    default: return TurnDirection::None;
  }
}

RoundaboutRole roundabout_role(ss_roundabout_role r) {
  switch (r) {
    case SS_ROUNDABOUT_ENTRY: return RoundaboutRole::Entry;
    case SS_ROUNDABOUT_INTERNAL: return RoundaboutRole::Internal;
    case SS_ROUNDABOUT_EXIT: return RoundaboutRole::Exit;
    default: return RoundaboutRole::None;
  }
}

RequestSource request_source(ss_module m) {
  switch (m) {
    case SS_MODULE_LANE_CHANGE: return RequestSource::LaneChange;
    case SS_MODULE_AVOIDANCE: return RequestSource::Avoidance;
    case SS_MODULE_PULL_OUT: return RequestSource::PullOut;
    case SS_MODULE_PULL_OVER: return RequestSource::PullOver;
    default: return RequestSource::None;
  }
}

Lanelet lanelet_of(const ss_lanelet& c) {
  Lanelet l;
  l.lane_id = c.id;
  l.edge_id = c.edge_id;
  l.junction_id = c.junction_id;
  l.is_internal = !l.junction_id.empty() || (!l.edge_id.empty() && l.edge_id.front() == ':');
  l.s_start = c.s_start;
  l.length = c.length;
  l.speed_limit = c.speed_limit;
  std::vector<Vec2> points;
  for (std::size_t i = 0; i < c.centerline_size; ++i) points.push_back({c.centerline[i].x, c.centerline[i].y});
  l.shape = Polyline(std::move(points));
  l.turn_direction = turn_direction(c.turn_direction);
  for (std::size_t i = 0; i < c.successor_turn_direction_count; ++i)
    l.successor_turn_directions.push_back(turn_direction(c.successor_turn_directions[i]));
  l.roundabout_role = roundabout_role(c.roundabout_role);
  l.roundabout_id = c.roundabout_id;
  l.leaves_ring_at_end = c.leaves_ring_at_end != 0;
  if (!std::isnan(c.turn_signal_distance)) l.turn_signal_distance = c.turn_signal_distance;
  for (std::size_t i = 0; i < c.tag_count; ++i) l.params[c.tags[i].key] = c.tags[i].value;
  return l;
}

// The decider's parameters by their names in ss_run.parameters (every one must be there).
TurnSignalParameters parameters_of(const ss_run& run) {
  std::map<std::string, std::string> by_name;
  for (std::size_t i = 0; i < run.parameter_count; ++i) by_name[run.parameters[i].key] = run.parameters[i].value;
  auto text = [&](const char* name) -> const std::string& {
    const auto it = by_name.find(name);
    if (it == by_name.end()) throw std::runtime_error(std::string("parameter ") + name + " is missing");
    return it->second;
  };
  auto number = [&](const char* name) { return std::strtod(text(name).c_str(), nullptr); };
  auto boolean = [&](const char* name) { return text(name) == "true"; };
  TurnSignalParameters p;
  p.base_link_to_front = run.base_link_to_front;
  p.turn_signal_intersection_search_distance = number("turn_signal_intersection_search_distance");
  p.turn_signal_intersection_angle_threshold_deg = number("turn_signal_intersection_angle_threshold_deg");
  p.turn_signal_search_time = number("turn_signal_search_time");
  p.turn_signal_minimum_search_distance = number("turn_signal_minimum_search_distance");
  p.turn_signal_path_backward_length = number("turn_signal_path_backward_length");
  p.forward_path_length = number("forward_path_length");
  p.turn_signal_roundabout_on_entry = text("turn_signal_roundabout_on_entry");
  p.turn_signal_roundabout_on_exit = text("turn_signal_roundabout_on_exit");
  p.turn_signal_roundabout_entry_indicator_persistence = boolean("turn_signal_roundabout_entry_indicator_persistence");
  p.turn_signal_roundabout_search_distance = number("turn_signal_roundabout_search_distance");
  p.turn_signal_roundabout_angle_threshold_deg = number("turn_signal_roundabout_angle_threshold_deg");
  p.turn_signal_roundabout_backward_depth = std::atoi(text("turn_signal_roundabout_backward_depth").c_str());
  p.turn_signal_shift_length_threshold = number("turn_signal_shift_length_threshold");
  p.turn_signal_remaining_shift_length_threshold = number("turn_signal_remaining_shift_length_threshold");
  p.turn_signal_remaining_distance_to_bound_threshold = number("turn_signal_remaining_distance_to_bound_threshold");
  p.turn_signal_on_swerving = boolean("turn_signal_on_swerving");
  p.turn_signal_roundabout_exit_signal_from_previous_exit =
      boolean("turn_signal_roundabout_exit_signal_from_previous_exit");
  return p;
}

struct ReferenceDecider {
  RouteMap route;
  TurnSignalDecider decider;
};

void write_error(char* error, size_t size, const char* what) {
  if (size > 0) std::snprintf(error, size, "%s", what);
}

}  // namespace

extern "C" {

uint32_t signalsim_plugin_abi_version(void) { return SIGNALSIM_PLUGIN_ABI_VERSION; }

const char* signalsim_plugin_name(void) { return "reference_decider (signalsim's own, through the C ABI)"; }

void* signalsim_decider_create(const ss_run* run, char* error, size_t error_size) {
  try {
    std::vector<Lanelet> lanelets;
    for (std::size_t i = 0; i < run->lanelet_count; ++i) lanelets.push_back(lanelet_of(run->lanelets[i]));
    return new ReferenceDecider{RouteMap(std::move(lanelets)), TurnSignalDecider(parameters_of(*run))};
  } catch (const std::exception& e) {
    write_error(error, error_size, e.what());
    return nullptr;
  }
}

int signalsim_decider_step(void* decider, const ss_step* step, ss_blinker* blinker, char* error, size_t error_size) {
  auto* self = static_cast<ReferenceDecider*>(decider);
  const EgoOnRoute ego{step->ego.s_front, step->ego.s_base, step->ego.speed};
  const ss_request& r = step->request;
  TurnSignalInfo request;
  request.turn = static_cast<TurnIndicator>(r.turn);
  request.hazard = static_cast<HazardLights>(r.hazard);
  request.source = request_source(r.module);
  request.desired_start = r.desired_start;
  request.desired_end = r.desired_end;
  request.required_start = r.required_start;
  request.required_end = r.required_end;
  try {
    const TurnSignalDecision d = self->decider.decide(self->route, ego, request);
    *blinker = d.hazard == HazardLights::Enable      ? SS_BLINKER_HAZARD
               : d.turn == TurnIndicator::EnableLeft  ? SS_BLINKER_LEFT
               : d.turn == TurnIndicator::EnableRight ? SS_BLINKER_RIGHT
                                                      : SS_BLINKER_NONE;
    return 0;
  } catch (const std::exception& e) {
    write_error(error, error_size, e.what());
    return 1;
  }
}

void signalsim_decider_destroy(void* decider) { delete static_cast<ReferenceDecider*>(decider); }

}  // extern "C"
