// StepAnswers: what SUMO answered during the current step, kept so that the session asks each thing
// at most once a step (SessionImpl, session_impl.hpp): the time, the ego's state, signals and lane
// index, and the state and timing of each light asked for; over TraCI also the subscribed answers
// they are read from. Nothing in it outlives the step: step() forgets it all, moving the ego
// (move_back) forgets the ego's part, shifting a light's program the lights'. Other TraCI clients
// (--connect) change nothing in between: SUMO runs all commands of one client before the next
// client's, until it asks for the step (TraCI protocol, "Basic Flow"). Include it after
// <libsumo/libsumo.h> or <libsumo/libtraci.h>, through session_impl.hpp.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "sumo/signal_timing.hpp"
#include "sumo/sumo_session.hpp"

namespace signalsim::sumo {

struct StepAnswers {
  // Over TraCI: the subscribed variables, as the step's answer brought them.
  std::optional<libsumo::TraCIResults> simulation_variables;
  std::optional<libsumo::TraCIResults> ego_variables;
  /// The ego was moved (moveTo) since the step: the subscribed variables no longer say where it is.
  bool ego_moved = false;

  std::optional<double> time;
  std::optional<EgoState> ego;
  std::optional<int> ego_signals;
  std::optional<int> ego_lane_index;
  std::vector<std::pair<std::string, std::string>> light_states;  ///< light id, state string
  std::vector<std::pair<std::string, LightTiming>> light_timings;

  void forget() {
    simulation_variables.reset();
    time.reset();
    ego_moved = false;
    forget_ego();
    forget_lights();
  }
  void forget_ego() {
    ego_variables.reset();
    ego.reset();
    ego_signals.reset();
    ego_lane_index.reset();
  }
  void forget_lights() {
    light_states.clear();
    light_timings.clear();
  }

  /// The answer kept for `id`, or nullptr (a route has a few lights: a linear search).
  template <class Value>
  static const Value* find(const std::vector<std::pair<std::string, Value>>& kept, const std::string& id) {
    for (const auto& [key, value] : kept)
      if (key == id) return &value;
    return nullptr;
  }
  template <class Value>
  static const Value& keep(std::vector<std::pair<std::string, Value>>& kept, const std::string& id, Value value) {
    kept.emplace_back(id, std::move(value));
    return kept.back().second;
  }
};

}  // namespace signalsim::sumo
