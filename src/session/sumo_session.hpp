// SumoSession: what the step loop sees of SUMO, whatever SUMO it runs on. One interface, three
// back-ends chosen at run time (docs/behaviour.md §S1):
//   embedded  libsumo in this process (default; batch, sweep and check use it)
//   gui       a sumo-gui this process starts and drives over TraCI (libtraci), the ego tracked
//   connect   a sumo or sumo-gui someone else started, stepped in lock-step with its other clients
// The per-step logic is written once (session_impl.hpp) and compiled against both libsumo and
// libtraci; only starting and closing differ (session_embedded.cpp, session_traci.cpp).
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/blinker_signals.hpp"  // the TraCI signal bits
#include "core/vehicle_defaults.hpp"
#include "session/signal_timing.hpp"

namespace signalsim::sumo {

/// A SUMO failure (load error, unknown id, refused or lost connection, ...). what() carries SUMO's
/// own first error line.
class SumoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The ego's SUMO speed factor while SUMO's lane limits are off (set_sumo_lane_limits).
inline constexpr double kFreeSpeedFactor = 10.0;

/// The id signalsim gives an ego it adds itself.
inline constexpr const char* kDefaultEgoId = "ego";

/// A vehicle standing still on a lane for the whole run (an obstacle to pass).
struct StandingVehicle {
  std::string id;
  std::string edge;
  int lane = 0;
  double pos = 0.0;     ///< lane position of its front [m]
  double length = 4.5;  ///< [m]; width, as SUMO's DEFAULT_VEHTYPE, 1.8 m
};

/// gui: what the kept screenshot shows (docs/outputs.md "gui.png").
struct GuiPicture {
  /// [s] the simulation time of the row whose command the picture follows (its timeline.csv row)
  double time = 0.0;
  /// the junction the view is zoomed out to (ahead of the ego, within 40 m, its blinker on; SUMO's
  /// id); empty: the default zoom (at departure or the first blinker, no junction near)
  std::string junction;
  std::string light;  ///< the light ahead framed with it (TraCI getNextTLS, within reach); empty: none
  /// [m] the net area the picture shows (GUI.getBoundary's extent about the ego): x_min, y_min, x_max, y_max
  std::vector<double> view;
};

/// Which SUMO the session runs on.
enum class BackendKind { Embedded, Gui, Connect };
std::string_view to_string(BackendKind kind);

struct BackendOptions {
  BackendKind kind = BackendKind::Embedded;
  std::string host = "127.0.0.1";  ///< connect: the server's host
  int port = 0;                    ///< connect: its TraCI port
  int client_order = 1;            ///< connect: TraCI setOrder (clients step in ascending order)
  /// connect, gui: [s] the longest wait for the server to accept the connection and for each of its
  /// answers (--traci-timeout; traci_relay.hpp); 0: no limit
  double traci_timeout = 30.0;
  int gui_delay_ms = 0;            ///< gui: sumo-gui's --delay between steps [ms]
  /// gui: the view's zoom [%] while it tracks the ego; 0: the default, about 60 m across (the ego
  /// and its blinkers). Fleet mode shows the traffic around it (docs/fleet.md).
  double gui_zoom = 0.0;
  /// gui: a PNG of the view (TraCI GUI.screenshot) written here at the first step the ego's blinker
  /// is on, replaced by the view zoomed out to the junction ahead once it is near (outputs.md
  /// "gui.png"), or at departure when the blinker never comes on; empty: none.
  std::string screenshot;
  std::string sumo_gui_binary = "sumo-gui";
};

struct SessionConfig {
  BackendOptions backend;
  std::string net;
  std::vector<std::string> route_files;  ///< SUMO -r (loaded incrementally)
  std::vector<std::string> additional;   ///< SUMO -a
  /// Options passed through to SUMO as they are (sumo_args, the sumocfg's other options), already
  /// checked and with relative output paths resolved (sumo_options.hpp).
  std::vector<std::string> extra_args;
  /// SUMO's messages and errors (--log); empty: captured only to report SUMO's first error line.
  std::string log_file;
  double step_length = 0.1;
  double begin = 0.0;  ///< SUMO --begin [s]
  int seed = 1;
  /// No ego at all (an egoless fleet run, docs/fleet.md "Without an ego"): SUMO's traffic alone; the
  /// ego's keys below are unused and the caller must not ask about or command an ego.
  bool no_ego = false;
  /// The ego: an id of a vehicle of the route files to take over when it departs, or empty to add
  /// one (id kDefaultEgoId) on `route` at `begin`.
  std::string take_over;
  double take_over_until = 0.0;  ///< take over: the latest simulation time to wait for its departure [s]
  std::vector<std::string> route;  ///< ego edges (added ego)
  int depart_lane = 0;
  double depart_pos = 0.0;
  /// Lateral offset from the depart lane's centre [m, left positive]; needs lateral_resolution > 0.
  /// The ego is moved there standing still before the session is returned (a few steps).
  double depart_pos_lat = 0.0;
  double depart_speed = 0.0;
  double max_speed = vehicle_defaults::kMaxSpeed;
  double length = vehicle_defaults::kLength;
  double width = vehicle_defaults::kWidth;  ///< [m]
  double accel = 1.0;              ///< vehicle type accel [m/s^2]
  double decel = vehicle_defaults::kSumoDecel;  ///< vehicle type decel: the most SUMO brakes with speed-mode bit 2
  double emergency_decel = 9.0;
  bool keep_planned_lanes = true;  ///< switch SUMO's own lane changes off for the ego
  /// SUMO drives the ego (`run --driver sumo`): it is inserted as configured, with the same vType,
  /// but no speed mode, lane-change mode or depart offset is applied (SUMO's defaults: its own
  /// lane changes, blinkers and stops at lights; docs/behaviour.md §S5). The caller only observes it, and
  /// must not call command(), command_lateral_offset(), move_back() or the speed-mode setters.
  bool sumo_drives = false;
  /// Sublane width [m] for SUMO's sublane model (`--lateral-resolution`). 0 = SUMO's default lane
  /// model (lane changes jump, no lateral motion inside a lane). > 0 also makes the ego's lateral
  /// dynamics fast enough to follow command_lateral_offset() exactly: vehicle-type maxSpeedLat
  /// 10 m/s and the vehicle parameter laneChangeModel.lcAccelLat 20 m/s^2 (docs/behaviour.md §S4).
  double lateral_resolution = 0.0;
  /// SUMO's continuous lane change (`--lanechange.duration`) [s], used when lateral_resolution is 0:
  /// > step_length lets command_lateral_offset() move the ego from one lane's centre to the next one's
  /// along the commanded offsets (its maxSpeedLat re-set every step; docs/behaviour.md §S4); every other
  /// vehicle's lane change then takes this long instead of one step. 0 = off.
  double lane_change_duration = 0.0;
  /// Inserted with the ego, each with a stop at its position that lasts for the whole run.
  std::vector<StandingVehicle> standing;
};

/// The ego as SUMO has it once it departed: what a taken-over vehicle brings from its route file.
struct EgoVehicle {
  std::string id;
  std::string type;            ///< its vType id (a distribution's member when drawn from one)
  std::string vclass;          ///< its vType's vClass
  double length = 0.0;         ///< [m]
  double width = 0.0;          ///< [m]
  double max_speed = 0.0;      ///< [m/s]
  double accel = 0.0;          ///< [m/s^2]
  double decel = 0.0;          ///< [m/s^2]
  double emergency_decel = 0.0;
  std::vector<std::string> route;  ///< its edges
  double depart_time = 0.0;    ///< [s]
  int depart_lane = 0;         ///< lane index on the first edge at departure
  double depart_pos = 0.0;     ///< front bumper's lane position at departure [m]
  double depart_speed = 0.0;   ///< [m/s]
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
  virtual ~SumoSession() = default;
  SumoSession(const SumoSession&) = delete;
  SumoSession& operator=(const SumoSession&) = delete;

