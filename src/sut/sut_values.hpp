// What a system under test (a user's decider or light judge, docs/decider.md) is given: the run once,
// then one step per simulation step, in the project's vocabulary and units. Value types; the
// adapters (lib: the C ABI of include/signalsim/decider_plugin.h, exec: JSON lines, traci) translate
// them, the step core fills them (step/step_core.cpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "map/route_map.hpp"
#include "traffic_light/signal_elements.hpp"
#include "traffic_light/traffic_light_judge.hpp"
#include "turn_signal/turn_signal_info.hpp"

namespace signalsim {

/// One lateral motion the behaviour modules plan (a lane change, an avoidance, a pull out or over).
struct SutShiftLine {
  RequestSource module = RequestSource::None;  ///< LaneChange, Avoidance, PullOut or PullOver
  std::string edge_id;
  double s_start = 0.0;  ///< [m] base_link route s where the lateral motion starts
  double s_end = 0.0;    ///< [m] where it ends
  double shift = 0.0;    ///< [m] lateral, left positive
};

/// The run, given once before the first step.
struct SutRun {
  std::string scenario;                 ///< the scenario's name
  double step_length = 0.1;             ///< [s]
  double vehicle_length = 0.0;          ///< [m]
  double base_link_to_front = 0.0;      ///< [m]
  std::vector<std::pair<std::string, std::string>> parameters;  ///< every run parameter by name, as text, sorted
  const RouteMap* route = nullptr;      ///< the route as driven (outlives the SUT)
  std::vector<SutShiftLine> shift_lines;  ///< the planned maneuvers, route order
  double timeout = 5.0;                 ///< [s] `sut_timeout`: the longest a SUT may take to answer one step
  std::string out_dir;                  ///< the run's output directory (an exec: SUT's stderr goes there)
};

/// The ego at the step's start.
struct SutEgo {
  double x = 0.0, y = 0.0;  ///< [m] front bumper, net coordinates
  double yaw = 0.0;         ///< [rad] 0 = east, counter-clockwise
  double speed = 0.0;       ///< [m/s] signed: negative while backing up
  double accel = 0.0;       ///< [m/s^2]
  double s_front = 0.0;     ///< [m] route s of the front bumper
  double s_base = 0.0;      ///< [m] route s of base_link
};

/// One light ahead within the judge's window, as perception delivered it this step.
struct SutLight {
  std::string tls_id;
  int link_index = -1;
  std::size_t route_index = 0;    ///< the approach lanelet
  double stop_line_s = 0.0;       ///< [m]
  double distance = 0.0;          ///< [m] front bumper to the stop line
  bool delivered = false;         ///< a perception message arrived this step (without this light: no elements)
  std::vector<SignalElement> elements;
  std::optional<double> time_to_red;  ///< [s] V2I's prediction, when V2I is on
};

/// What a step gives a SUT.
struct SutStep {
  double time = 0.0;               ///< [s]
  SutEgo ego;
  RouteMap::Window window;         ///< the decider's window of route lanelets (docs/behaviour.md §T3.2)
  TurnSignalInfo request;          ///< the behaviour modules' merged request (EMPTY when none)
  std::vector<SutLight> lights;    ///< nearest first; filled for a light judge only
  std::optional<int> sumo_signals; ///< the ego's SUMO signal mask at the observation (traci SUTs only)
  std::vector<std::pair<std::string, std::string>> ego_parameters;  ///< traci light judge: the ego's read parameters
};

/// A light judge's answer for one light of SutStep::lights.
struct SutLightAnswer {
  bool stop = false;
  std::string reason;  ///< optional
};

}  // namespace signalsim
