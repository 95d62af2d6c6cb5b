// One vehicle of the fleet (docs/fleet.md): its route (shared with every vehicle driving the same
// edges), where its front is on it (map/route_locator: the ego's rule), its own decider with its own
// remembered desired starts, and what it shows. Fleet vehicles have no lane-change, avoidance, pull-out
// or pull-over requests: the decider weighs the intersection and roundabout requests only (§T4, §T5).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "core/blinker_signals.hpp"
#include "fleet/fleet_routes.hpp"
#include "map/route_locator.hpp"
#include "turn_signal/turn_signal_decider.hpp"

namespace signalsim {

/// What the decider decided for a vehicle in one cycle, and what the request is for.
struct FleetDecision {
  Blinker blinker = Blinker::None;
  RequestSource source = RequestSource::None;
  double s_front = 0.0;    ///< [m] on the vehicle's route
  std::string place;       ///< the junction of the winning request's lanelet ("" when off)
  std::string place_kind;  ///< "junction" (intersection request), "roundabout", or ""
  double place_s = 0.0;    ///< [m] route s where the request's lanelets start (§T4 required start)
};

/// A blinker-on stretch of one vehicle for one place (the summary's lead distances).
struct FleetEpisode {
  std::string place;
  Blinker blinker = Blinker::None;
  double place_s = 0.0;
  bool sumo_seen = false;  ///< observe: SUMO's own blinker showed the same direction during it
};

class FleetVehicle {
 public:
  FleetVehicle(std::string id, std::string vclass, const TurnSignalParameters& params)
      : id_(std::move(id)), vclass_(std::move(vclass)), params_(params) {}

  const std::string& id() const { return id_; }
  const std::string& vclass() const { return vclass_; }
  const std::string& route_id() const { return route_id_; }
  const FleetRoute* route() const { return route_.get(); }
  bool understood() const { return route_ && route_->understood(); }

  /// Follows a route (at departure, or SUMO replaced it): the place on it is found afresh, and the
  /// decider starts with no remembered desired starts (they are keyed by positions on the old route).
  void follow(std::string route_id, std::shared_ptr<const FleetRoute> route);

  /// One cycle with the vehicle at (lane, lane_pos) with `speed`. Nothing while it is off the lanes
  /// (teleporting: lane "") or its route is not understood.
  std::optional<FleetDecision> decide(const std::string& lane, double lane_pos, double speed);

  Blinker shown = Blinker::None;         ///< the blinker of the last decision
  std::string shown_place;               ///< its place
  std::optional<FleetEpisode> episode;   ///< the blinker-on stretch running now
  bool signalled = false;                ///< the blinker was on at least once
  bool counted_left = false;             ///< counted in left_to_sumo
  bool counted_followed = false;         ///< counted in vehicles_followed
  std::optional<double> last_speed;      ///< [m/s] at the previous decision (its brake light)

 private:
  std::string id_;
  std::string vclass_;
  TurnSignalParameters params_;
  std::string route_id_;
  std::shared_ptr<const FleetRoute> route_;
  std::optional<RouteLocator> locator_;
  std::optional<TurnSignalDecider> decider_;
};

}  // namespace signalsim
