#include "step/behavior_stage.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {
namespace {

constexpr double kPathBackward = 5.0;  // [m] behind base_link: the behaviour modules' path start

}  // namespace

BehaviorStage::BehaviorStage(LateralPlan plan, const BehaviorSignalParameters& params,
                             const BehaviorStageConfig& config)
    : plan_(std::move(plan)), params_(params), config_(config) {
  for (const LateralSegment& seg : plan_.segments) executions_.emplace_back(seg.lane_change, config.gaps);
}

const LaneChangeExecution* BehaviorStage::execution_of(const LateralSegment& seg) const {
  if (seg.kind != LateralKind::LaneChange) return nullptr;
  const auto index = static_cast<std::size_t>(&seg - plan_.segments.data());
  return index < executions_.size() ? &executions_[index] : nullptr;
}

double BehaviorStage::planned_offset(const LateralSegment& seg, double s, bool backing) const {
  if (backing) return seg.plan.lines().front().shift_start;  // holding the road side before the pull out
  if (const LaneChangeExecution* lc = execution_of(seg)) {
    const auto& line = lc->approved_line();
    return line ? line->offset_at(s) : seg.lane_change.shift_start;
  }
  return seg.plan.offset_at(s);
}

std::size_t BehaviorStage::current_lane_change(double s_base) const {
  for (std::size_t i = 0; i < plan_.segments.size(); ++i) {
    const LateralSegment& seg = plan_.segments[i];
    const LaneChangePhase phase = executions_[i].phase();
    if (seg.kind == LateralKind::LaneChange && phase != LaneChangePhase::Done && phase != LaneChangePhase::Missed &&
        seg.lane_change.earliest_start <= s_base + config_.path_forward)
      return i;
  }
  return plan_.segments.size();
}

const LateralSegment* BehaviorStage::waiting_lane_change(double s_base) const {
  const std::size_t i = current_lane_change(s_base);
  if (i == plan_.segments.size() || executions_[i].phase() == LaneChangePhase::Running) return nullptr;
  return &plan_.segments[i];
}

BehaviorStage::Result BehaviorStage::step(const Observation& o) {
  const EgoOnRoute& ego = o.ego;
  const double path_back = std::min(config_.route_length, ego.s_base + config_.path_forward);
  const auto module_signal = [&](const LateralSegment& seg) {
    BehaviorSignalInput in;
    in.path_front = std::max(0.0, ego.s_base - kPathBackward);
    in.path_back = path_back;
    in.current_shift_length = o.segment == &seg ? o.lateral_offset : 0.0;
    in.route_start = 0.0;
    in.lane.left_half_width = seg.left_half_width;
    in.lane.right_half_width = seg.right_half_width;
    // The yaw relative to the lane: the plan's (SUMO follows it exactly, see planned_offset).
    if (o.segment == &seg) in.ego_relative_yaw = std::atan(seg.plan.heading_at(ego.s_base));
    return in;
  };

  LaneChangeSignal::Input lane_change;
  AvoidanceSignal::Input avoidance;
  PullOutSignal::Input pull_out;
  PullOverSignal::Input pull_over;
  BehaviorRequests requests;
  requests.now = o.now;
  LaneChangeExecution* current_lc = nullptr;
  const LateralSegment* current_lc_segment = nullptr;
  LaneChangeExecution::Step lc_step;

  for (std::size_t i = 0; i < plan_.segments.size(); ++i) {
    const LateralSegment& seg = plan_.segments[i];
    const bool finished = executions_[i].phase() == LaneChangePhase::Done || executions_[i].phase() == LaneChangePhase::Missed;
    if (seg.kind == LateralKind::LaneChange && !current_lc && !finished &&
        seg.lane_change.earliest_start <= ego.s_base + config_.path_forward) {
      current_lc = &executions_[i];
      current_lc_segment = &seg;
      lc_step.now = o.now;
      lc_step.s_base = ego.s_base;
      lc_step.speed = ego.speed;
      // The prepare segment is driven without braking (the ego does not brake for the lane change
      // once approved; braking for the hold point ends with the approval), and below
      // min_lane_changing_velocity at max_longitudinal_acc (the floor of the prepare time is the time
      // to reach that speed, docs/behaviour.md §T8.2).
      lc_step.accel = ego.speed < params_.min_lane_changing_velocity ? params_.max_longitudinal_acc
                                                                    : std::max(o.accel, 0.0);
      lc_step.max_speed = config_.max_speed;
      lc_step.vehicle_length = config_.vehicle_length;
      lc_step.base_link_to_front = params_.base_link_to_front;
      lc_step.prepare_duration = modules_.lane_change.actual_prepare_duration(o.now, ego.speed, params_);
      const ShiftLine line = current_lc->line(lc_step);
      const bool running = current_lc->phase() == LaneChangePhase::Running;
      lane_change.phase = running ? LaneChangeSignal::Phase::Running : LaneChangeSignal::Phase::WaitingApproval;
      lane_change.direction = line.relative_shift() > 0 ? TurnIndicator::EnableLeft : TurnIndicator::EnableRight;
      // Activation (the module's blinker) is measured to the earliest start of the lateral motion.
      lane_change.lane_changing_start = running ? line.s_start : seg.lane_change.earliest_start;
      lane_change.lane_changing_end = line.s_end;
      lane_change.boundary_crossing = line.s_at_offset(seg.boundary);
      lane_change.previous_path_front = std::max(0.0, ego.s_base - kPathBackward);
      lane_change.previous_path_end = path_back;
      // [LC] current_dist_buffer.min: the distance the remaining lane change needs (its length).
      lane_change.current_dist_buffer_min = seg.lane_change.length;
      requests.lane_change = &lane_change;
    }
    if (seg.kind == LateralKind::Avoidance && !requests.avoidance && seg.plan.lines().back().s_end >= ego.s_base &&
        seg.plan.lines().back().s_end <= path_back) {
      for (std::size_t k = 0; k < seg.plan.lines().size(); ++k) {
        const ShiftLine& line = seg.plan.lines()[k];
        avoidance.shift_lines.push_back({seg.first_line_id + k, line.s_start, line.s_end, line.shift_start, line.shift_end});
      }
      avoidance.planned_shift_at_ego = o.segment == &seg ? planned_offset(seg, ego.s_base, o.backing) : 0.0;
      avoidance.signal = module_signal(seg);
      requests.avoidance = &avoidance;
    }
    if (seg.kind == LateralKind::PullOut && o.segment == &seg && ego.s_base <= seg.plan.lines().back().s_end) {
      const ShiftLine& line = seg.plan.lines().front();
      pull_out.pull_out_start = line.s_start;
      pull_out.pull_out_end = line.s_end;
      pull_out.shift_at_start = line.shift_start;
      pull_out.shift_at_end = line.shift_end;
      pull_out.driving_forward = !o.backing;
      pull_out.override_ego_stopped_check = !o.departed;  // [SP]: not yet departed
      pull_out.closest_lanelet = seg.route_index;
      pull_out.signal = module_signal(seg);
      requests.pull_out = &pull_out;
    }
    if (seg.kind == LateralKind::PullOver && seg.goal_s <= path_back) {
      const ShiftLine& line = seg.plan.lines().front();
      pull_over.path_decided = true;
      pull_over.pull_over_start = line.s_start;
      pull_over.pull_over_end = line.s_end;
      pull_over.shift_at_start = line.shift_start;
      pull_over.shift_at_end = line.shift_end;
      pull_over.closest_lanelet = seg.route_index;
      pull_over.signal = module_signal(seg);
      requests.pull_over = &pull_over;
    }
  }

  Result result;
  result.behavior = merge_behavior_requests(modules_, requests, ego, params_);

  if (current_lc) {
    // The module's state after this step drives the phases: its blinker timestamp shortens the
    // prepare segment (docs/behaviour.md §T8.2 calc_actual_prepare_duration).
    lc_step.module_active = modules_.lane_change.active();
    lc_step.blinker_on_since = modules_.lane_change.blinker_on_since();
    lc_step.prepare_duration = modules_.lane_change.actual_prepare_duration(o.now, ego.speed, params_);
    if (lc_step.module_active && current_lc->phase() != LaneChangePhase::Running)
      lc_step.target_lane = o.target_lane;
    const LaneChangePhase before = current_lc->phase();
    if (current_lc->update(lc_step)) {
      // One transition per phase passed (pending -> waiting_approval -> running may be one step).
      LaneChangePhase from = before;
      const LaneChangePhase to = current_lc->phase();
      if (from == LaneChangePhase::Pending && to != LaneChangePhase::WaitingApproval) {
        result.transitions.push_back({current_lc_segment->edge, from, LaneChangePhase::WaitingApproval});
        from = LaneChangePhase::WaitingApproval;
      }
      result.transitions.push_back({current_lc_segment->edge, from, to});
      // Done or given up: the next lane change starts afresh.
      if (to == LaneChangePhase::Done || to == LaneChangePhase::Missed) modules_.lane_change.reset();
    }
    result.hold_distance = current_lc->distance_to_hold_point(ego.s_base);
  }
  return result;
}

