// What one run recorded: a row per step and an event per change.
#pragma once

#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

struct TimelineRow {
  double time = 0.0;             ///< [s] simulation time of the observation
  double s_front = 0.0;          ///< route position of the front bumper [m]
  double x = 0.0, y = 0.0;       ///< front bumper, net coordinates [m]
  double speed = 0.0;            ///< [m/s]
  double accel = 0.0;            ///< [m/s^2]
  std::string edge, lane;
  double lateral_offset = 0.0;   ///< [m], left positive
  Blinker blinker = Blinker::None;            ///< what the decider decided
  RequestSource blinker_source = RequestSource::None;
  int sumo_signals = -1;         ///< mask SUMO showed while executing this decision; -1 = gone
  std::string tl_id;             ///< next light ahead on the route, empty when none
  char tl_state = 0;             ///< its true link state for the ego's connection, 0 when none
};

struct TimelineEvent {
  double time = 0.0;
  double s_front = 0.0;
  std::string kind;              ///< "blinker"
  std::string from, to;
  std::string source;
};

struct ExpectationResult {
  std::string description;
  bool passed = false;
  std::string detail;            ///< why it failed, or what held
};

struct RunRecord {
  std::vector<TimelineRow> rows;
  std::vector<TimelineEvent> events;
  bool arrived = false;          ///< the ego reached the end of its route
  int collisions = 0;
  double base_link_to_front = 0.0;
};

}  // namespace signalsim
