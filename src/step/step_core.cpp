// The stages of one signalsim-driven step between SUMO's ports; see step_core.hpp.
#include "step/step_core.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <nlohmann/json.hpp>

#include "step/route_planning.hpp"

namespace signalsim {
namespace {

constexpr double kDepartedSpeed = 0.1;  // [m/s] start_planner moving_velocity_threshold

Blinker blinker_of(const TurnSignalDecision& d) {
  if (d.hazard == HazardLights::Enable) return Blinker::Hazard;
  if (d.turn == TurnIndicator::EnableLeft) return Blinker::Left;
  if (d.turn == TurnIndicator::EnableRight) return Blinker::Right;
  return Blinker::None;
}

BehaviorStageConfig behavior_config_for(const Scenario& scenario, const RouteMap& route, double start_time) {
  BehaviorStageConfig config;
  config.path_forward = scenario.run_params.decider.forward_path_length;
  config.route_length = route.length();
  config.vehicle_length = scenario.ego.length;
  config.max_speed = scenario.ego.max_speed;
  config.gaps = {scenario.run_params.lane_change_safety_rear_gap, scenario.run_params.lane_change_safety_front_gap};
  config.start_time = start_time;
  return config;
}

// The plan's last pull over, if any: its goal is a stop (the speed stage).
const LateralSegment* pull_over_goal(const LateralPlan& plan) {
  const LateralSegment* goal = nullptr;
  for (const LateralSegment& seg : plan.segments)
    if (seg.kind == LateralKind::PullOver) goal = &seg;
  return goal;
}

RequestSource module_of(LateralKind kind) {
  switch (kind) {
    case LateralKind::LaneChange: return RequestSource::LaneChange;
    case LateralKind::Avoidance: return RequestSource::Avoidance;
    case LateralKind::PullOut: return RequestSource::PullOut;
    case LateralKind::PullOver: return RequestSource::PullOver;
  }
  return RequestSource::None;
}

std::string parameter_text(const ParameterValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        else if constexpr (std::is_same_v<T, int>) return std::to_string(v);
        else if constexpr (std::is_same_v<T, double>) return nlohmann::json(v).dump();  // shortest round trip
        else return v;
      },
      value);
}

// A light judge's reason as the timeline writes it: at most 64 bytes (not cut inside a UTF-8
// character), a comma as ';', a quote or a control character as a space (docs/decider.md).
std::string cleaned_reason(const std::string& text) {
  std::string out = text.substr(0, 64);
  if (text.size() > 64)
    while (!out.empty() && (static_cast<unsigned char>(out.back()) & 0xC0) == 0x80) out.pop_back();
  if (text.size() > 64 && !out.empty() && static_cast<unsigned char>(out.back()) >= 0xC0) out.pop_back();
  for (char& c : out) {
    if (c == ',') c = ';';
    else if (c == '"' || static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = ' ';
  }
  return out;
}

// What a system under test is given once (docs/decider.md): the route, the planned maneuvers' shift
// lines and every run parameter by name.
SutRun sut_run(const Scenario& scenario, const RouteMap& route, const LateralPlan& lateral, const std::string& out_dir) {
  SutRun run;
  run.scenario = scenario.name;
  run.step_length = scenario.step_length;
  run.vehicle_length = scenario.ego.length;
  run.base_link_to_front = scenario.ego.base_link_to_front;
  for (const auto& [name, value] : scenario.params.values()) run.parameters.emplace_back(name, parameter_text(value));
  run.route = &route;
  run.timeout = scenario.sut_timeout;
  run.out_dir = out_dir;
  for (const LateralSegment& seg : lateral.segments)
    for (const ShiftLine& line : seg.plan.lines())
      run.shift_lines.push_back({module_of(seg.kind), seg.edge, line.s_start, line.s_end, line.relative_shift()});
  return run;
}

// The lights a step reads, as a SUT's step before it is filled: a light judge names the ego
// parameters it reads for them (LightJudgeSut::ego_parameters).
SutStep demanded_lights(const ObservationDemand& want) {
  SutStep in;
  for (const LightDemand& l : want.lights) in.lights.emplace_back().tls_id = l.tls_id;
  return in;
}

}  // namespace

