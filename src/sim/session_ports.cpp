// Reading a step's observation from SUMO and applying its commands; see session_ports.hpp.
#include "sim/session_ports.hpp"

#include <utility>

namespace signalsim {

StepObservation observe(const sumo::SumoSession& session, sumo::EgoState ego, const ObservationDemand& want) {
  StepObservation seen;
  seen.ego = std::move(ego);
  if (want.lateral_reference_lane) seen.lateral_offset = session.lateral_offset_from(*want.lateral_reference_lane);
  if (want.lane_traffic) seen.lane_traffic = session.vehicles_on_lane(*want.lane_traffic);
  seen.lights.reserve(want.lights.size());
  for (const LightDemand& light : want.lights) {
    LightReading& reading = seen.lights.emplace_back();
    reading.tls_id = light.tls_id;
    reading.state = session.light_state(light.tls_id);
    if (light.programs) reading.programs = session.light_programs(light.tls_id);
    if (light.timing) reading.timing = session.light_timing(light.tls_id);
  }
  // Vehicle::getLeader: also on the lanes ahead.
  if (want.leader)
    if (const auto leader = session.ego_leader(kLeaderRange)) seen.leader = LeaderInfo{leader->id, leader->gap};
  if (want.signals) seen.signals = want.signals_now ? session.ego_signals_now() : session.ego_signals();
  for (const std::string& key : want.ego_parameters) seen.ego_parameters.emplace_back(key, session.ego_parameter(key));
  return seen;
}

// SUMO's modes (right of way, lane limits, emergency braking), the blinker bits and the speed
// (re-sent every step, docs/behaviour.md §S4), the lateral offset, the back-up; then the step.
StepFeedback apply(sumo::SumoSession& session, const Commands& commands) {
  if (commands.drive) {
    session.set_right_of_way(commands.right_of_way);
    session.set_sumo_lane_limits(commands.lane_limits);
    session.set_emergency_braking(commands.emergency_braking);
    session.command(commands.write_signals ? commands.signal_mask : -1, commands.speed);
    if (commands.lateral) session.command_lateral_offset(commands.lateral->offset, commands.lateral->reference_lane);
    if (commands.move_back > 0.0) session.move_back(commands.move_back);
  }
  StepFeedback feedback;
  feedback.alive = session.step();
  feedback.signals = feedback.alive && commands.drive ? session.ego_signals() : -1;
  feedback.time = session.time();
  return feedback;
}

}  // namespace signalsim
