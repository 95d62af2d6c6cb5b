// Lateral maneuvers end to end on the real libsumo: the bundled lane-change scenarios run
// through run_scenario, and each step is checked against docs/behaviour.md §T8.2 (lane change, signalsim
// activation: on once the front is within max(v * turn_signal_search_time,
// turn_signal_minimum_search_distance) of the lane-changing start; off once base_link passes the
// lane-changing end) and against the lateral plan (measured offset within 0.2 m of the plan).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "maneuver_run.hpp"
#include "report/expectations.hpp"
#include "report/metrics.hpp"
#include "scenario/input_error.hpp"

namespace signalsim {
namespace {

constexpr double kSearchTime = 3.0;          // turn_signal_search_time
constexpr double kMinSearchDistance = 10.0;  // turn_signal_minimum_search_distance
constexpr double kTolerance = 0.2;           // m, lateral tracking
constexpr double kLaneWidth = 3.2;           // cross.net.xml lanes

using test::ManeuverRun;
using test::s_base;

ManeuverRun run(const std::string& name) { return test::run_bundled(name); }

// Every step with a plan: measured within 0.2 m of it; the plan starts on the depart lane's offset
// and ends on the planned lane's centre; the lane change is never a jump.
void expect_tracks_plan(const ManeuverRun& r, double start_offset) {
  ASSERT_TRUE(r.lateral.active());
  int steps = 0;
  std::optional<double> previous;
  for (const TimelineRow& row : r.record.rows) {
    if (!row.planned_offset) continue;
    ++steps;
    EXPECT_NEAR(row.lateral_offset, *row.planned_offset, kTolerance) << "t=" << row.time;
    if (previous) {
      EXPECT_LT(std::abs(row.lateral_offset - *previous), 0.5) << "a jump at t=" << row.time;
    }
    previous = row.lateral_offset;
  }
  EXPECT_GT(steps, 100);
  const auto first = std::find_if(r.record.rows.begin(), r.record.rows.end(),
                                  [](const TimelineRow& row) { return row.planned_offset.has_value(); });
  EXPECT_NEAR(*first->planned_offset, start_offset, 1e-9);
  EXPECT_NEAR(first->lateral_offset, start_offset, 0.01);
  EXPECT_NEAR(r.lateral.segments.front().plan.lines().back().shift_end, 0.0, 1e-12);
}

// The first step (index) where the blinker is `b` from `source`, or -1.
long first_step(const ManeuverRun& r, Blinker b, RequestSource source, std::size_t from = 0) {
  for (std::size_t i = from; i < r.record.rows.size(); ++i)
    if (r.record.rows[i].blinker == b && r.record.rows[i].blinker_source == source) return static_cast<long>(i);
  return -1;
}

// The line the ego executed for lane change `k` (fixed at approval), from the run record.
ShiftLine executed_line(const ManeuverRun& r, std::size_t k = 0) {
  const LaneChangeRecord& lc = r.record.lane_changes.at(k);
  EXPECT_EQ(lc.phase, "done");
  return {lc.start.value(), lc.end.value(), -lc.shift, 0.0};
}

// docs/behaviour.md §T8.2 prepare segment: approved at `approval_time` with the module's blinker on since
// `blinker_on_time`, the lateral motion starts max(4 s - blinker-on time, 2 s) of driving after
// base_link's approval position (never before the maneuver's earliest start, never after its latest start), and
// the planned offset holds the original lane until then.
void expect_prepare_rule(const ManeuverRun& r, std::size_t k = 0) {
  const LaneChangeRecord& lc = r.record.lane_changes.at(k);
  const LateralSegment* seg = r.lateral.on_edge(lc.edge);
  ASSERT_NE(seg, nullptr);
  ASSERT_TRUE(lc.approval_time && lc.blinker_on_time && lc.prepare_duration && lc.start);
  const double on_time = *lc.approval_time - *lc.blinker_on_time;
  EXPECT_GE(on_time, seg->lane_change.approval_delay - 1e-9);
  const auto at_approval = std::find_if(r.record.rows.begin(), r.record.rows.end(), [&](const TimelineRow& row) {
    return std::abs(row.time - *lc.approval_time) < 1e-6;
  });
  ASSERT_NE(at_approval, r.record.rows.end());
  // Below min_lane_changing_velocity (2.78 m/s) the floor is the time to reach it at 1 m/s^2.
  const double floor = at_approval->speed < 2.78 ? std::max(2.78 - at_approval->speed, 2.0) : 2.0;
  EXPECT_NEAR(*lc.prepare_duration, std::max(4.0 - on_time, floor), 1e-9);
  EXPECT_NEAR(*lc.approval_s_base, s_base(r, *at_approval), 1e-9);
  // Driven in the prepare time from the approval step's speed, at its acceleration when not braking,
  // at 1 m/s^2 (max_longitudinal_acc) below 2.78 m/s (prepare_distance is unit-tested).
  const double accel = at_approval->speed < 2.78 ? 1.0 : std::max(at_approval->accel, 0.0);
  const double prepared = *lc.approval_s_base + LaneChangeExecution::prepare_distance(
                                                    at_approval->speed, accel, r.scenario.ego.max_speed,
                                                    *lc.prepare_duration);
  const double expected = std::min(std::max(seg->lane_change.earliest_start, prepared), seg->lane_change.latest_start);
  EXPECT_NEAR(*lc.start, expected, 1e-9);
  EXPECT_NEAR(*lc.end - *lc.start, seg->lane_change.length, 1e-9);
  // The first step with the module's blinker on is the module's timestamp.
  const auto first_on = std::find_if(r.record.rows.begin(), r.record.rows.end(), [&](const TimelineRow& row) {
    return row.blinker_source == RequestSource::LaneChange && row.edge != "" && row.time >= *lc.blinker_on_time - 1e-6;
  });
  ASSERT_NE(first_on, r.record.rows.end());
  EXPECT_NEAR(first_on->time, *lc.blinker_on_time, 1e-6);
  // The original lane until the lateral motion starts.
  for (const TimelineRow& row : r.record.rows)
    if (row.planned_offset && row.edge == lc.edge && s_base(r, row) <= *lc.start) {
      EXPECT_NEAR(*row.planned_offset, -lc.shift, 1e-9) << "s_front " << row.s_front;
    }
}

// The lane-change blinker turns on exactly at the first step with the front within the prep
// distance of the earliest start of the lateral motion, and stays on (from the lane change) until
// base_link passes the end of the executed lateral motion; returns the index of the first step
// after it.
std::size_t expect_lane_change_stretch(const ManeuverRun& r, Blinker b, std::size_t k = 0, std::size_t from = 0) {
  const LateralSegment* seg = r.lateral.on_edge(r.record.lane_changes.at(k).edge);
  const ShiftLine line = executed_line(r, k);
  expect_prepare_rule(r, k);
  const auto& rows = r.record.rows;
  std::size_t i = from;
  for (; i < rows.size(); ++i) {
    const double prep = std::max(rows[i].speed * kSearchTime, kMinSearchDistance);
    if (seg->lane_change.earliest_start - rows[i].s_front <= prep) break;
    EXPECT_EQ(rows[i].blinker, Blinker::None) << "too early at s_front " << rows[i].s_front;
  }
  if (i >= rows.size()) {
    ADD_FAILURE() << "the lane change never came within reach";
    return i;
  }
  EXPECT_GT(i, from) << "the scenario should start out of reach";
  for (; i < rows.size() && s_base(r, rows[i]) <= line.s_end; ++i) {
    EXPECT_EQ(rows[i].blinker, b) << "s_front " << rows[i].s_front;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::LaneChange) << "s_front " << rows[i].s_front;
  }
  return i;
}

TEST(ManeuverScenario, LaneChangeRightAlone) {
  const ManeuverRun r = run("lane_change_right");
  ASSERT_TRUE(r.record.arrived);
  expect_tracks_plan(r, kLaneWidth);  // departs on in_S_1, one lane left of the planned in_S_0
  const std::size_t after = expect_lane_change_stretch(r, Blinker::Right);
  for (std::size_t i = after; i < r.record.rows.size(); ++i)
    EXPECT_EQ(r.record.rows[i].blinker, Blinker::None) << "s_front " << r.record.rows[i].s_front;
  // The lane change really happened: SUMO has the ego on in_S_0 at the end of in_S, and it went
  // straight through C on the route (no off-route step).
  std::string last_in_s;
  for (const TimelineRow& row : r.record.rows)
    if (row.edge == "in_S") last_in_s = row.lane;
  EXPECT_EQ(last_in_s, "in_S_0");
  EXPECT_EQ(r.record.off_route_steps, 0);
  EXPECT_EQ(r.record.collisions, 0);
}

TEST(ManeuverScenario, LaneChangeThenLeftTurnTheLeftTurnWaitsForTheLaneChangeEnd) {
  const ManeuverRun r = run("lane_change_then_left");
  ASSERT_TRUE(r.record.arrived);
  expect_tracks_plan(r, -kLaneWidth);  // departs on in_S_0, the left turn needs in_S_1
  const std::size_t after = expect_lane_change_stretch(r, Blinker::Left);
  // The intersection's own request would have started earlier: 3 v + 30 before the turn lane at
  // 189.60 (s_front ~118, see intersection_left.yaml); the lane-change path ends at base_link ~135.
  const long turn = first_step(r, Blinker::Left, RequestSource::Intersection);
  ASSERT_GE(turn, 0);
  EXPECT_EQ(static_cast<std::size_t>(turn), after) << "the left turn takes over right after the lane change";
  EXPECT_GT(s_base(r, r.record.rows[static_cast<std::size_t>(turn)]), executed_line(r).s_end);
  const double turn_search = r.record.rows[static_cast<std::size_t>(turn)].speed * kSearchTime + 30.0;
  EXPECT_LT(189.60 - r.record.rows[static_cast<std::size_t>(turn)].s_front, turn_search)
      << "the intersection request was already within reach when the lane change ended";
  for (std::size_t i = 0; i < r.record.rows.size(); ++i) EXPECT_NE(r.record.rows[i].blinker, Blinker::Right);
  EXPECT_EQ(r.record.off_route_steps, 0);
}

TEST(ManeuverScenario, EarlyLaneChangeThenLeftTurnTwoStretches) {
  const ManeuverRun r = run("lane_change_gap_then_left");
  ASSERT_TRUE(r.record.arrived);
  expect_tracks_plan(r, -kLaneWidth);
  const auto& rows = r.record.rows;
  // Departs already within reach (lane-changing start 20 m, front at 5 m): on from the first step.
  EXPECT_EQ(rows.front().blinker, Blinker::Left);
  EXPECT_EQ(rows.front().blinker_source, RequestSource::LaneChange);
  std::size_t i = 0;
  expect_prepare_rule(r);
  for (; i < rows.size() && s_base(r, rows[i]) <= executed_line(r).s_end; ++i)
    EXPECT_EQ(rows[i].blinker_source, RequestSource::LaneChange);
  const long turn = first_step(r, Blinker::Left, RequestSource::Intersection, i);
  ASSERT_GT(turn, static_cast<long>(i)) << "a gap without blinker between the two stretches";
  for (std::size_t k = i; k < static_cast<std::size_t>(turn); ++k) EXPECT_EQ(rows[k].blinker, Blinker::None);
  // The intersection request: on at the first step with the turn lane (189.60) within 3 v + 30.
  const TimelineRow& on = rows[static_cast<std::size_t>(turn)];
  const TimelineRow& before = rows[static_cast<std::size_t>(turn) - 1];
  EXPECT_LT(189.60 - on.s_front, on.speed * kSearchTime + 30.0);
  EXPECT_GE(189.60 - before.s_front, before.speed * kSearchTime + 30.0);
}

// ---- Lane changes on later edges --------------------------------------------------------------

// The last lane the ego was on while on `edge`.
std::string last_lane_on(const ManeuverRun& r, const std::string& edge) {
  std::string lane;
  for (const TimelineRow& row : r.record.rows)
    if (row.edge == edge) lane = row.lane;
  return lane;
}

TEST(ManeuverScenario, RequestedLaneChangeOnTheSecondEdge) {
  const ManeuverRun r = run("lane_change_second_edge");
  ASSERT_TRUE(r.record.arrived);
  ASSERT_EQ(r.lateral.segments.size(), 1u);
  const LateralSegment& seg = r.lateral.segments.front();
  EXPECT_EQ(seg.edge, "out_N");
  EXPECT_EQ(seg.reference_lane, "out_N_1");  // the requested lane is the planned lane of out_N
  expect_tracks_plan(r, -kLaneWidth);        // enters out_N on out_N_0 (straight from in_S_0)
  const std::size_t after = expect_lane_change_stretch(r, Blinker::Left);
  for (std::size_t i = after; i < r.record.rows.size(); ++i) EXPECT_EQ(r.record.rows[i].blinker, Blinker::None);
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_0");
  EXPECT_EQ(last_lane_on(r, "out_N"), "out_N_1");
  EXPECT_EQ(r.record.off_route_steps, 0);
  EXPECT_EQ(r.record.collisions, 0);
}

TEST(ManeuverScenario, LaneChangeTheRouteNeedsThenLeftTurn) {
  const ManeuverRun r = run("route_lane_change_then_left");
  ASSERT_TRUE(r.record.arrived);
  ASSERT_EQ(r.lateral.segments.size(), 1u);
  const LateralSegment& seg = r.lateral.segments.front();
  EXPECT_EQ(seg.edge, "in_W");
  EXPECT_EQ(seg.reference_lane, "in_W_1");
  const ShiftLine& line = seg.plan.lines().front();
  // The default length (in_W is long enough not to shrink it).
  EXPECT_NEAR(line.s_end - line.s_start, kDefaultLaneChangeLength, 1e-9);
  expect_tracks_plan(r, -kLaneWidth);
  // On before the ego reaches in_W (the module runs once its shift is ahead within the path).
  const std::size_t after = expect_lane_change_stretch(r, Blinker::Left);
  const long first_on = first_step(r, Blinker::Left, RequestSource::LaneChange);
  ASSERT_GE(first_on, 0);
  EXPECT_NE(r.record.rows[static_cast<std::size_t>(first_on)].edge, "in_W");
  const long turn = first_step(r, Blinker::Left, RequestSource::Intersection, after);
  ASSERT_GT(turn, static_cast<long>(after));
  for (const TimelineRow& row : r.record.rows) EXPECT_NE(row.blinker, Blinker::Right);
  EXPECT_EQ(last_lane_on(r, "w_far"), "w_far_0");
  EXPECT_EQ(last_lane_on(r, "in_W"), "in_W_1");
  EXPECT_EQ(r.record.off_route_steps, 0);
  EXPECT_EQ(r.record.collisions, 0);
}

TEST(ManeuverScenario, RequestedLaneChangeOnAnEdgeOffTheRouteIsRejected) {
  Scenario s = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/lane_change_second_edge.yaml");
  s.lane_changes.at(0).edge = "out_W";
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  EXPECT_THROW(plan_route(s, net), InputError);
}

// ---- Approval and the prepare segment (docs/behaviour.md §T8.2 calc_actual_prepare_duration) -------------

TEST(ManeuverScenario, ImmediateApprovalPreparesFourSeconds) {
  const ManeuverRun r = run("lane_change_right");
  const LaneChangeRecord& lc = r.record.lane_changes.at(0);
  EXPECT_NEAR(*lc.approval_time, *lc.blinker_on_time, 1e-9) << "approved in the step its blinker came on";
  EXPECT_NEAR(*lc.prepare_duration, 4.0, 1e-9);
  EXPECT_GT(*lc.start, r.lateral.segments.front().lane_change.earliest_start) << "4 s reach beyond `at`";
}

// The prepare durations are parameters (a sweep over them must change the run).
TEST(ManeuverScenario, MaxPrepareDurationIsAParameter) {
  ManeuverRun r;
  r.scenario = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/lane_change_right.yaml",
                             ScenarioOverrides{{"max_prepare_duration=3"}});
  const sumo::NetIndex net = sumo::NetIndex::load(r.scenario.net);
  const sumo::RoutePlan plan = plan_route(r.scenario, net);
  r.lateral = plan_lateral(r.scenario, plan, net);
  r.record = run_scenario(r.scenario, plan, net);
  EXPECT_NEAR(*r.record.lane_changes.at(0).prepare_duration, 3.0, 1e-9);
  const ManeuverRun defaults = run("lane_change_right");
  EXPECT_LT(*r.record.lane_changes.at(0).start, *defaults.record.lane_changes.at(0).start);
}

