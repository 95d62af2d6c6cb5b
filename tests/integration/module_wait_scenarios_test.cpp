// The behaviour modules' waits end to end on the real libsumo (docs/behaviour.md §T8.2): an avoidance
// waiting for approval at its wait point under each candidate_path_turn_signal policy (the bundled
// avoidance_candidate_* and avoidance_stop_on_approval, approval 12 s after the module's first step),
// and a pull out waiting at its start before engagement and for prepare_time_before_start after
// (pull_out_prepare_before_start, pull_out_centerline_engage). Each step's blinker is checked against
// the rule at that step, and the ego's rest and departure against the clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "maneuver_run.hpp"

namespace signalsim {
namespace {

using test::ManeuverRun;
using test::s_base;

constexpr double kApprovalDelay = 12.0;  // maneuvers[].avoid.approval_delay of the four scenarios [s]
constexpr double kHold = 3.0;            // turn_signal_on_approval_hold_duration [s]
constexpr double kStopped = 0.3;         // isVehicleStopped [m/s]
constexpr double kStep = 0.1;

const LateralSegment& avoidance_of(const ManeuverRun& r) {
  const LateralSegment& seg = r.lateral.segments.front();
  EXPECT_EQ(seg.kind, LateralKind::Avoidance);
  return seg;
}

// The index of the first row at or after time t.
std::size_t row_at(const ManeuverRun& r, double t) {
  const auto& rows = r.record.rows;
  const auto it = std::find_if(rows.begin(), rows.end(), [&](const TimelineRow& row) { return row.time >= t - 1e-6; });
  EXPECT_NE(it, rows.end()) << "no row at t=" << t;
  return static_cast<std::size_t>(it - rows.begin());
}

// §T8.1 on for the shift out: the front within max(3 v, 10 m) of its start.
bool within_prep(const TimelineRow& row, const ShiftLine& line) {
  return line.s_start - row.s_front <= std::max(row.speed * 3.0, 10.0);
}

// While waiting (rows before `approval`): the ego keeps its lane, brakes to rest with base_link at the
// wait point (stop_buffer, 1 m, before the shift starts) and stands there; the blinker per `expected`.
template <typename Expected>
void expect_wait(const ManeuverRun& r, std::size_t approval, Expected expected) {
  const LateralSegment& seg = avoidance_of(r);
  EXPECT_NEAR(seg.avoidance.wait_point, seg.plan.lines().front().s_start - 1.0, 1e-9);
  const auto& rows = r.record.rows;
  ASSERT_GT(approval, 0u);
  for (std::size_t i = 0; i < approval; ++i) {
    EXPECT_NEAR(*rows[i].planned_offset, 0.0, 1e-12) << "t=" << rows[i].time;
    EXPECT_EQ(rows[i].blinker, expected(rows[i])) << "t=" << rows[i].time << " s_front " << rows[i].s_front;
  }
  const TimelineRow& before = rows[approval - 1];
  EXPECT_NEAR(before.speed, 0.0, 1e-3) << "at rest when approved";
  EXPECT_NEAR(s_base(r, before), seg.avoidance.wait_point, 0.05);
}

// From `from` on: the avoidance as approved at once (avoidance_left's rules): the left blinker of
// the shift out, the ego at rest leaving no earlier than `departure_row`.
void expect_drives_off(const ManeuverRun& r, std::size_t from, std::size_t departure_row) {
  const auto& rows = r.record.rows;
  for (std::size_t i = from; i <= departure_row; ++i) {
    EXPECT_EQ(rows[i].blinker, Blinker::Left) << "t=" << rows[i].time;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::Avoidance);
    EXPECT_NEAR(rows[i].speed, 0.0, 1e-3) << "t=" << rows[i].time;
  }
  EXPECT_GT(rows[departure_row + 1].speed, 0.0) << "departs the step after t=" << rows[departure_row].time;
  EXPECT_TRUE(r.record.arrived);
  EXPECT_EQ(r.record.collisions, 0);
  for (const TimelineRow& row : rows)
    if (row.planned_offset) {
      EXPECT_NEAR(row.lateral_offset, *row.planned_offset, 0.2) << "t=" << row.time;
    }
}

TEST(AvoidanceWaitScenario, NoneNoBlinkerWhileWaitingThenLeftFromApproval) {
  const ManeuverRun r = test::run_bundled("avoidance_candidate_none");
  const std::size_t approval = row_at(r, r.record.rows.front().time + kApprovalDelay);
  expect_wait(r, approval, [](const TimelineRow&) { return Blinker::None; });
  expect_drives_off(r, approval, approval);
}

TEST(AvoidanceWaitScenario, StoppedCandidateLeftOnceSlowerThanPointThreeMetresPerSecond) {
  const ManeuverRun r = test::run_bundled("avoidance_candidate_stopped");
  const std::size_t approval = row_at(r, r.record.rows.front().time + kApprovalDelay);
  expect_wait(r, approval, [](const TimelineRow& row) {
    return std::abs(row.speed) < kStopped ? Blinker::Left : Blinker::None;
  });
  expect_drives_off(r, approval, approval);
}

TEST(AvoidanceWaitScenario, AllCandidateLeftWhileStillRollingWithinThePrepDistance) {
  const ManeuverRun r = test::run_bundled("avoidance_candidate_all");
  const ShiftLine& out = avoidance_of(r).plan.lines().front();
  const std::size_t approval = row_at(r, r.record.rows.front().time + kApprovalDelay);
  expect_wait(r, approval, [&](const TimelineRow& row) { return within_prep(row, out) ? Blinker::Left : Blinker::None; });
  const auto first_left = std::find_if(r.record.rows.begin(), r.record.rows.end(),
                                       [](const TimelineRow& row) { return row.blinker == Blinker::Left; });
  EXPECT_GT(first_left->speed, 1.0) << "on while still rolling toward the wait point";
  expect_drives_off(r, approval, approval);
}

TEST(AvoidanceWaitScenario, StopOnApprovalStandsThreeSecondsWithTheBlinkerThenAvoids) {
  const ManeuverRun r = test::run_bundled("avoidance_stop_on_approval");
  const std::size_t approval = row_at(r, r.record.rows.front().time + kApprovalDelay);
  expect_wait(r, approval, [](const TimelineRow&) { return Blinker::None; });
  // Held from the approval step until 3.0 s after it (>=): the step at +3.0 s commands the departure.
  const std::size_t release = row_at(r, r.record.rows[approval].time + kHold);
  EXPECT_EQ(release - approval, static_cast<std::size_t>(std::lround(kHold / kStep)));
  expect_drives_off(r, approval, release);
}

TEST(AvoidanceWaitScenario, ApprovedAtOnceNeitherStopsNorChangesTheBlinker) {
  // Without a delay every policy is avoidance_left: the same rows, blinker, speed and offset, step by step.
  const ManeuverRun left = test::run_bundled("avoidance_left");
  for (const char* name : {"avoidance_candidate_none", "avoidance_candidate_all", "avoidance_stop_on_approval"}) {
    const ManeuverRun r = test::run_bundled(name, {"maneuvers=[{avoid: {obstacle: parked, clearance: 1.0}}]"});
    ASSERT_EQ(r.record.rows.size(), left.record.rows.size()) << name;
    for (std::size_t i = 0; i < r.record.rows.size(); ++i) {
      EXPECT_EQ(r.record.rows[i].blinker, left.record.rows[i].blinker) << name << " t=" << r.record.rows[i].time;
      EXPECT_EQ(r.record.rows[i].speed, left.record.rows[i].speed) << name << " t=" << r.record.rows[i].time;
      EXPECT_EQ(r.record.rows[i].lateral_offset, left.record.rows[i].lateral_offset) << name;
    }
  }
}

// ---- Pull out: engagement and prepare_time_before_start ------------------------------------------------

// Rows before `depart`: at rest at the depart position, blinker `b` from the pull out; the row at
// `depart` (its step commands the start) still at rest, the next one moving.
void expect_waits_at_start(const ManeuverRun& r, std::size_t depart, Blinker b) {
  const auto& rows = r.record.rows;
  for (std::size_t i = 0; i <= depart; ++i) {
    EXPECT_NEAR(rows[i].speed, 0.0, 1e-9) << "t=" << rows[i].time;
    EXPECT_NEAR(rows[i].s_front, r.scenario.ego.depart_pos, 1e-6) << "t=" << rows[i].time;
  }
  for (std::size_t i = 0; i < depart; ++i) {
    EXPECT_EQ(rows[i].blinker, b) << "t=" << rows[i].time;
    EXPECT_EQ(rows[i].blinker_source, RequestSource::PullOut);
  }
  EXPECT_GT(rows[depart + 1].speed, 0.0);
  EXPECT_TRUE(r.record.arrived);
}

TEST(PullOutWaitScenario, WaitsPrepareTimeWithTheLeftBlinkerThenDeparts) {
  const ManeuverRun r = test::run_bundled("pull_out_prepare_before_start");
  // Engaged at the first step (t0): held while t - t0 < 2.0 s; the step at t0 + 2.0 commands the start.
  const std::size_t depart = row_at(r, r.record.rows.front().time + 2.0);
  EXPECT_EQ(depart, 20u);
  expect_waits_at_start(r, depart, Blinker::Left);
  EXPECT_EQ(r.record.rows[depart].blinker, Blinker::Left);
  // Without the wait the same pull out departs at once.
  const ManeuverRun at_once = test::run_bundled("pull_out_prepare_before_start", {"prepare_time_before_start=0"});
  EXPECT_GT(at_once.record.rows[1].speed, 0.0);
}

TEST(PullOutWaitScenario, CentreLineStartForcesItsBlinkerBeforeEngagementAndForThePrepareTime) {
  const ManeuverRun r = test::run_bundled("pull_out_centerline_engage");
  const double t0 = r.record.rows.front().time;
  // Not engaged for 1 s, then engaged for 2 s: turn_signal_on_centerline_start (LEFT) all along.
  const std::size_t engage = row_at(r, t0 + 1.0);
  const std::size_t depart = row_at(r, t0 + 3.0);
  EXPECT_EQ(engage, 10u);
  expect_waits_at_start(r, depart, Blinker::Left);
  // At t0 + 3.0 the forced blinker ends and the ego starts; the generator asks for none (the front
  // corner, 0.4 m right of the centre, is within 1.3 m of the far bound, §T8.1).
  const auto& rows = r.record.rows;
  for (std::size_t i = depart; i < rows.size(); ++i) EXPECT_EQ(rows[i].blinker, Blinker::None) << "t=" << rows[i].time;
  // Without a prepare time the blinker is forced only while the ego is not engaged yet.
  const ManeuverRun unengaged = test::run_bundled("pull_out_centerline_engage", {"prepare_time_before_start=0"});
  const auto& u = unengaged.record.rows;
  for (std::size_t i = 0; i < engage; ++i) EXPECT_EQ(u[i].blinker, Blinker::Left) << "t=" << u[i].time;
  EXPECT_EQ(u[engage].blinker, Blinker::None);
  EXPECT_NEAR(u[engage].speed, 0.0, 1e-9);
  EXPECT_GT(u[engage + 1].speed, 0.0);
}

}  // namespace
}  // namespace signalsim