double run_end_time(const Scenario& scenario, double start_time) {
  return std::min(start_time + scenario.duration, scenario.sumo.end.value_or(std::numeric_limits<double>::infinity()));
}

// The light stage on the route's lights; V2I (docs/behaviour.md §L1.7) reads SUMO's programs and
// timing through the observation, only when it is on.
StepCore::StepCore(CoreSetup setup)
    : scenario_(setup.scenario),
      route_(setup.route),
      lateral_(setup.lateral),
      b2f_(scenario_.ego.base_link_to_front),
      dt_(scenario_.step_length),
      judge_params_(scenario_.run_params.judge),
      end_time_(run_end_time(scenario_, setup.start_time)),
      decider_(turn_signal_parameters(scenario_)),
      behavior_(lateral_, behavior_parameters(scenario_), behavior_config_for(scenario_, route_, setup.start_time)),
      lights_(std::move(setup.lights), judge_params_, scenario_.perception,
              scenario_.run_params.decider.forward_path_length, scenario_.v2i_channel),
      outcomes_(judge_params_.stop_margin),
      stuck_(scenario_.run_params.stuck_rest_time),
      plan_watch_(route_, lateral_),
      locator_(route_, scenario_.ego.depart_pos),
      suts_(std::move(setup.suts)),
      speed_(scenario_, route_, pull_over_goal(behavior_.plan())) {
  record_.base_link_to_front = b2f_;
  record_.sumo = std::move(setup.sumo);
  record_.v2i = judge_params_.v2i.use_remaining_time;
  record_.decider_sut = suts_.decider_name;
  record_.light_judge_sut = suts_.light_judge_name;
  if (suts_.decider || suts_.light_judge) {
    const SutRun run = sut_run(scenario_, route_, lateral_, record_.sumo.out_dir);
    if (suts_.decider) suts_.decider->start(run);
    if (suts_.light_judge) {
      lights_.keep_delivered();
      suts_.light_judge->start(run);
    }
  }
}

// demand: the front located on the route (monotonic: searched from the lanelet it was on), and what
// the step will read at that place. The leader is asked for when this row may begin a stop at a
// light or end the run (a rest behind a vehicle is explained by the vehicle ahead at the row).
ObservationDemand StepCore::demand(const sumo::EgoState& ego) {
  place_ = locator_.locate(ego.lane, ego.edge, ego.lane_pos);
  const double s_front = place_.s_front;
  const double row_speed = row_speed_of(ego.speed, ego.time);
  ObservationDemand want;
  if (const LateralSegment* seg = behavior_.plan().on_edge(ego.edge)) want.lateral_reference_lane = seg->reference_lane;
  if (const LateralSegment* waiting = behavior_.waiting_lane_change(s_front - b2f_))
    want.lane_traffic = waiting->reference_lane;
  lights_.demand(s_front, want);
  if (suts_.decider && suts_.decider->reads_sumo_signals()) want.signals = want.signals_now = true;
  if (suts_.light_judge) want.ego_parameters = suts_.light_judge->ego_parameters(demanded_lights(want));
  want.leader = outcomes_.needs_leader(row_speed) || stuck_.may_end_at(ego.time, row_speed) ||
                ego.time + dt_ >= end_time_ - 0.5 * dt_ || fell_short(ego.speed);
  return want;
}

// Backing up (pull out with `backward`, emulated): not driving forward, until the plan's distance is
// backed up (the ego moves back only once engaged, docs/behaviour.md §T8.2 "Pull out").
bool StepCore::backing() const { return backed_up_ < lateral_.backward - 1e-9; }

// The row's signed speed: negative while moving back, else SUMO's.
double StepCore::row_speed_of(double sumo_speed, double time) const {
  return backing() && behavior_.engaged(time) ? -kBackwardSpeed : sumo_speed;
}