TEST(ManeuverScenario, LateApprovalShortensThePrepareSegment) {
  const ManeuverRun r = run("lane_change_approval_delay");
  ASSERT_TRUE(r.record.arrived);
  expect_tracks_plan(r, kLaneWidth);
  const std::size_t after = expect_lane_change_stretch(r, Blinker::Right);
  for (std::size_t i = after; i < r.record.rows.size(); ++i) EXPECT_EQ(r.record.rows[i].blinker, Blinker::None);
  const LaneChangeRecord& lc = r.record.lane_changes.at(0);
  // Approved at the first step 1.5 s after the blinker came on: prepare 4 - 1.5 = 2.5 s.
  EXPECT_NEAR(*lc.approval_time - *lc.blinker_on_time, 1.5, 1e-6);
  EXPECT_NEAR(*lc.prepare_duration, 2.5, 1e-6);
  // The same lane change approved at once starts its lateral motion earlier in s only because the
  // ego accelerates meanwhile; in time both start about 4 s after the blinker came on.
  const ManeuverRun immediate = run("lane_change_right");
  EXPECT_GT(*lc.start, *immediate.record.lane_changes.at(0).start);
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_0");
  EXPECT_EQ(r.record.collisions, 0);
}

TEST(ManeuverScenario, LaneChangeWaitsUntilTheTargetLaneIsClear) {
  const ManeuverRun r = run("lane_change_waits_for_gap");
  ASSERT_TRUE(r.record.arrived);
  expect_tracks_plan(r, kLaneWidth);
  expect_lane_change_stretch(r, Blinker::Right);
  const LaneChangeRecord& lc = r.record.lane_changes.at(0);
  // Waited with the blinker on more than 2 s: the minimum prepare segment.
  EXPECT_GT(*lc.approval_time - *lc.blinker_on_time, 2.0);
  EXPECT_NEAR(*lc.prepare_duration, 2.0, 1e-9);
  // Approved at the first step whose rear bumper is more than 10 m (rear gap) past the parked car's
  // front (70 m on in_S, route s 70): not one step earlier.
  const auto rear_gap = [&](const TimelineRow& row) { return row.s_front - r.scenario.ego.length - 10.0 - 70.0; };
  const auto& rows = r.record.rows;
  std::size_t k = 0;
  while (k < rows.size() && std::abs(rows[k].time - *lc.approval_time) > 1e-6) ++k;
  ASSERT_LT(k, rows.size());
  ASSERT_GT(k, 0u);
  EXPECT_GT(rear_gap(rows[k]), 0.0);
  EXPECT_LE(rear_gap(rows[k - 1]), 0.0);
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_0");
  EXPECT_EQ(r.record.collisions, 0);
}