  /// The back-end this session runs on.
  virtual BackendKind backend() const = 0;
  /// The ego as it departed (its id, type and route included).
  virtual const EgoVehicle& ego_vehicle() const = 0;
  /// SUMO's step length [s] (Simulation::getDeltaT).
  virtual double delta_t() const = 0;

  /// Advances one step. Returns false once the ego has arrived (it is then gone).
  virtual bool step() = 0;
  virtual double time() const = 0;
  /// The vehicles SUMO still has to run: those present plus those waiting to be inserted
  /// (Simulation::getMinExpectedNumber); 0 once all traffic has left.
  virtual int expected_vehicles() const = 0;

  virtual EgoState ego() const = 0;
  /// The signal mask SUMO shows for the ego now (docs/behaviour.md §S4 read-back).
  virtual int ego_signals() const = 0;
  /// The ego's signal mask asked of SUMO now (Vehicle::getSignals), never from the step's answer: over
  /// --connect it shows what a client of a lower order set during this step's round (setSignals
  /// shows at once), which the step's subscribed answer, computed when SUMO stepped, does not.
  virtual int ego_signals_now() const = 0;
  /// The ego's generic parameter `key` now (Vehicle::getParameter, as another TraCI client set it with
  /// setParameter); "" when it was never set.
  virtual std::string ego_parameter(const std::string& key) const = 0;
  /// Sets the ego's signals for the next step (must be re-sent every step, docs/behaviour.md §S4) and its
  /// speed (held until changed). A negative mask leaves the signals as they are (another TraCI client
  /// sets them: a traci decider under test, docs/decider.md).
  virtual void command(int signal_mask, double speed) = 0;

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
  virtual double lateral_offset_from(const std::string& reference_lane_id) const = 0;