// observe: whether SUMO left the lane plan, and the lateral offset, measured against the planned lane
// while the ego is on a segment's edge.
StepNow StepCore::observe(const StepObservation& seen) {
  StepNow now;
  now.sumo = seen.ego;
  if (!place_.on_route) ++record_.off_route_steps;  // the lane is not on the route: s held (counted)
  const double s_front = place_.s_front;
  now.off_plan = plan_watch_.observe(now.sumo.lane, now.sumo.edge, place_.index, s_front, now.sumo.time, record_);
  now.backing = backing();
  now.moving_back = now.backing && behavior_.engaged(now.sumo.time);
  now.ego = EgoOnRoute{s_front, s_front - b2f_, row_speed_of(now.sumo.speed, now.sumo.time)};
  // Autoware's start planner (updateData): has_departed once engaged and faster than its
  // moving_velocity_threshold, 0.1 m/s (docs/behaviour.md §T8.2 "Pull out").
  if (now.sumo.speed > kDepartedSpeed && behavior_.engaged(now.sumo.time)) departed_ = true;
  now.segment = behavior_.plan().on_edge(now.sumo.edge);
  now.lateral_offset = now.segment ? seen.lateral_offset.value() : now.sumo.lateral_offset;
  return now;
}

// A waiting lane change's target lane: the other vehicles on it, in route s.
std::vector<OccupiedSpan> StepCore::target_lane_traffic(const StepObservation& seen, double s_base) const {
  std::vector<OccupiedSpan> spans;
  const LateralSegment* waiting = behavior_.waiting_lane_change(s_base);
  if (!waiting) return spans;
  const double lane_start = route_.at(waiting->route_index).s_start;
  for (const sumo::SumoSession::LaneVehicle& v : seen.lane_traffic)
    spans.push_back({lane_start + v.pos - v.length, lane_start + v.pos});
  return spans;
}

// One step: maneuver (the behaviour modules, docs/behaviour.md §T8, and the lane changes' phases),
// decide (the decider takes the window of route lanelets around base_link itself, since its back
// length depends on the roundabouts, docs/behaviour.md §T3.2), light, plan; then the commands.
// Whether SUMO's speed now fell short of the previous step's command (the leader then explains it).
bool StepCore::fell_short(double sumo_speed) const {
  return !record_.rows.empty() && record_.rows.back().planned_speed &&
         sumo_speed < *record_.rows.back().planned_speed - kSpeedShortfall;
}

// The previous row's step as SUMO executed it: its speed after the step and, when it fell short of
// the command, SUMO's leader now (asked for by demand) or SUMO's other rules.
void StepCore::explain_previous_row(const StepObservation& seen) {
  if (record_.rows.empty()) return;
  TimelineRow& previous = record_.rows.back();
  previous.sumo_speed = seen.ego.speed;
  if (!fell_short(seen.ego.speed)) return;
  previous.sumo_limited_by = seen.leader ? "leader" : "sumo";
  if (seen.leader) {
    previous.leader = seen.leader->id;
    previous.leader_gap = seen.leader->gap;
  }
}

Commands StepCore::step(const StepObservation& seen) {
  explain_previous_row(seen);
  PendingStep& p = pending_.emplace();
  p.now = observe(seen);
  const StepNow& now = p.now;
  p.behavior = behavior_.step({.now = now.sumo.time,
                               .ego = now.ego,
                               .accel = now.sumo.accel,
                               .backing = now.backing,
                               .departed = departed_,
                               .segment = now.segment,
                               .lateral_offset = now.lateral_offset,
                               .target_lane = target_lane_traffic(seen, now.ego.s_base)});
  if (now.segment) p.planned_offset = behavior_.planned_offset(*now.segment, now.ego.s_base, now.backing);
  const TurnSignalDecision decision = decider_.decide(route_, now.ego, p.behavior.behavior);
  p.blinker = {blinker_of(decision), decision.source};
  p.lights = light(now, seen);
  if (suts_.decider || suts_.light_judge) {
    // The systems under test decide on the same inputs; the reference's choices are kept beside theirs.
    SutStep in = sut_step(now, seen, p.behavior.behavior, decision.path_backward_length);
    if (suts_.decider) {
      p.reference = p.blinker;
      p.blinker = {suts_.decider->decide(in), RequestSource::Sut};
    }
    if (suts_.light_judge) judge_under_test(in, p.lights);
  }
  p.plan = speed_.plan({.s_front = now.ego.s_front,
                         .s_base = now.ego.s_base,
                         .speed = now.sumo.speed,
                         .accel = now.sumo.accel,
                         .backing = now.backing,
                         .moving_back = now.moving_back,
                         .off_plan = now.off_plan,
                         .lights = &p.lights.steps,
                         .stopping = p.lights.stopping,
                         .hold = &p.behavior.hold});
  return commands(p);
}