TEST(ManeuverScenario, UnapprovedLaneChangeHoldsTheEgoAtItsLastStart) {
  const ManeuverRun r = run("lane_change_hold_until_approved");
  ASSERT_TRUE(r.record.arrived);
  expect_tracks_plan(r, kLaneWidth);
  expect_lane_change_stretch(r, Blinker::Right);
  const LaneChangeRecord& lc = r.record.lane_changes.at(0);
  const LateralSegment& seg = r.lateral.segments.front();
  EXPECT_NEAR(seg.lane_change.latest_start, 189.60 - r.scenario.ego.base_link_to_front - 50.0, 1e-6);
  // The hold point leaves room for the prepare segment from rest: 2.78 s at 1 m/s^2.
  const double hold = seg.lane_change.latest_start - 0.5 * 2.78 * 2.78;
  EXPECT_NEAR(seg.lane_change.hold_margin, 0.5 * 2.78 * 2.78, 1e-9);
  // At rest before approval, base_link within 5 cm short of the hold point, never beyond it.
  bool rested = false;
  for (const TimelineRow& row : r.record.rows) {
    if (row.time >= *lc.approval_time) break;
    EXPECT_LE(s_base(r, row), hold + 1e-6) << row.time;
    if (row.speed < 0.01 && row.time > 5.0) {
      rested = true;
      EXPECT_NEAR(s_base(r, row), hold, 0.05);
    }
  }
  EXPECT_TRUE(rested);
  EXPECT_NEAR(*lc.approval_time - *lc.blinker_on_time, 20.0, 1e-6);
  EXPECT_NEAR(*lc.prepare_duration, 2.78, 1e-9);
  // From rest the prepare segment is 3.86 m: the lateral motion starts at the latest start.
  EXPECT_NEAR(*lc.start, *lc.approval_s_base + 0.5 * 2.78 * 2.78, 1e-9);
  EXPECT_NEAR(*lc.start, seg.lane_change.latest_start, 0.05);
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_0");
  EXPECT_EQ(r.record.off_route_steps, 0);
}

