// summary.json's sections of what a run did, from its record alone: the counts, why the ego did not
// arrive, where SUMO left the lane plan, the lights on the way and each lane change.
#include "report/summary_sections.hpp"

#include "core/blinker_signals.hpp"
#include "core/number_text.hpp"

namespace signalsim {
namespace {

// With V2I on (docs/behaviour.md §L1.7): how many steps the judge's V2I rule held, and the first of them.
nlohmann::ordered_json v2i_json(const RunRecord& record) {
  std::size_t stop_steps = 0;
  const TimelineRow* first = nullptr;
  for (const TimelineRow& row : record.rows)
    if (row.v2i_stop) {
      ++stop_steps;
      if (!first) first = &row;
    }
  nlohmann::ordered_json first_stop = nullptr;
  if (first)
    first_stop = {{"light", first->tl_id}, {"time", as_written(first->time, 3)},
                  {"s_front", as_written(first->s_front, 3)},
                  {"light_state", first->tl_state ? std::string(1, first->tl_state) : std::string()},
                  {"time_to_red", first->v2i_time_to_red ? nlohmann::ordered_json(as_written(*first->v2i_time_to_red, 3))
                                                         : nlohmann::ordered_json(nullptr)},
                  {"stop_distance", first->stop_distance ? nlohmann::ordered_json(as_written(*first->stop_distance, 3))
                                                         : nlohmann::ordered_json(nullptr)}};
  return {{"stop_steps", stop_steps}, {"first_stop", first_stop}};
}

}  // namespace

double simulated_span(const RunRecord& record, double begin) {
  return record.rows.empty() ? 0.0 : record.rows.back().time - begin;
}

// The run's counts: steps and time, arrival, steps off the route or the plan, events by kind, steps
// per blinker and where SUMO's signals differed from the blinker.
nlohmann::ordered_json counts_json(const RunRecord& record, double begin) {
  nlohmann::ordered_json counts;
  counts["steps"] = record.rows.size();
  counts["simulated_time"] = as_written(simulated_span(record, begin), 3);
  counts["end_time"] = record.rows.empty() ? begin : as_written(record.rows.back().time, 3);
  counts["arrived"] = record.arrived;
  counts["collisions"] = record.collisions;
  counts["off_route_steps"] = record.off_route_steps;
  int off_plan_steps = 0;
  for (const OffPlanStretch& o : record.off_plan) off_plan_steps += o.steps;
  counts["off_plan_steps"] = off_plan_steps;
  std::size_t blinker_events = 0, light_events = 0;
  for (const TimelineEvent& e : record.events) {
    blinker_events += e.kind == "blinker";
    light_events += e.kind == "light";
  }
  counts["blinker_events"] = blinker_events;
  counts["light_events"] = light_events;
  std::size_t left = 0, right = 0, hazard = 0, mismatches = 0;
  for (const TimelineRow& r : record.rows) {
    left += r.blinker == Blinker::Left;
    right += r.blinker == Blinker::Right;
    hazard += r.blinker == Blinker::Hazard;
    if (r.sumo_signals >= 0) {
      mismatches += (r.sumo_signals & sumo::kBlinkerMask) != signal_mask(r.blinker);
    }
  }
  counts["steps_left"] = left;
  counts["steps_right"] = right;
  counts["steps_hazard"] = hazard;
  counts["sumo_signal_mismatches"] = mismatches;
  return counts;
}

// Why the ego did not arrive (step/stuck_watch), null when it did.
nlohmann::ordered_json not_arrived_json(const RunRecord& record) {
  const auto& n = record.not_arrived;
  if (!n) return nullptr;
  nlohmann::ordered_json leader = nullptr;
  if (n->leader) leader = {{"id", n->leader->id}, {"gap", as_written(n->leader->gap, 3)}};
  return {{"reason", n->reason},
          {"detail", n->detail},
          {"time", as_written(n->time, 3)},
          {"s_front", as_written(n->s_front, 3)},
          {"edge", n->edge},
          {"lane", n->lane},
          {"at_rest_for", as_written(n->at_rest_for, 3)},
          {"held_by", n->held_by},
          {"leader", leader},
          {"junction", n->junction}};
}

// Where SUMO left the lane plan (its own lane changes; with signalsim, another connection).
nlohmann::ordered_json off_plan_json(const RunRecord& record) {
  nlohmann::ordered_json off_plan = nlohmann::ordered_json::array();
  for (const OffPlanStretch& o : record.off_plan)
    off_plan.push_back({{"lane", o.lane}, {"planned_lane", o.planned_lane}, {"s_from", as_written(o.s_from, 3)},
                        {"s_to", as_written(o.s_to, 3)}, {"steps", o.steps}});
  return off_plan;
}

// The lights on the way: each stop at one, the red-light violations, the emergency stops and, only
// with V2I on (so every other summary stays as it was), what V2I did.
nlohmann::ordered_json lights_json(const RunRecord& record) {
  nlohmann::ordered_json lights;
  nlohmann::ordered_json stops = nlohmann::ordered_json::array();
  for (const LightStop& stop : record.stops)
    stops.push_back({{"light", stop.tl_id}, {"time", as_written(stop.time, 3)},
                     {"stop_s", as_written(stop.stop_s, 3)}, {"rest_s", as_written(stop.rest_s, 3)},
                     {"error", as_written(stop.error, 3)},
                     {"decision", stop.by_judge ? nlohmann::ordered_json(to_string(stop.decision)) : nullptr},
                     {"level", stop.by_judge ? nlohmann::ordered_json(to_string(stop.worst_level)) : nullptr},
                     {"queued_behind", stop.queued_behind.empty() ? nlohmann::ordered_json(nullptr)
                                                                  : nlohmann::ordered_json(stop.queued_behind)},
                     {"waiting_at", stop.waiting_at.empty() ? nlohmann::ordered_json(nullptr)
                                                            : nlohmann::ordered_json(stop.waiting_at)}});
  lights["stops"] = stops;
  nlohmann::ordered_json violations = nlohmann::ordered_json::array();
  for (const RedLightViolation& v : record.red_violations)
    violations.push_back({{"light", v.tl_id}, {"time", as_written(v.time, 3)},
                          {"s_front", as_written(v.s_front, 3)}});
  lights["red_light_violations"] = violations;
  std::size_t emergency = 0;
  for (const TimelineEvent& e : record.events) emergency += e.kind == "light" && e.to == "emergency_stop";
  lights["emergency_stops"] = emergency;
  if (record.v2i) lights["v2i"] = v2i_json(record);
  return lights;
}

// Each lane change as executed (docs/behaviour.md §T8.2): blinker, approval, prepare, lateral motion.
nlohmann::ordered_json lane_changes_json(const RunRecord& record) {
  nlohmann::ordered_json lane_changes = nlohmann::ordered_json::array();
  const auto optional_written = [](const std::optional<double>& v) -> nlohmann::ordered_json {
    return v ? nlohmann::ordered_json(as_written(*v, 3)) : nlohmann::ordered_json(nullptr);
  };
  for (const LaneChangeRecord& lc : record.lane_changes)
    lane_changes.push_back({{"edge", lc.edge},
                            {"phase", lc.phase},
                            {"shift", as_written(lc.shift, 3)},
                            {"blinker_on_time", optional_written(lc.blinker_on_time)},
                            {"approval_time", optional_written(lc.approval_time)},
                            {"approval_s_base", optional_written(lc.approval_s_base)},
                            {"prepare_duration", optional_written(lc.prepare_duration)},
                            {"lateral_start_s", optional_written(lc.start)},
                            {"lateral_end_s", optional_written(lc.end)}});
  return lane_changes;
}

}  // namespace signalsim