  /// Moves the ego sideways so that after the next step its offset from the centre of
  /// `reference_lane_id` is `target_offset_next_step` [m, left positive]. Call it every step while a
  /// lateral plan is driven (the plan's offset at the s the ego will have after the step). It moves
  /// the ego across lane boundaries too (a lane change). With the sublane model
  /// (SessionConfig::lateral_resolution > 0: changeSublane) the ego follows exactly as long as the
  /// plan stays within maxSpeedLat 10 m/s and lcAccelLat 20 m/s^2; without it, SUMO's continuous lane
  /// change (SessionConfig::lane_change_duration > step_length) moves the ego from lane centre to lane
  /// centre, towards the reference lane only, at the maxSpeedLat re-set every step (within
  /// millimetres). When the calls stop, the ego kept its offset in our SUMO 1.15 runs (alone on the
  /// road, even through a junction onto the next edge), while docs/behaviour.md §S4 reports a drift
  /// back to the lane centre: rely on neither, command the offset you want. Needs one of the two
  /// models and the ego on the reference lane's edge; throws SumoError otherwise. The target is
  /// clamped to the road border: the ego's whole width stays on
  /// the run of lanes around its own that its vehicle class may use (a sidewalk or any lane that
  /// disallows it is a border, like the outside of the edge). Unclamped, SUMO would refuse a move past
  /// the border and leave the ego short of it.
  virtual void command_lateral_offset(double target_offset_next_step, const std::string& reference_lane_id) = 0;

  /// Emulated backward driving (SUMO cannot drive backward): moves the ego `distance` metres back
  /// along its lane now (Vehicle::moveTo), keeping its lateral offset in the lane. Command speed 0
  /// for the step. Throws SumoError when the ego would leave the start of its lane.
  virtual void move_back(double distance) = 0;

  /// Another vehicle on a lane: its front's lane position and its length [m].
  struct LaneVehicle {
    std::string id;
    double pos = 0.0;
    double length = 0.0;
  };
  /// The vehicles other than the ego whose lane is `lane_id` now (Lane::getLastStepVehicleIDs, in
  /// SUMO's order). Throws SumoError for an unknown lane.
  virtual std::vector<LaneVehicle> vehicles_on_lane(const std::string& lane_id) const = 0;

  /// Live state of a light: one character per link index (docs/behaviour.md §S2). The reference
  /// stays valid for the session's life; its text is this step's until the next step.
  virtual const std::string& light_state(const std::string& tls_id) const = 0;

  /// The phase states of every program SUMO loaded for a light (net and additional files).
  virtual std::vector<std::string> program_states(const std::string& tls_id) const = 0;

  /// Every program SUMO loaded for a light, with its kind and phases (TrafficLight::
  /// getAllProgramLogics): for V2I predictions (docs/behaviour.md §L1.7), read once per light.
  virtual std::vector<LightProgram> light_programs(const std::string& tls_id) const = 0;

  /// A light's running program, current phase and next switch (TrafficLight::getProgram, getPhase,
  /// getNextSwitch): the live part of a V2I prediction, asked every step while V2I is on.
  virtual LightTiming light_timing(const std::string& tls_id) const = 0;

  /// Shifts a light's running program as if it had started `offset` seconds earlier (modulo its
  /// cycle), from the current simulation time. Throws SumoError for an unknown light.
  virtual void shift_light_program(const std::string& tls_id, double offset) = 0;

  /// Emergency braking: lets the ego brake beyond its vehicle type's `decel` (speed-mode bit 2
  /// cleared, docs/behaviour.md §S4) while on.
  virtual void set_emergency_braking(bool on) = 0;

  /// Whether SUMO holds the ego to the lanes' speed limits itself (on by default). Off, its speed
  /// factor is kFreeSpeedFactor: SUMO no longer brakes ahead of a lower limit (a turn's internal lane),
  /// the ego's speed is signalsim's command alone (its vType maxSpeed still caps it). The step loop
  /// turns it off while the ego crosses a light the judge passed on yellow at its current speed.
  virtual void set_sumo_lane_limits(bool on) = 0;

  /// Whether SUMO's right of way at junctions applies to the ego (speed-mode bit 3, on by default).
  /// The step loop switches it off while the next junction the ego enters is a light showing the
  /// ego red or yellow: the judge is then the only decision at that link. With bit 3 on, SUMO holds
  /// a slow ego 1 m (jmStoplineGap) before a red line while crossing traffic approaches, overriding
  /// the judge (measured on bologna/acosta: 5 of 113 approaches; none with the bit off).
  virtual void set_right_of_way(bool respect) = 0;

