// The C ABI of include/signalsim/decider_plugin.h for the bundled autoware_core decider: create
// copies the route into the rule's lanes (turn direction, turn_signal_distance, centerline length
// and required end point), step runs path_generator's get_turn_signal (turn_signal_rule.hpp) on the
// ego's base_link s and signed speed. The window, the behaviour request and the lights are not read:
// path_generator looks at neither (it publishes hazard NO_COMMAND always and ignores the modules).
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>
#include <vector>

#include "signalsim/decider_plugin.h"
#include "turn_signal_rule.hpp"

namespace {

using signalsim::autoware_core::Command;
using signalsim::autoware_core::Lane;
using signalsim::autoware_core::Point2;
using signalsim::autoware_core::Settings;
using signalsim::autoware_core::TurnDirection;

struct Decider {
  std::vector<Lane> route;
  Settings settings;
};

void write_error(char* error, size_t size, const char* text) {
  if (error != nullptr && size > 0) std::snprintf(error, size, "%s", text);
}

TurnDirection direction_of(ss_turn_direction d) {
  switch (d) {
    case SS_TURN_STRAIGHT: return TurnDirection::Straight;
    case SS_TURN_LEFT: return TurnDirection::Left;
    case SS_TURN_RIGHT: return TurnDirection::Right;
    default: return TurnDirection::None;
  }
}

Lane lane_of(const ss_lanelet& in, double angle_threshold_deg) {
  Lane lane;
  lane.s_start = in.s_start;
  lane.s_end = in.s_end;
  lane.turn_direction = direction_of(in.turn_direction);
  if (std::isfinite(in.turn_signal_distance)) lane.turn_signal_distance = in.turn_signal_distance;
  std::vector<Point2> centerline;
  for (size_t k = 0; in.centerline != nullptr && k < in.centerline_size; ++k) {
    centerline.push_back({in.centerline[k].x, in.centerline[k].y});
  }
  lane.geometric_length = centerline.size() >= 2 ? signalsim::autoware_core::polyline_length(centerline) : in.length;
  if (lane.turn_direction != TurnDirection::None) {
    lane.required_end_arc = signalsim::autoware_core::required_end_arc(centerline, angle_threshold_deg);
  }
  return lane;
}

ss_blinker blinker_of(Command command) {
  switch (command) {
    case Command::Left: return SS_BLINKER_LEFT;
    case Command::Right: return SS_BLINKER_RIGHT;
    default: return SS_BLINKER_NONE;  // NO_COMMAND and DISABLE both leave the blinker off
  }
}

}  // namespace

extern "C" {

uint32_t signalsim_plugin_abi_version(void) { return SIGNALSIM_PLUGIN_ABI_VERSION; }

const char* signalsim_plugin_name(void) { return "autoware_core path_generator 2d693b82"; }

void* signalsim_decider_create(const ss_run* run, char* error, size_t error_size) {
  if (run == nullptr || (run->lanelet_count > 0 && run->lanelets == nullptr)) {
    write_error(error, error_size, "autoware_core: create was given no route");
    return nullptr;
  }
  try {
    auto* decider = new Decider;
    decider->settings.base_link_to_front = run->base_link_to_front;
    for (size_t i = 0; i < run->lanelet_count; ++i) {
      decider->route.push_back(lane_of(run->lanelets[i], decider->settings.angle_threshold_deg));
    }
    return decider;
  } catch (const std::exception& e) {
    write_error(error, error_size, e.what());
    return nullptr;
  }
}

int signalsim_decider_step(void* decider, const ss_step* step, ss_blinker* blinker, char* error, size_t error_size) {
  if (decider == nullptr || step == nullptr || blinker == nullptr) {
    write_error(error, error_size, "autoware_core: step was given a null pointer");
    return 1;
  }
  const auto* self = static_cast<const Decider*>(decider);
  const signalsim::autoware_core::EgoState ego{step->ego.s_base, step->ego.speed};
  *blinker = blinker_of(signalsim::autoware_core::get_turn_signal(self->route, ego, self->settings));
  return 0;
}

void signalsim_decider_destroy(void* decider) { delete static_cast<Decider*>(decider); }

}  // extern "C"
