// The ports of one step (docs/architecture.md "The step as a system"): the values that cross
// between SUMO and the step's logic. Every SUMO input of a step is gathered into one
// StepObservation (sim/session_ports observe), as the step's core asks for it in its
// ObservationDemand; every write is one Commands value (sim/session_ports apply, the only writer);
// what SUMO says back after advancing is one StepFeedback. The core (step_core.hpp,
// sumo_driven_core.hpp) sees these values only: no session, no callbacks, so a recorded sequence of
// observations replays a run without SUMO (tests/unit/step).
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "report/timeline.hpp"
#include "session/signal_timing.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {

/// [m] how far ahead the leader is asked for: a rest behind a vehicle within it is explained by that
/// vehicle (a stop in the queue before a light, a run that ends at rest).
inline constexpr double kLeaderRange = 100.0;

/// What of one light a step needs: its state string always, V2I's timing and programs when asked.
struct LightDemand {
  std::string tls_id;
  bool timing = false;    ///< TrafficLight::getProgram/getPhase/getNextSwitch (V2I, every step)
  bool programs = false;  ///< TrafficLight::getAllProgramLogics (V2I, once per light)
};

/// What the core asks SUMO for, beyond the ego, before it runs the step.
struct ObservationDemand {
  /// The lights of the window (and the next light beyond it), one entry per light id.
  std::vector<LightDemand> lights;
  /// The ego's lateral offset from this lane's centre (the lateral plan's reference lane on the ego's
  /// edge); empty: SUMO's offset from the ego's own lane is enough.
  std::optional<std::string> lateral_reference_lane;
  /// The vehicles on this lane (a lane change's target lane while it waits for approval).
  std::optional<std::string> lane_traffic;
  /// SUMO's leader of the ego within kLeaderRange.
  bool leader = false;
  /// SUMO's signal mask of the ego at the observation (a SUMO-driven run's blinker).
  bool signals = false;
  /// With `signals`: the mask asked of SUMO at the observation itself (SumoSession::ego_signals_now),
  /// not from the step's answer: what another TraCI client set before this one's turn (a traci decider).
  bool signals_now = false;
  /// The ego's generic parameters to read at the observation, by key (a traci light judge's answers).
  std::vector<std::string> ego_parameters;

  /// The entry for `tls_id`, added when missing (one entry per light id, whatever asks for it).
  LightDemand& light(const std::string& tls_id);
};

/// One light as SUMO showed it at the observation.
struct LightReading {
  std::string tls_id;
  std::string state;                                        ///< one character per link index
  std::optional<sumo::LightTiming> timing;                  ///< when demanded
  std::optional<std::vector<sumo::LightProgram>> programs;  ///< when demanded
};

/// Every SUMO input of one step, read at the step's start (one moment: the timeline row's time).
struct StepObservation {
  sumo::EgoState ego;
  /// [m] from ObservationDemand::lateral_reference_lane's centre, when it was demanded.
  std::optional<double> lateral_offset;
  std::vector<LightReading> lights;                          ///< as demanded, in demand order
  std::vector<sumo::SumoSession::LaneVehicle> lane_traffic;  ///< as demanded
  std::optional<LeaderInfo> leader;                          ///< when demanded and there is one
  std::optional<int> signals;                                ///< when demanded
  /// As demanded, in demand order: key and value ("" for a parameter never set).
  std::vector<std::pair<std::string, std::string>> ego_parameters;

  /// The reading of `tls_id`, or nullptr when it was not demanded.
  const LightReading* light(const std::string& tls_id) const;
};

/// The ego's lateral motion for the next step: base_link `offset` [m] from `reference_lane`'s centre.
struct LateralCommand {
  double offset = 0.0;
  std::string reference_lane;
  bool operator==(const LateralCommand&) const = default;
};

/// Everything a step writes to SUMO. A SUMO-driven run commands nothing (`drive` false).
struct Commands {
  bool drive = true;                ///< false: nothing below is sent (SUMO drives the ego)
  bool right_of_way = true;         ///< SUMO's right-of-way checks (speed mode bit)
  bool lane_limits = true;          ///< SUMO's lane speed limits (speed mode bit)
  bool emergency_braking = false;   ///< SUMO may brake beyond the ego's decel
  int signal_mask = 0;              ///< the blinker as TraCI signal bits
  bool write_signals = true;        ///< false: the signals are left as another TraCI client sets them
  double speed = 0.0;               ///< [m/s]
  std::optional<LateralCommand> lateral;
  double move_back = 0.0;           ///< [m] emulated backward driving this step
  bool operator==(const Commands&) const = default;
};

/// What SUMO says after executing the commands and advancing one step.
struct StepFeedback {
  bool alive = true;     ///< false: the ego arrived (SUMO's step removed it)
  int signals = -1;      ///< the ego's signal mask while it executed the commands (-1 once arrived)
  double time = 0.0;     ///< [s] SUMO's time after the step
};

}  // namespace signalsim
