// SumoSession: the one place that calls libsumo. Starts SUMO in-process, inserts the ego, steps,
// observes and commands it. One session per process (libsumo is not re-entrant, spec SUMO §1).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace signalsim::sumo {

/// A SUMO failure (load error, unknown id, ...). what() carries SUMO's own first error line.
class SumoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// TraCI signal bits (spec SUMO §4; the libsumo headers do not define them).
inline constexpr int kBlinkerRight = 1;
inline constexpr int kBlinkerLeft = 2;
inline constexpr int kBlinkerEmergency = 4;
inline constexpr int kBlinkerMask = kBlinkerRight | kBlinkerLeft | kBlinkerEmergency;

struct SessionConfig {
  std::string net;
  std::vector<std::string> additional;
  double step_length = 0.1;
  int seed = 1;
  std::vector<std::string> route;  ///< ego edges
  int depart_lane = 0;
  double depart_pos = 0.0;
  double depart_speed = 0.0;
  double max_speed = 13.89;
  double length = 4.5;
  double accel = 1.0;              ///< vehicle type accel [m/s^2]
  double decel = 4.5;              ///< vehicle type decel: the most SUMO brakes with speed-mode bit 2
  double emergency_decel = 9.0;
  bool keep_planned_lanes = true;  ///< switch SUMO's own lane changes off for the ego
};

/// The ego as SUMO reports it after a step.
struct EgoState {
  double time = 0.0;
  std::string edge;
  std::string lane;
  double lane_pos = 0.0;        ///< front bumper position on `lane` [m]
  double speed = 0.0;           ///< [m/s]
  double accel = 0.0;           ///< [m/s^2]
  double x = 0.0;               ///< front bumper, net coordinates [m]
  double y = 0.0;
  double lateral_offset = 0.0;  ///< from the lane centre, left positive [m]
};

class SumoSession {
 public:
  /// Starts SUMO (step length, seed, --time-to-teleport -1, collisions as warnings) and inserts
  /// the ego; returns once the ego has departed. Throws SumoError with SUMO's message.
  explicit SumoSession(const SessionConfig& config);
  ~SumoSession();
  SumoSession(const SumoSession&) = delete;
  SumoSession& operator=(const SumoSession&) = delete;

  /// Advances one step. Returns false once the ego has arrived (it is then gone).
  bool step();
  double time() const;

  EgoState ego() const;
  /// The signal mask SUMO shows for the ego now (spec SUMO §4 read-back).
  int ego_signals() const;
  /// Sets the ego's signals for the next step (must be re-sent every step, spec SUMO §4) and its
  /// speed (held until changed).
  void command(int signal_mask, double speed);

  /// Live state of a light: one character per link index (spec SUMO §2).
  std::string light_state(const std::string& tls_id) const;

  /// The phase states of every program SUMO loaded for a light (net and additional files).
  std::vector<std::string> program_states(const std::string& tls_id) const;

  /// Shifts a light's running program as if it had started `offset` seconds earlier (modulo its
  /// cycle), from the current simulation time. Throws SumoError for an unknown light.
  void shift_light_program(const std::string& tls_id, double offset);

  /// Emergency braking: lets the ego brake beyond its vehicle type's `decel` (speed-mode bit 2
  /// cleared, spec SUMO §4) while on.
  void set_emergency_braking(bool on);

  /// Collisions involving the ego so far.
  int ego_collisions() const { return ego_collisions_; }

 private:
  int ego_collisions_ = 0;
  bool emergency_braking_ = false;
};

}  // namespace signalsim::sumo