  /// SUMO's leader of the ego within `range` metres along its route (Vehicle::getLeader), with the
  /// gap from the ego's front bumper to the leader's rear; nothing when there is none.
  struct Leader {
    std::string id;
    double gap = 0.0;  ///< [m]
  };
  virtual std::optional<Leader> ego_leader(double range) const = 0;

  /// The options of a SUMO someone else started that matter to a run (connect: seed, step length,
  /// collision.action, time-to-teleport, lateral-resolution, its files), as it reports them
  /// (Simulation::getOption); empty for a SUMO signalsim started itself.
  virtual std::vector<std::pair<std::string, std::string>> server_options() const { return {}; }

  /// Collisions involving the ego so far.
  virtual int ego_collisions() const = 0;

  /// gui: what the kept screenshot shows; none without a screenshot (other back-ends).
  virtual std::optional<GuiPicture> gui_picture() const { return std::nullopt; }

  // The other vehicles (fleet mode, docs/fleet.md): asked only for the vehicles present, never for
  // the net or for vehicles that left. The ego is never among them (the caller skips its id).

  /// What changed in SUMO's vehicles during the last step (Simulation::getDepartedIDList,
  /// getArrivedIDList, getStartingTeleportIDList).
  struct TrafficChanges {
    std::vector<std::string> departed;
    std::vector<std::string> arrived;
    std::vector<std::string> teleport_started;
  };
  virtual TrafficChanges traffic_changes() const = 0;
  /// Every vehicle in the simulation now (Vehicle::getIDList): once, when fleet mode starts after
  /// the ego's departure.
  virtual std::vector<std::string> traffic_present() const = 0;
  /// A vehicle as it departed: its vType, vClass and length, once per vehicle.
  struct TrafficVehicle {
    std::string type;
    std::string vclass;
    double length = 0.0;  ///< [m]
  };
  virtual TrafficVehicle traffic_vehicle(const std::string& id) const = 0;
  /// A vehicle's route now (Vehicle::getRoute): asked when its route id changed.
  virtual std::vector<std::string> traffic_route(const std::string& id) const = 0;
  /// A vehicle where it is now: one batch of reads per vehicle and step (over TraCI a subscription
  /// made by track_traffic, answered with the step; in process the getters).
  struct TrafficState {
    std::string route_id;  ///< changes when SUMO replaced its route (rerouter, TraCI changeTarget, ...)
    std::string lane;      ///< "" while it teleports (off the lanes)
    double lane_pos = 0.0;  ///< front bumper position on `lane` [m]
    double speed = 0.0;     ///< [m/s]
    int signals = 0;        ///< its signal mask now (read only when asked: `with_signals`)
    bool known = true;      ///< false: SUMO no longer knows the vehicle (removed by another client)
  };
  /// Starts following `id` (over TraCI: subscribes its variables). Call once after it departed.
  virtual void track_traffic(const std::string& id, bool with_signals) = 0;
  /// Fills `out` with the state of each of `ids` (tracked with track_traffic), in the same order.
  virtual void traffic_states(const std::vector<std::string>& ids, bool with_signals,
                              std::vector<TrafficState>& out) const = 0;
  /// Sets a vehicle's signal mask for the next step (Vehicle::setSignals: SUMO shows it for one step
  /// and then computes its own again, docs/behaviour.md §S4). A vehicle SUMO no longer knows (another
  /// TraCI client removed it) is passed over.
  virtual void set_traffic_signals(const std::string& id, int signal_mask) = 0;

 protected:
  SumoSession() = default;
};

/// Starts SUMO on the configured back-end and inserts (or waits for and takes over) the ego; returns
/// once the ego has departed. Throws SumoError with SUMO's message, a refused connection, a missing
/// display, a step length that differs from a connected server's, the libsumo module not loadable
/// (session_factory.hpp), ...
std::unique_ptr<SumoSession> open_session(const SessionConfig& config);

/// Whether SUMO itself (embedded, this process) loads the net alone: empty when it does, else SUMO's
/// first error line (e.g. "Error: Unknown vehicle class 'cable_car'." of a net newer than SUMO 1.15).
/// Starts and closes one simulation of no steps; costs about SUMO's load time of the net. Throws
/// SumoError when the libsumo module cannot be loaded, Interrupted after SIGINT/SIGTERM.
std::string net_load_error(const std::string& net_path);

/// Loads libsumo's module now if it is not loaded (session_factory.hpp): a batch does it before it forks
/// its workers, which then share it. Throws SumoError when it cannot be loaded.
void load_embedded_backend();

/// Whether the next embedded simulation of this process starts as it would in a fresh process. libsumo
/// runs one simulation at a time and may start again once it is closed (a batch's persistent worker
/// runs one scenario after another), but a start that failed leaves SUMO's message handlers behind:
/// that run's sumo.log would receive the next run's messages. False from then on: a worker ends.
bool embedded_sumo_reusable();

}  // namespace signalsim::sumo
