// SessionImpl<Api>: the per-step SUMO logic of SumoSession, written once for both client libraries.
// `Api` names the library's domain classes (Api::Vehicle, Api::Simulation, ...): libsumo (in-process)
// or libtraci (over a socket) have the same API in two namespaces whose headers cannot be included in
// one translation unit (docs/behaviour.md §S1), so this header includes neither. session_embedded.cpp and
// session_traci.cpp include their library, define Api and instantiate this template; they own only
// how SUMO is started and closed. Include it after <libsumo/libsumo.h> or <libsumo/libtraci.h>
// (it uses their shared types and constants, libsumo::TraCIResults, libsumo::VAR_*).
// `Api::kSubscribes` says whether the ego's and the simulation's variables are subscribed: over a
// socket one subscribed answer a step replaces nine round trips; in process libsumo's subscription
// machinery costs more than the getters it replaces (about 20 000 instructions a step, measured:
// docs/performance.md), so the embedded session asks the getters, each once a step.
//
// This file declares the class; its members are defined, one job a file, in the files it includes
// at its end:
//   session_impl_observe.hpp   what it reads: the step and its subscribed answer, the ego, the lights
//   session_impl_commands.hpp  what it tells SUMO: signals, speed, lateral offset, modes, programs
//   session_impl_ego.hpp       the ego's life: insertion or take-over, control, hand-back
//   session_impl_traffic.hpp   the other vehicles, for fleet mode: what changed, where each is, signals
//   session_lane_data.hpp      the static lane data it asks once and keeps (LaneData)
//   session_step_answers.hpp   what SUMO answered during the current step, asked once (StepAnswers)
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "session/interruption.hpp"
#include "core/number_parsing.hpp"
#include "session/session_lane_data.hpp"
#include "session/session_step_answers.hpp"
#include "session/sumo_session.hpp"

namespace signalsim::sumo {

// Speed-mode bits (docs/behaviour.md §S4): 0 safe speed, 1 max accel, 2 max decel, 3 right of way; bit 4
// (hard braking for red lights) is never set: the traffic-light judge decides at lights.
inline constexpr int kSpeedModeSafeSpeed = 1, kSpeedModeMaxAccel = 2, kSpeedModeMaxDecel = 4, kSpeedModeRightOfWay = 8;
// SUMO's defaults, for a vehicle signalsim hands back (TraCI docs: speed mode 31, lane-change mode 1621).
inline constexpr int kSumoDefaultSpeedMode = 31, kSumoDefaultLaneChangeMode = 0b011001010101;

template <class Api>
class SessionImpl : public SumoSession {
 public:
  explicit SessionImpl(const SessionConfig& config)
      : config_(config), ego_(config.take_over.empty() ? kDefaultEgoId : config.take_over) {}

  const EgoVehicle& ego_vehicle() const override { return vehicle_; }
  double delta_t() const override { return guarded("the step length", [] { return Api::Simulation::getDeltaT(); }); }
  int ego_collisions() const override { return ego_collisions_; }

  // Reads (session_impl_observe.hpp).
  bool step() override;
  double time() const override;
  int expected_vehicles() const override;
  EgoState ego() const override;
  int ego_signals() const override;
  int ego_signals_now() const override;
  std::string ego_parameter(const std::string& key) const override;
  std::optional<Leader> ego_leader(double range) const override;
  std::vector<LaneVehicle> vehicles_on_lane(const std::string& lane_id) const override;
  double lateral_offset_from(const std::string& reference_lane_id) const override;
  const std::string& light_state(const std::string& tls_id) const override;
  std::vector<std::string> program_states(const std::string& tls_id) const override;
  std::vector<LightProgram> light_programs(const std::string& tls_id) const override;
  LightTiming light_timing(const std::string& tls_id) const override;

  // Commands (session_impl_commands.hpp).
  void command(int signal_mask, double speed) override;
  void move_back(double distance) override;
  void command_lateral_offset(double target_offset_next_step, const std::string& reference_lane_id) override;
  void shift_light_program(const std::string& tls_id, double offset) override;
  void set_emergency_braking(bool on) override;
  void set_sumo_lane_limits(bool on) override;
  void set_right_of_way(bool respect) override;

  // The other vehicles, for fleet mode (session_impl_traffic.hpp).
  TrafficChanges traffic_changes() const override;
  std::vector<std::string> traffic_present() const override;
  TrafficVehicle traffic_vehicle(const std::string& id) const override;
  std::vector<std::string> traffic_route(const std::string& id) const override;
  void track_traffic(const std::string& id, bool with_signals) override;
  void traffic_states(const std::vector<std::string>& ids, bool with_signals,
                      std::vector<TrafficState>& out) const override;
  void set_traffic_signals(const std::string& id, int signal_mask) override;