std::vector<LaneChangeRecord> BehaviorStage::lane_change_records() const {
  std::vector<LaneChangeRecord> out;
  for (std::size_t i = 0; i < plan_.segments.size(); ++i) {
    const LateralSegment& seg = plan_.segments[i];
    if (seg.kind != LateralKind::LaneChange) continue;
    const LaneChangeExecution& lc = executions_[i];
    LaneChangeRecord r;
    r.edge = seg.edge;
    r.phase = to_string(lc.phase());
    r.shift = -seg.lane_change.shift_start;
    r.blinker_on_time = lc.blinker_on_since();
    if (const auto& a = lc.approval()) {
      r.blinker_on_time = a->blinker_on_since;
      r.approval_time = a->time;
      r.approval_s_base = a->s_base;
      r.prepare_duration = a->prepare_duration;
    }
    if (const auto& line = lc.approved_line()) {
      r.start = line->s_start;
      r.end = line->s_end;
    }
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<ManeuverLine> maneuver_lines(const LateralPlan& plan, const std::vector<LaneChangeRecord>& executed,
                                         double min_shift) {
  std::vector<ManeuverLine> out;
  const auto kind_of = [](LateralKind k) {
    switch (k) {
      case LateralKind::LaneChange: return "lane_change";
      case LateralKind::Avoidance: return "avoidance";
      case LateralKind::PullOut: return "pull_out";
      case LateralKind::PullOver: return "pull_over";
    }
    return "?";
  };
  for (const LateralSegment& seg : plan.segments) {
    for (ShiftLine line : seg.plan.lines()) {
      if (seg.kind == LateralKind::LaneChange) {
        const LaneChangeRecord* record = nullptr;
        for (const LaneChangeRecord& r : executed)
          if (r.edge == seg.edge) record = &r;
        if (record && !(record->start && record->end)) continue;  // never approved: nothing executed
        if (record) {
          line.s_start = *record->start;
          line.s_end = *record->end;
        }
      }
      if (std::abs(line.relative_shift()) < min_shift) continue;
      out.push_back({kind_of(seg.kind), seg.edge, line.s_start, line.s_end,
                     line.relative_shift() > 0 ? Blinker::Left : Blinker::Right});
    }
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const ManeuverLine& a, const ManeuverLine& b) { return a.s_start < b.s_start; });
  return out;
}

}  // namespace signalsim
