// StepAnswers: what SUMO answered during the current step, kept so that the session asks each thing
// at most once a step (SessionImpl, session_impl.hpp): the time, the ego's state, signals and lane
// index, and the state and timing of each light asked for; over TraCI also the subscribed answers
// they are read from. Nothing in it outlives the step: step() forgets it all, moving the ego
// (move_back) forgets the ego's part, shifting a light's program the lights'. A light's kept
// answer stays at one address for the whole run (the next step's answer overwrites it in place), so
// a reference to it never dangles and a same-sized state string needs no new allocation. Other TraCI clients
// (--connect) change nothing in between: SUMO runs all commands of one client before the next
// client's, until it asks for the step (TraCI protocol, "Basic Flow"). Include it after
// <libsumo/libsumo.h> or <libsumo/libtraci.h>, through session_impl.hpp.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "session/signal_timing.hpp"
#include "session/sumo_session.hpp"

namespace signalsim::sumo {

/// Per-light answers by light id, kept at stable addresses (a route has a few lights: a linear
/// search). forget() marks them stale; keep() overwrites a stale entry of the same light in place.
template <class Value>
class KeptAnswers {
 public:
  /// The answer kept for `id` this step, or nullptr.
  const Value* find(const std::string& id) const {
    for (const Entry& e : entries_)
      if (e.fresh && e.id == id) return &e.value;
    return nullptr;
  }
  const Value& keep(const std::string& id, Value value) {
    for (Entry& e : entries_)
      if (e.id == id) {
        e.value = std::move(value);
        e.fresh = true;
        return e.value;
      }
    entries_.push_back({id, std::move(value), true});  // a deque: earlier entries do not move
    return entries_.back().value;
  }
  void forget() {
    for (Entry& e : entries_) e.fresh = false;
  }

 private:
  struct Entry {
    std::string id;
    Value value;
    bool fresh = false;
  };
  std::deque<Entry> entries_;
};

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
  KeptAnswers<std::string> light_states;  ///< by light id: the state string
  KeptAnswers<LightTiming> light_timings;

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
    light_states.forget();
    light_timings.forget();
  }
};

}  // namespace signalsim::sumo