 protected:
  // The ego's life (session_impl_ego.hpp).
  /// Inserts the ego (or waits for the vehicle to take over) once SUMO runs, then applies the ego's
  /// controls and reads what it departed as. The factory calls it once, after the back-end started.
  void insert_ego();
  /// Hands the ego back when signalsim leaves a simulation that goes on (--connect): an ego it added
  /// (and its standing obstacles) is removed; a taken-over vehicle drives on under SUMO's own models
  /// (default speed and lane-change modes, its own speed and signals). Never throws.
  void release_ego() noexcept;

  /// SUMO's own reason for a failure (the embedded back-end reads it from SUMO's stderr).
  virtual std::string failure_reason(const std::exception& e) const { return e.what(); }
  /// Called once the ego is under control (gui: colour and track it).
  virtual void on_ego_departed() {}
  /// Called after each command (gui: the screenshot at the first blinker).
  virtual void on_command(int /*signal_mask*/) {}
  /// Called after each step (gui: waits for a requested screenshot to be written).
  virtual void on_stepped() {}

  const SessionConfig config_;
  const std::string ego_;
  /// How command_lateral_offset() moves the ego: SUMO's sublane model (changeSublane) or, without
  /// it, its continuous lane change (continue_lane_change). A TraCI server's own sublane model wins.
  bool sublane_ = config_.lateral_resolution > 0.0;
  bool continuous_lane_change_ = !sublane_ && config_.lane_change_duration > 0.0;
  bool lane_change_step_ = false;  ///< a continuous lane change moved the ego in this step
  int last_signal_mask_ = -1;      ///< the mask command() sent for this step (-1: none)

 private:
  // A library call whose failure becomes a SumoError "SUMO could not report <what>: ...".
  template <class F>
  auto guarded(const char* what, F f) const {
    try {
      return f();
    } catch (const std::exception& e) {
      throw SumoError(std::string("SUMO could not report ") + what + ": " + failure_reason(e));
    }
  }

  // The subscribed variables of the step (over TraCI), or nullptr: none subscribed (libsumo), none
  // to trust (the ego's after move_back moved it), or not all of them (the ego has gone).
  const libsumo::TraCIResults* simulation_variables() const;
  const libsumo::TraCIResults* ego_variables() const;
  // The ego's state and lane index, asked once a step (ego_state() is ego() without its error text).
  const EgoState& ego_state() const;
  EgoState read_ego_state() const;
  int ego_lane_index() const;
  /// Forgets what the session kept of an earlier run (the step's answers, the lanes' data, the ego's
  /// class): a run starts from SUMO's own answers, also in a session SUMO reloaded.
  void forget_run_answers();

  void apply_speed_mode();       // session_impl_commands.hpp, as the next one
  void continue_lane_change(double shift, int ego_index, int reference_index);
  void restore_blinkers_after_lane_change();
  void add_ego();                // session_impl_ego.hpp, as the next three
  bool wait_for_departure();
  void take_control();
  void move_to_depart_offset();

  LaneData<Api> lanes_;
  mutable StepAnswers answers_;
  EgoVehicle vehicle_;
  // Over TraCI, the ego's variables that come with each step's answer (ego(), ego_signals(), and its
  // lane index for lateral_offset_from()).
  static constexpr std::array<int, 9> kEgoVariables = {
      libsumo::VAR_ROAD_ID,      libsumo::VAR_LANE_ID,  libsumo::VAR_LANEPOSITION,     libsumo::VAR_SPEED,
      libsumo::VAR_ACCELERATION, libsumo::VAR_POSITION, libsumo::VAR_LANEPOSITION_LAT, libsumo::VAR_SIGNALS,
      libsumo::VAR_LANE_INDEX};

  bool subscribed_ = false;     // over TraCI: the ego's and the simulation's variables come with each step
  mutable std::string vclass_;  // the ego's vehicle class, asked once
  bool ego_present_ = false;  // inserted (or taken over) and not arrived: release_ego() has work
  int ego_collisions_ = 0;
  bool emergency_braking_ = false;
  bool right_of_way_ = true;
  bool lane_limits_ = true;  // speed factor 1 (set_sumo_lane_limits)
};

}  // namespace signalsim::sumo

#include "session/session_impl_observe.hpp"
#include "session/session_impl_commands.hpp"
#include "session/session_impl_ego.hpp"
#include "session/session_impl_traffic.hpp"
