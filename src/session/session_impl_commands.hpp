// SessionImpl<Api>, part 2 of 3: what the session tells SUMO (session_impl.hpp has the class).
// The ego's signals and speed, backing up, its lateral offset (the sublane model or the continuous
// lane change), its speed mode (emergency braking, right of way) and speed factor (SUMO's lane
// limits), and the shift of a light's program. Where the
// ego is comes from the step's answer (session_impl_observe.hpp); its length and width are the ones
// it departed with (take_control).
// Included by session_impl.hpp only.
#pragma once

namespace signalsim::sumo {

template <class Api>
void SessionImpl<Api>::command(int signal_mask, double speed) {
  try {
    if (signal_mask >= 0) Api::Vehicle::setSignals(ego_, signal_mask);
    Api::Vehicle::setSpeed(ego_, speed);
  } catch (const std::exception& e) {
    throw SumoError("SUMO refused a command for the ego: " + failure_reason(e));
  }
  last_signal_mask_ = signal_mask;
  on_command(signal_mask);
}

template <class Api>
void SessionImpl<Api>::move_back(double distance) {
  try {
    const EgoState now = ego_state();  // a copy: moving the ego forgets the step's answer
    if (now.lane_pos - distance < vehicle_.length)
      throw SumoError("the ego cannot back up beyond the start of lane " + now.lane);
    Api::Vehicle::moveTo(ego_, now.lane, now.lane_pos - distance);
    answers_.forget_ego();
    answers_.ego_moved = true;  // until the next step, where the ego is is asked directly
    const double drift = now.lateral_offset - Api::Vehicle::getLateralLanePosition(ego_);
    if (sublane_ && std::abs(drift) > 1e-6) Api::Vehicle::changeSublane(ego_, drift);
  } catch (const SumoError&) {
    throw;
  } catch (const std::exception& e) {
    throw SumoError("SUMO refused to move the ego back: " + failure_reason(e));
  }
}

template <class Api>
void SessionImpl<Api>::command_lateral_offset(double target_offset_next_step, const std::string& reference_lane_id) {
  if (!sublane_ && !continuous_lane_change_)
    throw SumoError("lateral offsets can only be commanded with SUMO's sublane model or its continuous lane "
                    "change: set the session's lateral_resolution > 0 (--lateral-resolution) or "
                    "lane_change_duration > step_length (--lanechange.duration)");
  try {
    const std::string& reference_edge = lanes_.lane_edge(reference_lane_id);
    const std::string& ego_edge = ego_state().edge;
    if (ego_edge != reference_edge)
      throw SumoError("cannot command a lateral offset from lane '" + reference_lane_id + "': the ego is on '" +
                      ego_edge + "', not on that lane's edge '" + reference_edge + "'");
    // Keep the target on the lanes the ego may use around its own (the road border): SUMO refuses a
    // move past it and leaves the ego where it was, short of the border, instead of clamping.
    const int reference_index = lanes_.lane_index_on(reference_edge, reference_lane_id);
    const int ego_index = ego_lane_index();
    const int lanes = lanes_.lane_count(reference_edge);
    if (vclass_.empty()) vclass_ = Api::Vehicle::getVehicleClass(ego_);
    const std::string& vclass = vclass_;
    const auto lane = [&](int k) { return reference_edge + "_" + std::to_string(k); };
    int lo = ego_index, hi = ego_index;
    while (lo > 0 && lanes_.permits(lane(lo - 1), vclass)) --lo;
    while (hi + 1 < lanes && lanes_.permits(lane(hi + 1), vclass)) ++hi;
    const double half_width = 0.5 * vehicle_.width;
    const double lowest =
        lanes_.centre_distance(reference_edge, reference_index, lo) - 0.5 * lanes_.lane_width(lane(lo)) + half_width;
    const double highest =
        lanes_.centre_distance(reference_edge, reference_index, hi) + 0.5 * lanes_.lane_width(lane(hi)) - half_width;
    double target = target_offset_next_step;
    if (lowest <= highest) target = std::clamp(target, lowest, highest);
    const double shift = target - lateral_offset_from(reference_lane_id);
    if (sublane_) Api::Vehicle::changeSublane(ego_, shift);
    else continue_lane_change(shift, ego_index, reference_index);
  } catch (const SumoError&) {
    throw;
  } catch (const std::exception& e) {
    throw SumoError("SUMO refused a lateral offset from lane '" + reference_lane_id + "': " + failure_reason(e));
  }
}

// Without the sublane model (docs/behaviour.md §S4): SUMO's continuous lane change moves the ego from
// its lane's centre to the next lane's, `maxSpeedLat` a step while its vType sets one
// (MSAbstractLaneChangeModel::computeSpeedLat: the manoeuvre's distance over whole steps at most that
// fast). Re-set every step to the speed that lands on the commanded offset, it follows the plan. A
// manoeuvre is started (changeLane, for one step) only towards the reference lane and only while the
// ego is at a lane's centre, so that a running one is never redirected and one that SUMO ended a
// step early is not followed by a step back. A shift away from the manoeuvre's direction holds the ego.
template <class Api>
void SessionImpl<Api>::continue_lane_change(double shift, int ego_index, int reference_index) {
  constexpr double kAtCentre = 1e-9;    // [m] SUMO's offset between manoeuvres is exactly 0
  constexpr double kSlowestLat = 1e-5;  // [m/s] maxSpeedLat > 0: SUMO divides by it
  if (std::abs(ego_state().lateral_offset) <= kAtCentre) {
    const int towards = reference_index > ego_index ? 1 : -1;  // lane indices grow to the left, as offsets
    if (reference_index < 0 || ego_index == reference_index || shift * towards <= 0.0) return;
    Api::Vehicle::changeLane(ego_, ego_index + towards, config_.step_length);
  }
  Api::Vehicle::setMaxSpeedLat(ego_, std::max(std::abs(shift) / config_.step_length, kSlowestLat));
  lane_change_step_ = true;
}

// SUMO switches the blinkers off in the step a continuous lane change ends
// (MSAbstractLaneChangeModel::endLaneChangeManeuver), over the mask sent for that step. Sent again
// after that step (setSignals shows at once), SUMO shows the decider's blinker, as in every other step.
template <class Api>
void SessionImpl<Api>::restore_blinkers_after_lane_change() {
  if (last_signal_mask_ < 0 || (ego_signals() & kBlinkerMask) == (last_signal_mask_ & kBlinkerMask)) return;
  Api::Vehicle::setSignals(ego_, last_signal_mask_);
  answers_.ego_signals = Api::Vehicle::getSignals(ego_);
}

template <class Api>
void SessionImpl<Api>::shift_light_program(const std::string& tls_id, double offset) {
  answers_.forget_lights();  // the light's state and timing change now
  try {
    const std::string program = Api::TrafficLight::getProgram(tls_id);
    for (const auto& logic : Api::TrafficLight::getAllProgramLogics(tls_id)) {
      if (logic.programID != program) continue;
      double cycle = 0.0;
      for (const auto& phase : logic.phases) cycle += phase->duration;
      if (cycle <= 0.0) return;
      // Where the cycle stands now, plus the offset: that phase, with the rest of its duration.
      const double now = Api::Simulation::getTime();
      double into = std::fmod(now + offset, cycle);
      if (into < 0) into += cycle;
      for (std::size_t i = 0; i < logic.phases.size(); ++i) {
        const double duration = logic.phases[i]->duration;
        if (into < duration) {
          Api::TrafficLight::setPhase(tls_id, static_cast<int>(i));
          Api::TrafficLight::setPhaseDuration(tls_id, duration - into);
          return;
        }
        into -= duration;
      }
      return;
    }
  } catch (const std::exception& e) {
    throw SumoError("cannot shift the program of traffic light '" + tls_id + "': " + failure_reason(e));
  }
}

template <class Api>
void SessionImpl<Api>::set_emergency_braking(bool on) {
  if (on == emergency_braking_) return;
  emergency_braking_ = on;
  apply_speed_mode();
}

template <class Api>
void SessionImpl<Api>::set_sumo_lane_limits(bool on) {
  if (on == lane_limits_) return;
  lane_limits_ = on;
  guarded("the ego's speed factor", [&] { Api::Vehicle::setSpeedFactor(ego_, on ? 1.0 : kFreeSpeedFactor); });
}

template <class Api>
void SessionImpl<Api>::set_right_of_way(bool respect) {
  if (respect == right_of_way_) return;
  right_of_way_ = respect;
  apply_speed_mode();
}

template <class Api>
void SessionImpl<Api>::apply_speed_mode() {
  int mode = kSpeedModeSafeSpeed | kSpeedModeMaxAccel;
  if (!emergency_braking_) mode |= kSpeedModeMaxDecel;
  if (right_of_way_) mode |= kSpeedModeRightOfWay;
  try {
    Api::Vehicle::setSpeedMode(ego_, mode);
  } catch (const std::exception& e) {
    throw SumoError("SUMO refused the ego's speed mode: " + failure_reason(e));
  }
}

}  // namespace signalsim::sumo