// A lane change approved at once never brakes the ego, even when its earliest start is its latest.
TEST(ManeuverScenario, ImmediateApprovalDoesNotBrakeForTheHoldPoint) {
  ManeuverRun r;
  r.scenario = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/lane_change_right.yaml");
  r.scenario.lane_changes.at(0).at = 189.60 - r.scenario.ego.base_link_to_front - 50.0;
  const sumo::NetIndex net = sumo::NetIndex::load(r.scenario.net);
  const sumo::RoutePlan plan = plan_route(r.scenario, net);
  r.lateral = plan_lateral(r.scenario, plan, net);
  r.record = run_scenario(r.scenario, plan, net);
  const LaneChangeRecord& lc = r.record.lane_changes.at(0);
  ASSERT_EQ(lc.phase, "done");
  EXPECT_NEAR(*lc.approval_time, *lc.blinker_on_time, 1e-9);
  for (const TimelineRow& row : r.record.rows) {
    if (row.time > *lc.approval_time) break;
    EXPECT_GE(row.accel, -1e-9) << row.time;  // no braking (SUMO's arithmetic aside)
  }
  EXPECT_NEAR(*lc.start, r.lateral.segments.front().lane_change.latest_start, 1e-9) << "cut short to fit";
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_0");
}

// Departing too close to the last start to stop for it: the lane change is given up (missed), never
// started half; the ego brakes as hard as it must (emergency) and keeps its lane.
TEST(ManeuverScenario, ALaneChangeThatCanNoLongerEndOnItsEdgeIsMissed) {
  ManeuverRun r;
  r.scenario = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/lane_change_hold_until_approved.yaml");
  r.scenario.ego.depart_pos = 135.0;
  r.scenario.ego.depart_speed = 13.89;
  r.scenario.lane_changes.at(0).at = 131.3;
  r.scenario.lane_changes.at(0).approval_delay = 5.0;
  r.scenario.duration = 12.0;
  const sumo::NetIndex net = sumo::NetIndex::load(r.scenario.net);
  const sumo::RoutePlan plan = plan_route(r.scenario, net);
  r.lateral = plan_lateral(r.scenario, plan, net);
  r.record = run_scenario(r.scenario, plan, net);
  const LaneChangeRecord& lc = r.record.lane_changes.at(0);
  EXPECT_EQ(lc.phase, "missed");
  EXPECT_FALSE(lc.approval_time);
  EXPECT_FALSE(lc.start);
  ASSERT_TRUE(lc.blinker_on_time) << "its blinker did come on";
  bool missed_event = false;
  for (const TimelineEvent& e : r.record.events) missed_event = missed_event || (e.kind == "lane_change" && e.to == "missed");
  EXPECT_TRUE(missed_event);
  for (const TimelineRow& row : r.record.rows) {
    if (row.planned_offset) {
      EXPECT_NEAR(*row.planned_offset, kLaneWidth, 1e-9) << "no lateral motion at " << row.time;
    }
    EXPECT_NE(row.lane, "in_S_0");
  }
  // No maneuver section for a lane change that never happened, and the run fails on it.
  EXPECT_TRUE(r.record.maneuver_lines.empty());
  const auto results = evaluate_expectations(r.scenario, plan.map, r.record);
  ASSERT_FALSE(results.empty());
  EXPECT_EQ(results.back().description, "lane_change on in_S executed");
  EXPECT_FALSE(results.back().passed);
  EXPECT_EQ(run_status(results), RunStatus::Failed);
}

