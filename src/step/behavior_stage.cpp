// The behaviour stage of a step; see behavior_stage.hpp.
#include "step/behavior_stage.hpp"

#include <algorithm>
#include <cmath>

namespace signalsim {
namespace {

constexpr double kPathBackward = 5.0;  // [m] behind base_link: the behaviour modules' path start

// The common signal input of a module on `seg`: the module path, the shift measured on the ego's own
// segment, the lane's half widths and the yaw relative to the lane (the plan's: SUMO follows it
// exactly, see planned_offset).
BehaviorSignalInput signal_input(const LateralSegment& seg, const BehaviorStage::Observation& o,
                                 const ModulePath& path) {
  BehaviorSignalInput in;
  in.path_front = path.front;
  in.path_back = path.back;
  in.current_shift_length = o.segment == &seg ? o.lateral_offset : 0.0;
  in.route_start = 0.0;
  in.lane.left_half_width = seg.left_half_width;
  in.lane.right_half_width = seg.right_half_width;
  if (o.segment == &seg) in.ego_relative_yaw = std::atan(seg.plan.heading_at(o.ego.s_base));
  return in;
}

// Keeps the nearest of this step's holds.
void add_hold(BehaviorStage::Result& result, std::optional<double> distance, const char* reason, const char* kind) {
  if (distance && (!result.hold || *distance < result.hold->distance))
    result.hold = BehaviorStage::Hold{*distance, reason, kind};
}

// Avoidance: every shift line of its plan (ids from the segment's first; registered, or the candidate
// lines while waiting for approval), the shift that path plans at the ego, the phase and the policy.
void add_avoidance(const LateralSegment& seg, bool waiting, CandidateTurnSignalPolicy policy,
                   double planned_shift_at_ego, const BehaviorSignalInput& signal, ModuleInputs& in) {
  for (std::size_t k = 0; k < seg.plan.lines().size(); ++k) {
    const ShiftLine& line = seg.plan.lines()[k];
    in.avoidance.shift_lines.push_back({seg.first_line_id + k, line.s_start, line.s_end, line.shift_start, line.shift_end});
  }
  in.avoidance.phase = waiting ? AvoidanceSignal::Phase::WaitingApproval : AvoidanceSignal::Phase::Running;
  in.avoidance.policy = policy;
  in.avoidance.planned_shift_at_ego = planned_shift_at_ego;
  in.avoidance.signal = signal;
  in.requests.avoidance = &in.avoidance;
}

// Pull out: its shift line, whether the ego drives forward and has departed ([SP]), the time since it
// first drove forward engaged, and whether it may back up.
void add_pull_out(const LateralSegment& seg, const BehaviorStage::Observation& o,
                  std::optional<double> since_engaged_forward, bool enable_back, const BehaviorSignalInput& signal,
                  ModuleInputs& in) {
  const ShiftLine& line = seg.plan.lines().front();
  PullOutSignal::Input& pull_out = in.pull_out;
  pull_out.pull_out_start = line.s_start;
  pull_out.pull_out_end = line.s_end;
  pull_out.shift_at_start = line.shift_start;
  pull_out.shift_at_end = line.shift_end;
  pull_out.driving_forward = !o.backing;
  pull_out.override_ego_stopped_check = !o.departed;  // [SP]: not yet departed
  pull_out.time_since_first_engaged_forward = since_engaged_forward;
  pull_out.enable_back = enable_back;
  pull_out.closest_lanelet = seg.route_index;
  pull_out.signal = signal;
  in.requests.pull_out = &pull_out;
}

// Pull over: its shift line, the path decided once the goal is within the module path.
void add_pull_over(const LateralSegment& seg, const BehaviorSignalInput& signal, ModuleInputs& in) {
  const ShiftLine& line = seg.plan.lines().front();
  PullOverSignal::Input& pull_over = in.pull_over;
  pull_over.path_decided = true;
  pull_over.pull_over_start = line.s_start;
  pull_over.pull_over_end = line.s_end;
  pull_over.shift_at_start = line.shift_start;
  pull_over.shift_at_end = line.shift_end;
  pull_over.closest_lanelet = seg.route_index;
  pull_over.signal = signal;
  in.requests.pull_over = &pull_over;
}

}  // namespace

BehaviorStage::BehaviorStage(LateralPlan plan, const BehaviorSignalParameters& params,
                             const BehaviorStageConfig& config)
    : plan_(std::move(plan)),
      params_(params),
      config_(config),
      departure_(config.start_time + plan_.engage_delay, params.prepare_time_before_start) {
  const bool stop_on_approval = params.candidate_path_turn_signal == CandidateTurnSignalPolicy::StopOnApproval;
  for (const LateralSegment& seg : plan_.segments) {
    executions_.emplace_back(seg.lane_change, config.gaps);
    avoidances_.emplace_back(seg.avoidance, stop_on_approval, params.turn_signal_on_approval_hold_duration);
  }
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
  const auto index = static_cast<std::size_t>(&seg - plan_.segments.data());
  if (seg.kind == LateralKind::Avoidance && !avoidances_.at(index).approved()) return seg.plan.lines().front().shift_start;
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

// One step: the inputs of the four modules (each from its segment of the plan, when the module runs:
// see behavior_stage.hpp), merged in Autoware's order; then the current lane change moves on.
BehaviorStage::Result BehaviorStage::step(const Observation& o) {
  const EgoOnRoute& ego = o.ego;
  const ModulePath path{std::max(0.0, ego.s_base - kPathBackward),
                        std::min(config_.route_length, ego.s_base + config_.path_forward)};
  ModuleInputs in;
  in.requests.now = o.now;
  Result result;
  const std::size_t lc = current_lane_change(ego.s_base);
  LaneChangeExecution::Step lc_step;
  if (lc < plan_.segments.size()) {
    lc_step = lane_change_step(o);
    add_lane_change(plan_.segments[lc], executions_[lc], lc_step, path, in);
  }
  for (const LateralSegment& seg : plan_.segments) {
    if (seg.kind == LateralKind::Avoidance && !in.requests.avoidance && seg.plan.lines().back().s_end >= ego.s_base &&
        seg.plan.lines().back().s_end <= path.back)
      run_avoidance(seg, o, path, in, result);
    if (seg.kind == LateralKind::PullOut && o.segment == &seg && ego.s_base <= seg.plan.lines().back().s_end)
      run_pull_out(seg, o, path, in, result);
    if (seg.kind == LateralKind::PullOver && seg.goal_s <= path.back) add_pull_over(seg, signal_input(seg, o, path), in);
  }
  result.behavior = merge_behavior_requests(modules_, in.requests, ego, params_);
  if (lc < plan_.segments.size()) advance_lane_change(lc, lc_step, o, result);
  return result;
}

// The lane change's step before the modules run: the ego's motion, and the prepare segment driven
// without braking (the ego does not brake for the lane change once approved; braking for the hold
// point ends with the approval), and below min_lane_changing_velocity at max_longitudinal_acc (the
// floor of the prepare time is the time to reach that speed, docs/behaviour.md §T8.2).
LaneChangeExecution::Step BehaviorStage::lane_change_step(const Observation& o) const {
  LaneChangeExecution::Step step;
  step.now = o.now;
  step.s_base = o.ego.s_base;
  step.speed = o.ego.speed;
  step.accel = o.ego.speed < params_.min_lane_changing_velocity ? params_.max_longitudinal_acc : std::max(o.accel, 0.0);
  step.max_speed = config_.max_speed;
  step.vehicle_length = config_.vehicle_length;
  step.base_link_to_front = params_.base_link_to_front;
  step.prepare_duration = modules_.lane_change.actual_prepare_duration(o.now, o.ego.speed, params_);
  return step;
}

// The current lane change's module input: its line as the execution plans it this step.
void BehaviorStage::add_lane_change(const LateralSegment& seg, LaneChangeExecution& execution,
                                   const LaneChangeExecution::Step& step, const ModulePath& path,
                                   ModuleInputs& in) const {
  const ShiftLine line = execution.line(step);
  const bool running = execution.phase() == LaneChangePhase::Running;
  LaneChangeSignal::Input& lane_change = in.lane_change;
  lane_change.phase = running ? LaneChangeSignal::Phase::Running : LaneChangeSignal::Phase::WaitingApproval;
  lane_change.direction = line.relative_shift() > 0 ? TurnIndicator::EnableLeft : TurnIndicator::EnableRight;
  // Activation (the module's blinker) is measured to the earliest start of the lateral motion.
  lane_change.lane_changing_start = running ? line.s_start : seg.lane_change.earliest_start;
  lane_change.lane_changing_end = line.s_end;
  lane_change.boundary_crossing = line.s_at_offset(seg.boundary);
  lane_change.previous_path_front = path.front;
  lane_change.previous_path_end = path.back;
  // [LC] current_dist_buffer.min: the distance the remaining lane change needs (its length).
  lane_change.current_dist_buffer_min = seg.lane_change.length;
  in.requests.lane_change = &lane_change;
}

// After the modules ran: the lane change's phases move on. The module's state after this step drives
// them: its blinker timestamp shortens the prepare segment (docs/behaviour.md §T8.2
// calc_actual_prepare_duration); the target lane's traffic is read only while it waits for approval.
void BehaviorStage::advance_lane_change(std::size_t index, LaneChangeExecution::Step step, const Observation& o,
                                        Result& result) {
  LaneChangeExecution& execution = executions_[index];
  const LateralSegment& seg = plan_.segments[index];
  step.module_active = modules_.lane_change.active();
  step.blinker_on_since = modules_.lane_change.blinker_on_since();
  step.prepare_duration = modules_.lane_change.actual_prepare_duration(o.now, o.ego.speed, params_);
  if (step.module_active && execution.phase() != LaneChangePhase::Running) step.target_lane = o.target_lane;
  const LaneChangePhase before = execution.phase();
  if (execution.update(step)) {
    // One transition per phase passed (pending -> waiting_approval -> running may be one step).
    LaneChangePhase from = before;
    const LaneChangePhase to = execution.phase();
    if (from == LaneChangePhase::Pending && to != LaneChangePhase::WaitingApproval) {
      result.transitions.push_back({seg.edge, from, LaneChangePhase::WaitingApproval});
      from = LaneChangePhase::WaitingApproval;
    }
    result.transitions.push_back({seg.edge, from, to});
    // Done or given up: the next lane change starts afresh.
    if (to == LaneChangePhase::Done || to == LaneChangePhase::Missed) modules_.lane_change.reset();
  }
  add_hold(result, execution.distance_to_hold_point(o.ego.s_base), "the hold point of a lane change waiting for approval",
           "lane_change_hold");
}

// The avoidance's phase moves on before its module runs (an approval or a release is seen by the step
// it comes in, docs/behaviour.md §T8.2 "Avoidance"); then its module input, and the wait point or the
// hold on approval. While waiting the module sees the candidate path's offset at the ego.
void BehaviorStage::run_avoidance(const LateralSegment& seg, const Observation& o, const ModulePath& path,
                                  ModuleInputs& in, Result& result) {
  AvoidanceExecution& execution = avoidances_.at(static_cast<std::size_t>(&seg - plan_.segments.data()));
  execution.update({o.now, o.ego.s_base, std::abs(o.ego.speed) < AvoidanceSignal::kStoppedSpeed});
  const double planned_shift_at_ego = o.segment == &seg ? seg.plan.offset_at(o.ego.s_base) : 0.0;
  add_avoidance(seg, execution.phase() == AvoidancePhase::WaitingApproval, params_.candidate_path_turn_signal,
                planned_shift_at_ego, signal_input(seg, o, path), in);
  add_hold(result, execution.distance_to_hold_point(o.ego.s_base),
           execution.phase() == AvoidancePhase::Holding ? "an approved avoidance holding with its blinker (stop_on_approval)"
                                                        : "the wait point of an avoidance waiting for approval",
           "avoidance_hold");
}

// The start planner: its clock sees the step first (Autoware's updateData), then the module runs; it
// holds the ego before engagement and for prepare_time_before_start after (docs/behaviour.md §T8.2 "Pull out").
void BehaviorStage::run_pull_out(const LateralSegment& seg, const Observation& o, const ModulePath& path,
                                 ModuleInputs& in, Result& result) {
  departure_.observe(o.now, !o.backing);
  add_pull_out(seg, o, departure_.time_since_first_engaged_forward(o.now), params_.enable_back,
               signal_input(seg, o, path), in);
  if (departure_.holds(o.now))
    add_hold(result, 0.0, departure_.engaged(o.now) ? "the start planner's wait before starting (prepare_time_before_start)"
                                                    : "the start planner before engagement (engage_delay)",
             "pull_out_wait");
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