// The step as a system under test sees it (docs/decider.md "Each step"): the ego, the decider's window
// of route lanelets, the behaviour modules' merged request, SUMO's mask for a traci decider.
SutStep StepCore::sut_step(const StepNow& now, const StepObservation& seen, const TurnSignalInfo& request,
                           double path_backward_length) const {
  SutStep in;
  in.time = now.sumo.time;
  const Lanelet& lanelet = route_.at(place_.index);
  const double yaw = lanelet.shape.heading_at(now.ego.s_front - lanelet.s_start);
  in.ego = {now.sumo.x, now.sumo.y, yaw, now.ego.speed, now.sumo.accel, now.ego.s_front, now.ego.s_base};
  in.window = route_.window(now.ego.s_base - path_backward_length,
                            now.ego.s_base + scenario_.run_params.decider.forward_path_length);
  in.request = request;
  in.sumo_signals = seen.signals;
  in.ego_parameters = seen.ego_parameters;
  return in;
}

// A light judge under test answers for every judged light of the window; its answer replaces the
// reference's decision (kept beside it) and the planner executes it as its own: a stop brings the
// front to the stop point (the stop line - stop_margin), a go plans no stop.
void StepCore::judge_under_test(SutStep& in, StepLights& lights) {
  // The SUT's decision replaces the reference's (kept beside it); a stop's point is the reference's,
  // but within stop_margin of the line it is where the front is (as the reference's restart
  // suppression does): never a brake to a point already passed.
  const auto decide = [this](LightStep& l, bool stop) {
    l.reference_decision = l.result.decision;
    l.result.decision = stop ? JudgeDecision::Stop : JudgeDecision::Pass;
    l.result.zone = JudgeZone::None;
    l.result.stop_point_distance.reset();
    if (stop) l.result.stop_point_distance = std::max(0.0, l.front_to_stop_line - judge_params_.stop_margin);
  };
  std::vector<LightStep*> judged;
  for (LightStep& l : lights.steps) {
    if (!l.judged) continue;
    if (l.front_to_stop_line <= 0.0) {  // its line is behind the front: passed, nothing to ask
      decide(l, false);
      continue;
    }
    judged.push_back(&l);
    in.lights.push_back({l.light->tls_id, l.light->link_index, l.light->route_index, l.light->s_stop_line,
                         l.front_to_stop_line, l.delivered, l.elements, l.result.v2i_time_to_red});
  }
  if (!judged.empty()) {
    const std::vector<SutLightAnswer> answers = suts_.light_judge->judge(in);
    for (std::size_t i = 0; i < judged.size(); ++i) {
      decide(*judged[i], answers[i].stop);
      judged[i]->sut_reason = cleaned_reason(answers[i].reason);
    }
  }
  choose_stopping_and_shown(lights);  // also when only passed lights were decided here
}

// The light the ego brakes for: the nearest stop requested; the light the row describes: that one,
// else the nearest.
void choose_stopping_and_shown(StepLights& lights) {
  lights.stopping = nullptr;
  for (const LightStep& l : lights.steps)
    if (l.result.stop_point_distance &&
        (!lights.stopping || *l.result.stop_point_distance < *lights.stopping->result.stop_point_distance))
      lights.stopping = &l;
  lights.shown = lights.stopping ? lights.stopping : (lights.steps.empty() ? nullptr : &lights.steps.front());
}