TEST(ManeuverScenario, TwoLaneChangesEachSignalAfresh) {
  const ManeuverRun r = run("two_lane_changes");
  ASSERT_TRUE(r.record.arrived);
  ASSERT_EQ(r.record.lane_changes.size(), 2u);
  EXPECT_EQ(r.record.lane_changes[0].edge, "in_S");
  EXPECT_EQ(r.record.lane_changes[1].edge, "out_N");
  const std::size_t after_first = expect_lane_change_stretch(r, Blinker::Right, 0);
  const std::size_t after_second = expect_lane_change_stretch(r, Blinker::Left, 1, after_first);
  for (std::size_t i = after_second; i < r.record.rows.size(); ++i) EXPECT_EQ(r.record.rows[i].blinker, Blinker::None);
  // The module was reset: the second blinker has its own timestamp, after the first lane change
  // was done, and a full 4 s prepare segment.
  double first_done = -1.0;
  for (const TimelineEvent& e : r.record.events)
    if (e.kind == "lane_change" && e.to == "done" && e.source == "in_S") first_done = e.time;
  ASSERT_GT(first_done, 0.0);
  EXPECT_GT(*r.record.lane_changes[1].blinker_on_time, first_done);
  EXPECT_NEAR(*r.record.lane_changes[1].prepare_duration, 4.0, 1e-9);
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_0");
  EXPECT_EQ(last_lane_on(r, "out_N"), "out_N_1");
  EXPECT_EQ(r.record.off_route_steps, 0);
  EXPECT_EQ(r.record.collisions, 0);
}

// The metrics measure each lateral motion like a turn: the blinker's lead over it is the prepare
// time (4 s when approved at once, and still 4 s when approved 1.5 s late; the wait plus 2 s after a
// long wait).
TEST(ManeuverScenario, LaneChangeMetricsLeadTimeIsThePrepareTime) {
  const auto lane_change_section = [](const ManeuverRun& r, std::size_t n) {
    const sumo::NetIndex net = sumo::NetIndex::load(r.scenario.net);
    const RunMetrics m = compute_metrics(r.scenario, plan_route(r.scenario, net).map, r.record);
    std::vector<SectionMetrics> found;
    for (const SectionMetrics& s : m.sections)
      if (s.section.kind == "lane_change") found.push_back(s);
    EXPECT_EQ(found.size(), n);
    return found;
  };
  const double step = 0.1;
  const ManeuverRun at_once = run("lane_change_right");
  const auto a = lane_change_section(at_once, 1);
  EXPECT_EQ(a.at(0).section.blinker, Blinker::Right);
  EXPECT_FALSE(*a.at(0).missed);
  EXPECT_NEAR(*a.at(0).lead_time, 4.0, step);
  const ManeuverRun late = run("lane_change_approval_delay");
  EXPECT_NEAR(*lane_change_section(late, 1).at(0).lead_time, 4.0, step);
  const ManeuverRun gap = run("lane_change_waits_for_gap");
  const LaneChangeRecord& lc = gap.record.lane_changes.at(0);
  // (It was braking for the hold point at approval and accelerates again: the 2 s segment planned
  // with the braking is driven a little faster.)
  EXPECT_NEAR(*lane_change_section(gap, 1).at(0).lead_time, *lc.approval_time - *lc.blinker_on_time + 2.0, 0.5);
  const auto two = lane_change_section(run("two_lane_changes"), 2);
  EXPECT_EQ(two.at(0).section.blinker, Blinker::Right);
  EXPECT_EQ(two.at(1).section.blinker, Blinker::Left);
  EXPECT_NEAR(*two.at(1).lead_time, 4.0, step);
}

TEST(ManeuverScenario, TwoLaneChangesOnTheFirstEdgeAreRejected) {
  Scenario s = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/two_lane_changes.yaml");
  s.lane_changes.at(1).edge = "in_S";
  s.lane_changes.at(1).to_lane = 0;
  const sumo::NetIndex net = sumo::NetIndex::load(s.net);
  EXPECT_THROW(plan_route(s, net), InputError);
}

// ---- Lane change inside a two-lane roundabout, before its exit -----------------------------------

