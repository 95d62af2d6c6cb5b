#include "step/stuck_watch.hpp"

#include <cstdio>

#include "core/number_text.hpp"

namespace signalsim {

namespace {

constexpr double kJunctionApproach = 10.0;  // [m] the front this close to a junction waits at it

// The junction the front is in, or at the entry of (the next route lanelet is internal).
std::string junction_at(const RouteMap& route, double s_front) {
  if (route.empty()) return "";
  const std::size_t i = route.index_at(s_front);
  const Lanelet& here = route.at(i);
  if (here.is_internal) return here.junction_id;
  if (i + 1 < route.size() && route.at(i + 1).is_internal && here.s_end() - s_front <= kJunctionApproach)
    return route.at(i + 1).junction_id;
  return "";
}

}  // namespace

bool StuckWatch::may_end_at(double time, double speed) const {
  if (limit_ <= 0.0 || !(speed < kRestSpeed && speed > -kRestSpeed)) return false;
  const double clock = counting_ ? free_for_ + (time - last_time_) : free_for_;
  return clock >= limit_ - 1e-9;
}

bool StuckWatch::observe(double time, double speed, const std::string& held_by, bool queued) {
  const double since_last = observed_ ? time - last_time_ : 0.0;
  observed_ = true;
  last_time_ = time;
  held_by_ = held_by;
  const bool at_rest = speed < kRestSpeed && speed > -kRestSpeed;  // backing up moves backward
  if (!at_rest) {
    rest_since_.reset();
    free_for_ = 0.0;
    counting_ = false;
    return false;
  }
  if (!rest_since_) rest_since_ = time;
  if (!held_by.empty()) {  // signalsim keeps it at rest: the clock restarts
    free_for_ = 0.0;
    counting_ = false;
    return false;
  }
  if (queued) {  // a red light ahead keeps the queue: the clock pauses
    counting_ = false;
    return false;
  }
  if (counting_) free_for_ += since_last;
  counting_ = true;
  return limit_ > 0.0 && free_for_ >= limit_ - 1e-9;
}

NotArrived not_arrived(const std::string& reason, double duration, const TimelineRow& last, const StuckWatch& watch,
                       const std::optional<LeaderInfo>& leader, const RouteMap& route) {
  NotArrived n;
  n.reason = reason;
  n.time = last.time;
  n.s_front = last.s_front;
  n.edge = last.edge;
  n.lane = last.lane;
  n.at_rest_for = watch.at_rest_for();
  n.held_by = watch.held_by();
  const bool free_rest = watch.at_rest() && n.held_by.empty();
  if (free_rest) n.leader = leader;
  if (free_rest && !n.leader) n.junction = junction_at(route, last.s_front);

  const std::string where =
      format_text("s_front %.2f m", last.s_front) + " (edge " + last.edge + ", lane " + last.lane + ")";
  std::string why;  // SUMO's side, for a rest signalsim did not ask for
  if (n.leader) {
    why = "behind vehicle '" + n.leader->id + "' (gap " + format_text("%.2f", n.leader->gap) + " m)";
  } else if (!n.junction.empty()) {
    why = "no leader within 100 m: held by SUMO at junction " + n.junction;
  } else {
    why = "SUMO gives no reason (no leader within 100 m, not at a junction)";
  }
  if (reason == "stuck") {
    n.detail = "at rest for " + format_text("%.1f", watch.stuck_for()) + " s at " + where +
               " while signalsim commanded it to drive; " + why;
  } else if (!watch.at_rest()) {
    n.detail = "duration " + format_text("%g", duration) + " s reached at " + where + ", moving at " +
               format_text("%.2f", last.speed) + " m/s";
  } else if (!n.held_by.empty()) {
    n.detail = "duration " + format_text("%g", duration) + " s reached at " + where + ", at rest for " +
               format_text("%.1f", n.at_rest_for) + " s, held by signalsim: " + n.held_by;
  } else {
    n.detail = "duration " + format_text("%g", duration) + " s reached at " + where + ", at rest for " +
               format_text("%.1f", n.at_rest_for) + " s while signalsim commanded it to drive; " + why;
  }
  return n;
}

}  // namespace signalsim
