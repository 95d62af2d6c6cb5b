// The ride on the real libsumo (docs/behaviour.md §P): the ego arrives at a turn's limit within its
// decel and the ride's jerk, a taken-over vehicle inserted above its lane's limit brakes within its
// own decel, a light passed on yellow is crossed without speeding up, a run's timeline says what set
// each speed, and with a sumocfg the simulated time is the span from its begin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "net/net_index.hpp"
#include "report/summary_sections.hpp"
#include "scenario/scenario.hpp"
#include "scenario/take_over.hpp"
#include "sim/step_loop.hpp"
#include "step/route_planning.hpp"

namespace signalsim {
namespace {

std::string source(const std::string& relative) { return std::string(SIGNALSIM_SOURCE_DIR) + "/" + relative; }

struct Ride {
  Scenario scenario;
  sumo::NetIndex net;
  RunRecord record;
};

Ride ride(const std::string& path, const ScenarioOverrides& overrides = {}) {
  Ride r{load_scenario(source(path), overrides), {}, {}};
  resolve_route_file_ego(r.scenario);  // a taken-over vehicle's route is in the route files
  r.net = sumo::NetIndex::load(r.scenario.net);
  const sumo::RoutePlan plan = plan_route(r.scenario, r.net);
  r.record = run_scenario(r.scenario, plan, r.net);
  return r;
}

double max_decel(const RunRecord& r) {
  double worst = 0.0;
  for (const TimelineRow& row : r.rows) worst = std::max(worst, -row.accel);
  return worst;
}

double max_jerk(const RunRecord& r) {
  double worst = 0.0;
  for (std::size_t i = 1; i < r.rows.size(); ++i)
    worst = std::max(worst, std::abs(r.rows[i].accel - r.rows[i - 1].accel) / (r.rows[i].time - r.rows[i - 1].time));
  return worst;
}

// Every row whose front is on an internal lane drives at or below that lane's limit.
void expect_within_turn_limits(const Ride& r) {
  int turn_rows = 0;
  for (const TimelineRow& row : r.record.rows) {
    if (row.lane.empty() || row.lane[0] != ':') continue;
    ++turn_rows;
    EXPECT_LE(row.speed, r.net.lane(row.lane)->speed + 0.01) << "t=" << row.time << " on " << row.lane;
  }
  EXPECT_GT(turn_rows, 0);
}

TEST(Ride, ATurnIsEnteredAtItsLimitWithinTheDecelAndTheRidesJerk) {
  const Ride r = ride("scenarios/intersection_left.yaml");  // before: 9.475 m/s on the 9.26 m/s turn, -2.15 m/s^2
  ASSERT_TRUE(r.record.arrived);
  expect_within_turn_limits(r);
  EXPECT_LE(max_decel(r.record), r.scenario.ego.decel + 1e-6);
  EXPECT_LE(max_jerk(r.record), 1.0 + 1e-6) << "before: 21 m/s^3 where SUMO clamped the speed";
}

TEST(Ride, ATakenOverVehicleInsertedAboveItsLimitBrakesWithinItsOwnDecel) {
  const Ride r = ride("tests/data/user_sumo/depart_max.yaml");
  ASSERT_GT(r.record.rows.front().speed, 13.89) << "SUMO inserts it above the 13.89 m/s lane limit";
  EXPECT_LE(max_decel(r.record), r.scenario.ego.decel + 1e-6) << "before: -2.17 m/s^2 in its first step";
  EXPECT_LE(max_jerk(r.record), 1.0 + 1e-6);
  expect_within_turn_limits(r);
  EXPECT_TRUE(r.record.arrived);
}

TEST(Ride, ALightPassedOnYellowIsCrossedWithoutSpeedingUp) {
  // Accelerating out of the lane change's hold when the light turns yellow: the judge's pass assumes
  // the speed kept to the line; the acceleration is released (at the jerk: at most a^2 / 2J more).
  const Ride r = ride("scenarios/lane_change_hold_until_approved.yaml");
  const TimelineRow* first = nullptr;
  for (const TimelineRow& row : r.record.rows) {
    if (row.zone != JudgeZone::PassThroughYellow) continue;
    if (!first) first = &row;
    if (row.lane.rfind(':', 0) != 0) {
      EXPECT_EQ(row.speed_limited_by, "held_on_yellow") << "t=" << row.time;
    }
    const double release = first->accel * first->accel / 2.0;  // J = 1 m/s^3
    EXPECT_LE(row.speed, first->speed + release + 0.01) << "t=" << row.time << " (held: at most the jerk-limited release)";
  }
  ASSERT_NE(first, nullptr) << "the light turns yellow on the approach";
  EXPECT_GT(first->accel, 0.5) << "it was speeding up when the pass was decided";
  EXPECT_LE(max_decel(r.record), r.scenario.ego.decel + 1e-6);
}

TEST(Ride, TheTimelineSaysWhatSetTheSpeedAndWhatSumoDid) {
  const Ride r = ride("tests/data/user_sumo/take_over_flow.yaml");
  bool leader = false, stopped_for_light = false;
  for (const TimelineRow& row : r.record.rows) {
    ASSERT_TRUE(row.planned_speed.has_value());
    EXPECT_FALSE(row.speed_limited_by.empty()) << "t=" << row.time;
    if (row.sumo_limited_by == "leader") {
      leader = true;
      EXPECT_FALSE(row.leader.empty());
      ASSERT_TRUE(row.leader_gap.has_value());
      ASSERT_TRUE(row.sumo_speed.has_value());
      EXPECT_LT(*row.sumo_speed, *row.planned_speed - kSpeedShortfall);
    }
    stopped_for_light = stopped_for_light || row.speed_limited_by == "light_stop";
  }
  EXPECT_TRUE(leader) << "SUMO holds the taken-over vehicle behind its leader";
  const Ride lights = ride("scenarios/tl_red_stop_then_go.yaml");
  for (const TimelineRow& row : lights.record.rows) stopped_for_light = stopped_for_light || row.speed_limited_by == "light_stop";
  EXPECT_TRUE(stopped_for_light);
  EXPECT_FALSE(lights.record.rows.back().sumo_speed.has_value()) << "the last row has no step after it";
}

TEST(Ride, WithASumocfgTheSimulatedTimeIsTheSpanFromItsBegin) {
  const Ride r = ride("tests/data/user_sumo/take_over_late.yaml");
  ASSERT_EQ(r.scenario.sumo.begin, 3.0);
  const nlohmann::ordered_json counts = counts_json(r.record, r.scenario.sumo.begin);
  EXPECT_NEAR(counts["end_time"].get<double>(), r.record.rows.back().time, 1e-3) << "SUMO's clock";
  EXPECT_NEAR(counts["simulated_time"].get<double>(), r.record.rows.back().time - 3.0, 1e-3) << "the span from 3 s";
}

}  // namespace
}  // namespace signalsim
