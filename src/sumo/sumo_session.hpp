// SumoSession: the one place that calls libsumo. Starts SUMO in-process, inserts the ego, steps,
// observes and commands it. One session per process (libsumo is not re-entrant, spec SUMO §1).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace signalsim::sumo {

class StderrCapture;

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

/// A vehicle standing still on a lane for the whole run (an obstacle to pass).
struct StandingVehicle {
  std::string id;
  std::string edge;
  int lane = 0;
  double pos = 0.0;     ///< lane position of its front [m]
  double length = 4.5;  ///< [m]; width, as SUMO's DEFAULT_VEHTYPE, 1.8 m
};

struct SessionConfig {
  std::string net;
  std::vector<std::string> additional;
  double step_length = 0.1;
  int seed = 1;
  std::vector<std::string> route;  ///< ego edges
  int depart_lane = 0;
  double depart_pos = 0.0;
  /// Lateral offset from the depart lane's centre [m, left positive]; needs lateral_resolution > 0.
  /// The ego is moved there standing still before the constructor returns (a few steps).
  double depart_pos_lat = 0.0;
  double depart_speed = 0.0;
  double max_speed = 13.89;
  double length = 4.5;
  double accel = 1.0;              ///< vehicle type accel [m/s^2]
  double decel = 4.5;              ///< vehicle type decel: the most SUMO brakes with speed-mode bit 2
  double emergency_decel = 9.0;
  bool keep_planned_lanes = true;  ///< switch SUMO's own lane changes off for the ego
  /// Sublane width [m] for SUMO's sublane model (`--lateral-resolution`). 0 = SUMO's default lane
  /// model (lane changes jump, no lateral motion inside a lane). > 0 also makes the ego's lateral
  /// dynamics fast enough to follow command_lateral_offset() exactly: vehicle-type maxSpeedLat
  /// 10 m/s and the vehicle parameter laneChangeModel.lcAccelLat 20 m/s^2 (spec SUMO §4).
  double lateral_resolution = 0.0;
  /// Inserted with the ego, each with a stop at its position that lasts for the whole run.
  std::vector<StandingVehicle> standing;
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

  /// The ego's lateral offset [m, left positive] from the centre line of `reference_lane_id`, a
  /// lane of the edge the ego is on: its offset inside its own lane (getLateralLanePosition) plus
  /// the distance between the two lane centres (half widths of both lanes plus the full widths of
  /// the lanes between; lanes of an edge may differ in width). Continuous while the ego crosses a
  /// lane boundary, although SUMO switches the ego's lane when its centre crosses the boundary.
  /// When the ego is on another edge than the reference lane's (the next edge, or an internal
  /// junction lane while the reference is a normal lane), the reference lane says nothing about it:
  /// this returns the plain getLateralLanePosition (offset from the centre of whatever lane the ego
  /// is on). A reference lane of an internal edge works like any other while the ego is on that
  /// internal edge. Throws SumoError for an unknown lane.
  double lateral_offset_from(const std::string& reference_lane_id) const;

  /// Moves the ego sideways (SUMO changeSublane) so that after the next step its offset from the
  /// centre of `reference_lane_id` is `target_offset_next_step` [m, left positive]. Call it every
  /// step while a lateral plan is driven (the plan's offset at the s the ego will have after the
  /// step). It moves the ego across lane boundaries too (a lane change). The ego follows exactly as
  /// long as the plan stays within maxSpeedLat 10 m/s and lcAccelLat 20 m/s^2 (SessionConfig::
  /// lateral_resolution). When the calls stop, the ego kept its offset in our SUMO 1.15 runs (alone
  /// on the road, even through a junction onto the next edge), while spec SUMO §4 reports a drift
  /// back to the lane centre: rely on neither, command the offset you want. Needs the sublane model
  /// (SessionConfig::lateral_resolution > 0) and the ego on the reference lane's edge; throws
  /// SumoError otherwise. The target is clamped to the road border: the ego's whole width stays on
  /// the run of lanes around its own that its vehicle class may use (a sidewalk or any lane that
  /// disallows it is a border, like the outside of the edge). Unclamped, SUMO would refuse a move past
  /// the border and leave the ego short of it.
  void command_lateral_offset(double target_offset_next_step, const std::string& reference_lane_id);

  /// Emulated backward driving (SUMO cannot drive backward): moves the ego `distance` metres back
  /// along its lane now (Vehicle::moveTo), keeping its lateral offset in the lane. Command speed 0
  /// for the step. Throws SumoError when the ego would leave the start of its lane.
  void move_back(double distance);

  /// Another vehicle on a lane: its front's lane position and its length [m].
  struct LaneVehicle {
    std::string id;
    double pos = 0.0;
    double length = 0.0;
  };
  /// The vehicles other than the ego whose lane is `lane_id` now (Lane::getLastStepVehicleIDs, in
  /// SUMO's order). Throws SumoError for an unknown lane.
  std::vector<LaneVehicle> vehicles_on_lane(const std::string& lane_id) const;

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
  std::string sumo_reason(const std::exception& e) const;
  void move_to_depart_offset(const SessionConfig& config);
  std::unique_ptr<StderrCapture> capture_;  ///< SUMO's stderr while the session lives
  int ego_collisions_ = 0;
  bool emergency_braking_ = false;
  double lateral_resolution_ = 0.0;
};

}  // namespace signalsim::sumo