// Common checks: entered on the inner lane, the shift on ring_EN to the outer lane, right from the
// lane change; returns the first step after the lane-change stretch.
std::size_t expect_ring_lane_change(const ManeuverRun& r) {
  EXPECT_TRUE(r.record.arrived);
  EXPECT_EQ(r.lateral.segments.size(), 1u);
  const LateralSegment& seg = r.lateral.segments.front();
  EXPECT_EQ(seg.edge, "ring_EN");
  EXPECT_EQ(seg.reference_lane, "ring_EN_0");
  expect_tracks_plan(r, kLaneWidth);  // from the inner lane (one lane left) to the outer one
  EXPECT_EQ(last_lane_on(r, "in_S"), "in_S_1");
  EXPECT_EQ(last_lane_on(r, "ring_SE"), "ring_SE_1");
  EXPECT_EQ(last_lane_on(r, "ring_EN"), "ring_EN_0");
  EXPECT_EQ(r.record.off_route_steps, 0);
  EXPECT_EQ(r.record.collisions, 0);
  for (const TimelineRow& row : r.record.rows) EXPECT_NE(row.blinker, Blinker::Left);
  return expect_lane_change_stretch(r, Blinker::Right);
}

TEST(ManeuverScenario, RoundaboutLaneChangeBeforeExitThenExitSignal) {
  const ManeuverRun r = run("roundabout_two_lane_change_before_exit");
  const std::size_t after = expect_ring_lane_change(r);
  const auto& rows = r.record.rows;
  // de: the exit request starts on the exit lanelet only, after a gap.
  const long exit = first_step(r, Blinker::Right, RequestSource::RoundaboutExit, after);
  ASSERT_GT(exit, static_cast<long>(after));
  for (std::size_t i = after; i < static_cast<std::size_t>(exit); ++i) EXPECT_EQ(rows[i].blinker, Blinker::None);
  EXPECT_EQ(rows[static_cast<std::size_t>(exit)].lane, ":RN_2_0");
}

TEST(ManeuverScenario, RoundaboutLaneChangeWinsOverTheExitSignalUntilItsPathEnds) {
  const ManeuverRun r = run("roundabout_two_lane_change_exit_from_previous");
  const std::size_t after = expect_ring_lane_change(r);
  const auto& rows = r.record.rows;
  ASSERT_LT(after, rows.size());
  // The exit request (from the previous exit) takes over at once: no gap.
  EXPECT_EQ(rows[after].blinker, Blinker::Right);
  EXPECT_EQ(rows[after].blinker_source, RequestSource::RoundaboutExit);
  EXPECT_EQ(rows[after].edge, "ring_EN");
  std::size_t i = after;
  for (; i < rows.size() && rows[i].blinker == Blinker::Right; ++i)
    EXPECT_EQ(rows[i].blinker_source, RequestSource::RoundaboutExit);
  ASSERT_LT(i, rows.size());
  EXPECT_EQ(rows[i].edge, "out_N");
}

// ---- Avoidance (docs/behaviour.md §T8.2 "Avoidance", §T8.1) ----------------------------------------------

constexpr double kMaxPrepareTime = 3.0;  // avoidance max_prepare_time
constexpr double kAvoidOffset = 0.9 + 1.0 + 0.9;  // half obstacle + clearance + half ego [m]

// The avoidance segment's two lines (shift out, shift back) and the tracking of the whole plan.
struct AvoidLines {
  ShiftLine out, back;
};
AvoidLines avoid_lines(const ManeuverRun& r, double side) {
  const LateralSegment& seg = r.lateral.segments.back();
  EXPECT_EQ(seg.kind, LateralKind::Avoidance);
  EXPECT_EQ(seg.plan.lines().size(), 2u);
  const AvoidLines lines{seg.plan.lines().front(), seg.plan.lines().back()};
  EXPECT_NEAR(lines.out.shift_end, side * kAvoidOffset, 1e-9);
  EXPECT_NEAR(lines.back.shift_start, side * kAvoidOffset, 1e-9);
  EXPECT_NEAR(lines.back.shift_end, 0.0, 1e-12);
  // The measured offset follows the plan; it really reaches the hold offset beside the obstacle.
  double widest = 0.0;
  for (const TimelineRow& row : r.record.rows) {
    if (!row.planned_offset) continue;
    EXPECT_NEAR(row.lateral_offset, *row.planned_offset, kTolerance) << "t=" << row.time;
    widest = std::max(widest, side * row.lateral_offset);
  }
  EXPECT_NEAR(widest, kAvoidOffset, 0.01);
  EXPECT_EQ(r.record.collisions, 0);
  EXPECT_EQ(r.record.off_route_steps, 0);
  return lines;
}

// §T8.1 on: the first step with the front within max(v * search_time, min distance) of `line`'s start.
bool within_prep(const TimelineRow& row, const ShiftLine& line) {
  return line.s_start - row.s_front <= std::max(row.speed * kSearchTime, kMinSearchDistance);
}

// §T8.2 target line: the return line once its start is within v * max_prepare_time of base_link
// (strict) and the shift out has started.
bool return_is_target(const ManeuverRun& r, const TimelineRow& row, const AvoidLines& l) {
  return l.out.s_start <= s_base(r, row) && l.back.s_start - s_base(r, row) < row.speed * kMaxPrepareTime;
}

TEST(ManeuverScenario, AvoidanceAloneShiftOutLeftReturnRight) {
  const ManeuverRun r = run("avoidance_left");
  ASSERT_TRUE(r.record.arrived);
  const AvoidLines l = avoid_lines(r, +1.0);
  const auto& rows = r.record.rows;
  std::size_t i = 0;
  for (; i < rows.size() && !within_prep(rows[i], l.out); ++i) EXPECT_EQ(rows[i].blinker, Blinker::None);
  ASSERT_GT(i, 0u);
  // Left (shift out) until the return line becomes the target, then right (return).
  for (; i < rows.size() && !return_is_target(r, rows[i], l); ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Left) << "s_front " << rows[i].s_front;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::Avoidance);
  }
  ASSERT_LT(i, rows.size());
  // Right until the remaining return is below turn_signal_remaining_shift_length_threshold (0.1 m):
  // then NONE and the line latched as ignored; nothing after that.
  for (; i < rows.size() && std::abs(rows[i].lateral_offset) >= 0.1; ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Right) << "s_front " << rows[i].s_front;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::Avoidance);
  }
  EXPECT_LT(s_base(r, rows[i]), l.back.s_end);
  for (std::size_t k = i + 1; k < rows.size(); ++k) EXPECT_EQ(rows[k].blinker, Blinker::None) << rows[k].s_front;
}