// light: every judge in the window (docs/behaviour.md §L); the ego brakes for the nearest stop requested by any
// of them, and the timeline describes that light, else the nearest one.
StepLights StepCore::light(const StepNow& now, const StepObservation& seen) {
  StepLights out;
  out.steps = lights_.step(now.sumo.time, now.ego.s_front, now.sumo.speed, now.sumo.accel, seen);
  choose_stopping_and_shown(out);
  // SUMO's right of way would hold the ego at a red line on its own (docs/behaviour.md §S4, measured): while
  // the next junction is a light showing the ego red or yellow, the judge alone decides there.
  out.sumo_right_of_way = !light_decides_next_junction(route_, now.ego.s_front, out.steps);
  return out;
}
// The commands: SUMO's modes (right of way, lane limits, emergency braking), the blinker bits and the
// speed (re-sent every step, docs/behaviour.md §S4), the lateral plan's offset where base_link will be
// after the step (normal lanes of the plan's edge only), the back-up.
Commands StepCore::commands(const PendingStep& step) {
  const StepNow& now = step.now;
  Commands c;
  c.right_of_way = step.lights.sumo_right_of_way;
  c.lane_limits = step.plan.sumo_lane_limits;
  c.emergency_braking = step.plan.emergency_braking;
  c.signal_mask = signal_mask(step.blinker.blinker);
  c.write_signals = !(suts_.decider && suts_.decider->reads_sumo_signals());
  c.speed = step.plan.speed;
  if (now.segment)
    c.lateral = LateralCommand{
        behavior_.planned_offset(*now.segment, now.ego.s_base + step.plan.speed * dt_, now.backing),
        now.segment->reference_lane};
  if (now.moving_back) {
    c.move_back = std::min(kBackwardSpeed * dt_, lateral_.backward - backed_up_);
    backed_up_ += c.move_back;
  }
  return c;
}

// record: one timeline row, with the mask SUMO showed while executing the decision; the next light's
// state as observed with the row; events on change; stops and red crossings; every light's own entry.
bool StepCore::record(const StepObservation& seen, const StepFeedback& feedback) {
  const PendingStep& p = *pending_;
  const StepNow& now = p.now;
  TimelineRow row = timeline_row(now.sumo, now.ego, now.lateral_offset, p.planned_offset, p.blinker.blinker,
                                 p.blinker.source, p.lights.shown, p.plan.stop_level);
  row.sumo_signals = feedback.signals;  // -1 once the ego arrived
  row.planned_speed = p.plan.speed;
  row.speed_limited_by = p.plan.limited_by;
  if (p.reference) {
    row.ref_blinker = p.reference->blinker;
    row.ref_blinker_source = p.reference->source;
  }
  if (p.lights.shown && p.lights.shown->reference_decision) {
    row.ref_tl_decision = p.lights.shown->reference_decision;
    row.tl_reason = p.lights.shown->sut_reason;
  }
  if (!p.lights.shown)
    if (const sumo::ApproachLight* next = lights_.next_light())  // beyond the horizon
      if (const LightReading* reading = seen.light(next->tls_id)) show_next_light(row, *next, reading->state);
  events_.record(row, p.behavior.transitions, record_);
  outcomes_.observe(row, p.lights.steps, p.lights.stopping, seen.leader, route_, record_);
  log_lights(p.lights.steps, record_);
  record_.rows.push_back(std::move(row));
  return ended(seen, feedback, p.plan);
}

// end: the ego arrived, the stuck rule holds, or the run's time is over (step/stuck_watch).
bool StepCore::ended(const StepObservation& seen, const StepFeedback& feedback, const SpeedPlan& plan) {
  if (!feedback.alive) {
    record_.arrived = true;
    return true;
  }
  const TimelineRow& last = record_.rows.back();
  if (stuck_.observe(last.time, last.speed, plan.held_by, plan.queued)) return end_not_arrived("stuck", seen.leader);
  if (feedback.time >= end_time_ - 1e-9) return end_not_arrived("duration", seen.leader);
  return false;
}

bool StepCore::end_not_arrived(const std::string& reason, const std::optional<LeaderInfo>& leader) {
  record_.not_arrived = not_arrived(reason, scenario_.duration, record_.rows.back(), stuck_, leader, route_);
  plan_watch_.explain(*record_.not_arrived, record_);
  return true;
}

RunRecord StepCore::finish(int collisions) {
  if (suts_.decider) suts_.decider->finish();
  if (suts_.light_judge) suts_.light_judge->finish();
  record_.collisions = collisions;
  record_.lane_changes = behavior_.lane_change_records();
  record_.maneuver_lines = maneuver_lines(behavior_.plan(), record_.lane_changes,
                                          scenario_.run_params.decider.turn_signal_shift_length_threshold);
  return std::move(record_);
}

}  // namespace signalsim
