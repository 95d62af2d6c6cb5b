// The record of a signalsim-driven run: SUMO fields, rows, events, light log; see step_record.hpp.
#include "step/step_record.hpp"

#include <utility>

namespace signalsim {
namespace {

void record_event(RunRecord& record, const TimelineRow& row, std::string kind, std::string from, std::string to,
                  std::string source) {
  record.events.push_back({row.time, row.s_front, std::move(kind), std::move(from), std::move(to), std::move(source)});
}

}  // namespace

TimelineRow timeline_row(const sumo::EgoState& observed, const EgoOnRoute& ego, double lateral_offset,
                         std::optional<double> planned_offset, Blinker blinker, RequestSource source,
                         const LightStep* shown, std::optional<StopLevel> stop_level) {
  TimelineRow row;
  row.time = observed.time;
  row.s_front = ego.s_front;
  row.x = observed.x;
  row.y = observed.y;
  row.speed = ego.speed;  // signed: negative while backing up
  row.accel = observed.accel;
  row.edge = observed.edge;
  row.lane = observed.lane;
  row.lateral_offset = lateral_offset;
  row.planned_offset = planned_offset;
  row.blinker = blinker;
  row.blinker_source = blinker == Blinker::None ? RequestSource::None : source;
  if (shown) {
    row.tl_id = shown->light->tls_id;
    row.tl_state = shown->own_state;
  }
  if (shown && shown->judged) {
    row.tl_observed = shown->observed;
    row.tl_decision = shown->result.decision;
    row.zone = shown->result.zone;
    row.stop_distance = shown->result.distance;
    row.judge_distance = shown->result.judge_dist;
    row.yellow_lamp_line = shown->result.yellow_lamp_line;
    if (shown->result.stop_point_distance) row.stop_s = ego.s_front + *shown->result.stop_point_distance;
    row.stop_level = stop_level;
    row.v2i_stop = shown->result.v2i_stop;
    row.v2i_time_to_red = shown->result.v2i_time_to_red;
  }
  return row;
}

void show_next_light(TimelineRow& row, const sumo::ApproachLight& next, const std::string& state) {
  row.tl_id = next.tls_id;
  if (next.link_index >= 0 && static_cast<std::size_t>(next.link_index) < state.size())
    row.tl_state = state[static_cast<std::size_t>(next.link_index)];
}

void log_lights(const std::vector<LightStep>& lights, RunRecord& record) {
  for (const LightStep& l : lights)
    record.light_log.push_back({record.rows.size(), l.light->route_index, l.own_state,
                                l.judged ? l.result.decision : JudgeDecision::None,
                                l.judged ? l.result.zone : JudgeZone::None});
}

void StepEvents::record(const TimelineRow& row, const std::vector<BehaviorStage::Transition>& transitions,
                        RunRecord& record) {
  if (row.blinker != blinker_) {
    record_event(record, row, "blinker", std::string(to_string(blinker_)), std::string(to_string(row.blinker)),
                 std::string(to_string(row.blinker_source)));
    blinker_ = row.blinker;
  }
  for (const BehaviorStage::Transition& t : transitions)
    record_event(record, row, "lane_change", to_string(t.from), to_string(t.to), t.edge);
  if (row.tl_decision != decision_) {
    record_event(record, row, "light", std::string(to_string(decision_)), std::string(to_string(row.tl_decision)),
                 row.tl_id);
    decision_ = row.tl_decision;
  }
  // With V2I on: when its rule starts or stops holding for the light shown (docs/behaviour.md §L1.7).
  if (record.v2i && row.v2i_stop != v2i_stop_) {
    record_event(record, row, "v2i", v2i_stop_ ? "red_predicted" : "none", row.v2i_stop ? "red_predicted" : "none",
                 row.tl_id);
    v2i_stop_ = row.v2i_stop;
  }
}

}  // namespace signalsim