TEST(ManeuverScenario, AvoidanceBeforeLeftTurnReturnHandsOverToTheTurn) {
  const ManeuverRun r = run("avoidance_before_left_turn");
  ASSERT_TRUE(r.record.arrived);
  const AvoidLines l = avoid_lines(r, -1.0);  // on the right: in_S_1 is the leftmost lane
  const auto& rows = r.record.rows;
  std::size_t i = 0;
  for (; i < rows.size() && !within_prep(rows[i], l.out); ++i) EXPECT_EQ(rows[i].blinker, Blinker::None);
  for (; i < rows.size() && !return_is_target(r, rows[i], l); ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Right) << "s_front " << rows[i].s_front;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::Avoidance);
  }
  // The return (left) from the avoidance, then the left turn's own request, left all the way.
  const long turn = first_step(r, Blinker::Left, RequestSource::Intersection);
  ASSERT_GT(turn, static_cast<long>(i));
  for (; i < static_cast<std::size_t>(turn); ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Left) << "s_front " << rows[i].s_front;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::Avoidance);
  }
  // The turn takes over exactly when the remaining return drops below 0.1 m (the avoidance goes
  // NONE and latches), not where its own search distance begins.
  EXPECT_LT(std::abs(rows[static_cast<std::size_t>(turn)].lateral_offset), 0.1);
  EXPECT_GE(std::abs(rows[static_cast<std::size_t>(turn) - 1].lateral_offset), 0.1);
  for (const TimelineRow& row : rows) EXPECT_NE(row.blinker, Blinker::Hazard);
}

TEST(ManeuverScenario, AvoidanceAfterLeftTurnWaitsForTheTurnToEnd) {
  const ManeuverRun r = run("avoidance_after_left_turn");
  ASSERT_TRUE(r.record.arrived);
  const AvoidLines l = avoid_lines(r, -1.0);
  const auto& rows = r.record.rows;
  const long turn = first_step(r, Blinker::Left, RequestSource::Intersection);
  const long avoid = first_step(r, Blinker::Right, RequestSource::Avoidance);
  ASSERT_GE(turn, 0);
  ASSERT_GT(avoid, turn);
  // Left (the turn) without a gap up to the avoidance's right, which was already within reach the
  // step before: the turn won while base_link was still in junction C (it leaves at 208.95).
  for (long k = turn; k < avoid; ++k) EXPECT_EQ(rows[static_cast<std::size_t>(k)].blinker, Blinker::Left);
  const TimelineRow& before = rows[static_cast<std::size_t>(avoid) - 1];
  EXPECT_TRUE(within_prep(before, l.out)) << "the avoidance request existed before it won";
  EXPECT_LE(s_base(r, before), 208.95 + 0.01);
  EXPECT_GT(s_base(r, rows[static_cast<std::size_t>(avoid)]), 208.95);
  // Then left again for the return, from the avoidance.
  const long back = first_step(r, Blinker::Left, RequestSource::Avoidance, static_cast<std::size_t>(avoid));
  ASSERT_GT(back, avoid);
  EXPECT_TRUE(return_is_target(r, rows[static_cast<std::size_t>(back)], l));
}

// ---- Pull out and pull over (docs/behaviour.md §T8.2 start / goal planner) --------------------------------

constexpr double kRemainingShift = 0.1;  // turn_signal_remaining_shift_length_threshold
constexpr double kBoundThreshold = 1.3;  // turn_signal_remaining_distance_to_bound_threshold
constexpr double kHalfLane = 1.6, kHalfEgo = 0.9;

TEST(ManeuverScenario, PullOutLeftOffOnceTheFrontCornerNearsTheFarBound) {
  const ManeuverRun r = run("pull_out_left");
  ASSERT_TRUE(r.record.arrived);
  const ShiftLine& line = r.lateral.segments.front().plan.lines().front();
  EXPECT_NEAR(line.shift_start, -0.7, 1e-12);
  const auto& rows = r.record.rows;
  EXPECT_NEAR(rows.front().lateral_offset, -0.7, 0.01) << "departs at the road side";
  EXPECT_NEAR(rows.front().speed, 0.0, 1e-9);
  std::size_t i = 0;
  for (; i < rows.size() && rows[i].blinker == Blinker::Left; ++i) {
    EXPECT_EQ(rows[i].blinker_source, RequestSource::PullOut);
    EXPECT_NEAR(rows[i].lateral_offset, *rows[i].planned_offset, kTolerance);
  }
  ASSERT_GT(i, 0u) << "left from the first step";
  ASSERT_LT(i, rows.size());
  // Off: the left front corner (offset + half width, plus the yaw's share) within 1.3 m of the
  // left bound, while the shift is not yet complete; on before that.
  const auto corner_gap = [&](const TimelineRow& row) {
    const double yaw = std::atan(line.heading_at(s_base(r, row)));
    return kHalfLane - (row.lateral_offset + kHalfEgo * std::cos(yaw) + r.record.base_link_to_front * std::sin(yaw));
  };
  EXPECT_LT(corner_gap(rows[i]), kBoundThreshold + 0.01);
  EXPECT_GE(corner_gap(rows[i - 1]), kBoundThreshold - 0.01);
  EXPECT_LT(s_base(r, rows[i]), line.s_end);
  for (std::size_t k = i; k < rows.size(); ++k) EXPECT_EQ(rows[k].blinker, Blinker::None) << rows[k].s_front;
}

TEST(ManeuverScenario, PullOverRightSignalsFromSearchTimeBeforeThePathAndStopsAtTheGoal) {
  const ManeuverRun r = run("pull_over_right");
  const LateralSegment& seg = r.lateral.segments.front();
  ASSERT_EQ(seg.kind, LateralKind::PullOver);
  const ShiftLine& line = seg.plan.lines().front();
  const auto& rows = r.record.rows;
  std::size_t i = 0;
  for (; i < rows.size() && !within_prep(rows[i], line); ++i) EXPECT_EQ(rows[i].blinker, Blinker::None) << rows[i].s_front;
  ASSERT_GT(i, 0u);
  for (; i < rows.size() && std::abs(rows[i].lateral_offset - line.shift_end) >= kRemainingShift; ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Right) << "s_front " << rows[i].s_front;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::PullOver);
  }
  ASSERT_LT(i, rows.size());
  for (std::size_t k = i; k < rows.size(); ++k) EXPECT_EQ(rows[k].blinker, Blinker::None) << rows[k].s_front;
  // Stopped at the goal, at the road-side offset, the measured offset on the plan all the way.
  EXPECT_NEAR(rows.back().speed, 0.0, 1e-6);
  EXPECT_NEAR(s_base(r, rows.back()), seg.goal_s, 0.05);
  EXPECT_NEAR(rows.back().lateral_offset, -0.7, 0.01);
  for (const TimelineRow& row : rows) {
    if (row.planned_offset) {
      EXPECT_NEAR(row.lateral_offset, *row.planned_offset, kTolerance) << row.time;
    }
  }
  EXPECT_EQ(r.record.collisions, 0);
}

TEST(ManeuverScenario, PullOutBackingUpGivesHazardThenLeft) {
  const ManeuverRun r = run("pull_out_backward_hazard");
  ASSERT_TRUE(r.record.arrived);
  const auto& rows = r.record.rows;
  // Backing up 3 m at 1 m/s (emulated): hazard (docs/behaviour.md §T3.1, §T8.1 not driving forward) every step
  // with a negative speed, the front moving back 0.1 m per step, the road-side offset held.
  std::size_t i = 0;
  for (; i < rows.size() && rows[i].speed < 0.0; ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Hazard) << "t=" << rows[i].time;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::PullOut);
    EXPECT_EQ(rows[i].sumo_signals & sumo::kBlinkerMask, sumo::kBlinkerEmergency) << "SUMO shows the hazard bit";
    EXPECT_NEAR(rows[i].lateral_offset, -0.7, 0.01);
    if (i > 0) {
      EXPECT_NEAR(rows[i].s_front, rows[i - 1].s_front - 0.1, 1e-6);
    }
  }
  EXPECT_EQ(i, 30u);
  EXPECT_NEAR(rows[i].s_front, 12.0, 1e-6);
  // Then forward: the pull out's left blinker straight away, never right.
  EXPECT_EQ(rows[i].blinker, Blinker::Left);
  EXPECT_EQ(rows[i].blinker_source, RequestSource::PullOut);
  for (const TimelineRow& row : rows) {
    EXPECT_NE(row.blinker, Blinker::Right);
    if (row.planned_offset) {
      EXPECT_NEAR(row.lateral_offset, *row.planned_offset, kTolerance) << row.time;
    }
  }
}

// ---- Scenario checks before SUMO starts (InputError naming the key) ----------------------------

std::string input_error(const std::string& name, std::vector<std::string> set) {
  try {
    const Scenario scenario =
        load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml", ScenarioOverrides{set});
    const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
    plan_route(scenario, net);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ManeuverInput, RejectsWhatCannotBeDriven) {
  EXPECT_NE(input_error("lane_change_right", {"ego.depart_lane=2"}).find("ego.depart_lane"), std::string::npos);
  EXPECT_NE(input_error("lane_change_right", {"ego.depart_lane=0"}).find("departs on the planned lane"),
            std::string::npos);
  EXPECT_NE(input_error("lane_change_right", {"maneuvers=[{lane_change: {at: 40, length: 160}}]"})
                .find("must end while the front bumper is still on the edge"),
            std::string::npos);
  EXPECT_NE(input_error("lane_change_right", {"maneuvers=[{lane_change: {at: 0, length: 50}}]"}).find("behind"),
            std::string::npos);
  EXPECT_NE(input_error("lane_change_right", {"maneuvers=[{pull_sideways: {}}]"}).find("unknown maneuver"),
            std::string::npos);
  EXPECT_NE(input_error("avoidance_left", {"obstacles=[{id: parked, edge: in_S, lane: 1, pos: 120}]"})
                .find("not on the ego's planned lane"),
            std::string::npos);
  EXPECT_NE(input_error("avoidance_left", {"maneuvers=[{avoid: {obstacle: nobody}}]"}).find("no such obstacle"),
            std::string::npos);
  EXPECT_NE(input_error("avoidance_left", {"obstacles=[{id: parked, edge: in_S, lane: 0, pos: 30}]"})
                .find("must start and end"),
            std::string::npos);
  EXPECT_NE(input_error("avoidance_left", {"maneuvers=[{avoid: {obstacle: parked, side: up}}]"}).find("side"),
            std::string::npos);
  EXPECT_EQ(input_error("avoidance_left", {}), "");
  EXPECT_NE(input_error("pull_over_right", {"maneuvers=[{pull_over: {edge: out_N, pos: 20, offset: -0.7}}]"})
                .find("must start and end"),
            std::string::npos);
  EXPECT_NE(input_error("pull_over_right", {"maneuvers=[{pull_over: {edge: out_E, pos: 120, offset: -0.7}}]"})
                .find("not on the ego's route"),
            std::string::npos);
  EXPECT_NE(input_error("pull_out_backward_hazard", {"maneuvers=[{pull_out: {offset: -0.7, backward: 12}}]"})
                .find("back the ego off the start"),
            std::string::npos);
  EXPECT_NE(input_error("pull_out_left", {"ego.depart_lane=1"}).find("pull_out and a lane change"), std::string::npos);
  EXPECT_EQ(input_error("lane_change_right", {}), "");
}

}  // namespace
}  // namespace signalsim
