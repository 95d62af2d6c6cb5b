// The SUMO-driven mode (`run --driver sumo`) on the real libsumo: the ego is inserted as
// for signalsim but SUMO drives it, and the timeline records what SUMO did on its own. Each fact
// checked here is SUMO's built-in behaviour as docs/behaviour.md §S5 describes it, measured: the blinker from
// 7 s x the lane speed (capped by the ego's maximum speed) before the end of the current lane, for
// the next junction only, kept through it; none while circulating a roundabout past an exit; the
// stop at a red light on its own; its own lane changes, located on the route's edge.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "report/metrics.hpp"
#include "scenario/scenario.hpp"
#include "sim/session_setup.hpp"
#include "sim/step_loop.hpp"
#include "step/sumo_driven_core.hpp"
#include "net/net_index.hpp"

namespace signalsim {
namespace {

constexpr double kBlinkerSeconds = 7.0;  // docs/behaviour.md §S5

struct Driven {
  Scenario scenario;
  sumo::RoutePlan plan;
  RunRecord record;
};

Driven drive_by_sumo(const std::string& name) {
  Driven d;
  const Scenario scenario = load_scenario(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml");
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  RunContext context;
  context.sumo_drives = true;
  StartedRun run = start_run(plan_run(scenario, net), net, context);
  d.record = drive(run, net);
  d.scenario = run.scenario;
  d.plan = std::move(run.plan);
  return d;
}

const Lanelet& lanelet(const Driven& d, const std::string& lane) {
  const auto i = d.plan.map.find_lane(lane);
  EXPECT_TRUE(i.has_value()) << lane << " is not on the route";
  return d.plan.map.at(i.value_or(0));
}

// SUMO's blinker threshold on a lane: 7 s x the speed the ego may drive there.
double threshold_on(const Driven& d, const Lanelet& l) {
  return kBlinkerSeconds * std::min(l.speed_limit, d.scenario.ego.max_speed);
}

// The first row showing `b`, or rows.size().
std::size_t first_with(const std::vector<TimelineRow>& rows, Blinker b) {
  return static_cast<std::size_t>(std::find_if(rows.begin(), rows.end(), [b](const TimelineRow& r) { return r.blinker == b; }) -
                                  rows.begin());
}

// Every row is SUMO's own blinker, decoded from the mask it showed.
void expect_rows_are_sumos(const RunRecord& record) {
  for (const TimelineRow& r : record.rows) {
    ASSERT_EQ(r.blinker, blinker_of_signals(r.sumo_signals)) << "t=" << r.time;
    ASSERT_EQ(r.blinker_source, r.blinker == Blinker::None ? RequestSource::None : RequestSource::Sumo);
    ASSERT_EQ(r.tl_decision, JudgeDecision::None) << "no judge runs when SUMO drives";
  }
}

// intersection_left: SUMO's left blinker comes on at the first step the front is within 7 s x 13.89
// m/s (97.2 m) of the end of in_S_1, stays on through junction C and goes off on out_W.
TEST(SumoDriven, LeftTurnBlinkerFromSevenSecondsBeforeTheApproachLaneEnd) {
  const Driven d = drive_by_sumo("intersection_left");
  const auto& rows = d.record.rows;
  ASSERT_TRUE(d.record.arrived);
  EXPECT_EQ(d.record.driver, Driver::Sumo);
  expect_rows_are_sumos(d.record);
  const Lanelet& approach = lanelet(d, "in_S_1");
  const double threshold = threshold_on(d, approach);
  EXPECT_NEAR(threshold, 97.23, 0.01);
  const std::size_t k = first_with(rows, Blinker::Left);
  ASSERT_LT(k, rows.size()) << "SUMO never showed its left blinker";
  ASSERT_GT(k, 0u);
  EXPECT_EQ(rows[k].lane, "in_S_1");
  EXPECT_LT(approach.s_end() - rows[k].s_front, threshold) << "on within 7 s x the speed limit of the lane end";
  EXPECT_GE(approach.s_end() - rows[k - 1].s_front, threshold) << "and not a step earlier";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const bool on_approach_or_junction = rows[i].lane == "in_S_1" || rows[i].edge.rfind(":C_", 0) == 0;
    const Blinker expected = i >= k && on_approach_or_junction ? Blinker::Left : Blinker::None;
    ASSERT_EQ(rows[i].blinker, expected) << "t=" << rows[i].time << " lane " << rows[i].lane;
  }
  EXPECT_TRUE(d.record.off_plan.empty());
  EXPECT_EQ(d.record.off_route_steps, 0);
  // The metrics read it like a signalsim run: the turn is served, lead ~ the threshold.
  const RunMetrics m = compute_metrics(d.scenario, d.plan.map, d.record);
  ASSERT_EQ(m.sections.size(), 1u);
  EXPECT_EQ(m.sections[0].missed, std::optional<bool>(false));
  EXPECT_GT(*m.sections[0].lead_distance, threshold - 13.89 * d.scenario.step_length);
  EXPECT_LE(*m.sections[0].lead_distance, threshold);
}

// roundabout_jp_exit2 (right-hand ring, entry and exit links 'r'): SUMO shows right 7 s x the limit
// before the entry and through it, nothing on the ring while passing exit E (link 's'), right again
// on the last ring lane (shorter than 7 s x 8.33 m/s, so from its start) and through the exit,
// nothing on out_N. Never left, so Japan's left exit signal is missed.
TEST(SumoDriven, RoundaboutBlinkerOnlyForTheNextLinkNeverWhilePassingAnExit) {
  const Driven d = drive_by_sumo("roundabout_jp_exit2");
  const auto& rows = d.record.rows;
  ASSERT_TRUE(d.record.arrived);
  expect_rows_are_sumos(d.record);
  const Lanelet& approach = lanelet(d, "in_S_0");
  const Lanelet& last_ring = lanelet(d, "ring_EN_0");
  EXPECT_LT(last_ring.length, threshold_on(d, last_ring));
  const std::size_t k = first_with(rows, Blinker::Right);
  ASSERT_LT(k, rows.size());
  ASSERT_GT(k, 0u);
  EXPECT_LT(approach.s_end() - rows[k].s_front, threshold_on(d, approach));
  EXPECT_GE(approach.s_end() - rows[k - 1].s_front, threshold_on(d, approach));
  std::size_t passing = 0, exiting = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string& lane = rows[i].lane;
    Blinker expected = Blinker::None;
    if ((lane == "in_S_0" && i >= k) || lane == ":RS_0_0" || lane == "ring_EN_0" || lane == ":RN_1_0")
      expected = Blinker::Right;
    passing += lane == "ring_SE_0" || lane == ":RE_2_0";
    exiting += lane == "ring_EN_0" || lane == ":RN_1_0";
    ASSERT_EQ(rows[i].blinker, expected) << "t=" << rows[i].time << " lane " << lane;
  }
  EXPECT_GT(passing, 10u);
  EXPECT_GT(exiting, 10u);
  const RunMetrics m = compute_metrics(d.scenario, d.plan.map, d.record);
  ASSERT_EQ(m.sections.size(), 2u);
  EXPECT_EQ(m.sections[1].section.kind, "roundabout_exit");
  EXPECT_EQ(m.sections[1].section.blinker, Blinker::Left);  // the jp preset
  EXPECT_EQ(m.sections[1].missed, std::optional<bool>(true));
}

// tl_red_stop_then_go: red until 40 s. SUMO stops before the line on its own (recorded as a stop
// without a judge, against the judge's stop point), waits while red, crosses on green, arrives.
TEST(SumoDriven, StopsAtTheRedLightByItselfThenGoesOnGreen) {
  const Driven d = drive_by_sumo("tl_red_stop_then_go");
  const auto& rows = d.record.rows;
  ASSERT_TRUE(d.record.arrived);
  expect_rows_are_sumos(d.record);
  EXPECT_TRUE(d.record.red_violations.empty());
  ASSERT_EQ(d.record.stops.size(), 1u);
  const LightStop& stop = d.record.stops[0];
  EXPECT_EQ(stop.tl_id, "C");
  EXPECT_FALSE(stop.by_judge);
  EXPECT_NEAR(stop.stop_s, 389.6, 0.01);  // stop line, stop_margin 0
  EXPECT_LT(stop.error, 0.0) << "SUMO rests before the stop line";
  EXPECT_GT(stop.error, -2.0);
  std::size_t at_stop = 0;
  while (rows[at_stop].time < stop.time - 1e-9) ++at_stop;
  EXPECT_EQ(rows[at_stop].tl_state, 'r');
  std::size_t crossing = at_stop;
  while (crossing < rows.size() && rows[crossing].s_front <= 389.6) ++crossing;
  ASSERT_LT(crossing, rows.size());
  for (std::size_t i = at_stop; i < crossing; ++i)
    if (rows[i].tl_state == 'r') {
      ASSERT_LT(rows[i].speed, 0.1) << "moving at red, t=" << rows[i].time;
    }
  EXPECT_EQ(rows[crossing - 1].tl_state, 'G');
  EXPECT_GT(rows[crossing].time, 40.0);
}

// avoidance_left: a car parked on the ego's lane. SUMO passes it with its own lane changes (left,
// then back right), each with its blinker; the ego is located on in_S while on the other lane.
TEST(SumoDriven, OwnLaneChangesAroundAParkedCarAreRecordedOffThePlan) {
  const Driven d = drive_by_sumo("avoidance_left");
  const auto& rows = d.record.rows;
  ASSERT_TRUE(d.record.arrived) << "SUMO must pass the parked car on its own";
  expect_rows_are_sumos(d.record);
  ASSERT_EQ(d.record.off_plan.size(), 1u);
  const OffPlanStretch& o = d.record.off_plan[0];
  EXPECT_EQ(o.lane, "in_S_1");
  EXPECT_EQ(o.planned_lane, "in_S_0");
  const double parked_front = 120.0;  // the obstacle's lane position on in_S (s from 0 there)
  EXPECT_LT(o.s_from, parked_front - 4.5);
  EXPECT_GT(o.s_to, parked_front);
  const std::size_t left = first_with(rows, Blinker::Left);
  ASSERT_LT(left, rows.size());
  EXPECT_LT(rows[left].s_front, o.s_from) << "left blinker before the change";
  bool right_before_return = false;
  for (const TimelineRow& r : rows)
    if (r.blinker == Blinker::Right && r.s_front <= o.s_to && r.s_front > parked_front) right_before_return = true;
  EXPECT_TRUE(right_before_return);
  for (std::size_t i = 1; i < rows.size(); ++i) ASSERT_GE(rows[i].s_front, rows[i - 1].s_front);
}

// lane_change_right departs on in_S_1 (the plan changes to in_S_0 for straight on). SUMO keeps
// in_S_1 and takes the other straight connection, :C_9_1: located in junction C of the route, its
// route position never goes back and stays within the junction.
TEST(SumoDriven, AnotherConnectionThroughTheJunctionIsLocatedInIt) {
  const Driven d = drive_by_sumo("lane_change_right");
  const auto& rows = d.record.rows;
  ASSERT_TRUE(d.record.arrived);
  EXPECT_EQ(d.record.off_route_steps, 0);
  ASSERT_GE(d.record.off_plan.size(), 2u);
  EXPECT_EQ(d.record.off_plan[0].lane, "in_S_1");
  EXPECT_EQ(d.record.off_plan[0].planned_lane, "in_S_0");
  EXPECT_EQ(d.record.off_plan[1].lane, ":C_9_1");
  EXPECT_EQ(d.record.off_plan[1].planned_lane, ":C_9_0");
  const Lanelet& junction = lanelet(d, ":C_9_0");
  std::size_t inside = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (i > 0) {
      ASSERT_GE(rows[i].s_front, rows[i - 1].s_front) << "t=" << rows[i].time;
    }
    if (rows[i].lane != ":C_9_1") continue;
    ++inside;
    EXPECT_GE(rows[i].s_front, junction.s_start);
    EXPECT_LE(rows[i].s_front, junction.s_end());
  }
  EXPECT_GT(inside, 5u);
}

}  // namespace
}  // namespace signalsim

namespace signalsim {
namespace {

// A SUMO-driven run ends at the sumocfg's `end` when that comes before `duration` after departure
// (docs/sumo.md), as a signalsim-driven run does, and records the same SUMO fields: the output
// directory, SUMO's log there, the options passed through and the back-end's notes.
TEST(SumoDriven, EndsAtTheSumocfgEndAndRecordsTheRunsSumoFields) {
  namespace fs = std::filesystem;
  const fs::path work = fs::temp_directory_path() / ("signalsim_sumocfg_end_" + std::to_string(::getpid()));
  fs::create_directories(work);
  std::ofstream(work / "short.sumocfg")
      << "<configuration><input><net-file value=\"" << SIGNALSIM_SOURCE_DIR
      << "/sumo_nets/cross/cross.net.xml\"/></input><time><begin value=\"0\"/><end value=\"8\"/>"
         "<step-length value=\"0.1\"/></time></configuration>\n";
  std::ofstream(work / "short.yaml") << "name: short\nsumocfg: short.sumocfg\nduration: 60\n"
                                        "ego: {route: [in_S, out_W], depart_speed: 8.33}\n";
  const Scenario scenario = load_scenario((work / "short.yaml").string());
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const auto run_with = [&](bool sumo_drives) {
    RunContext context;
    context.sumo_drives = sumo_drives;
    context.out_dir = (work / (sumo_drives ? "sumo" : "signalsim")).string();
    fs::create_directories(context.out_dir);
    const StartedRun run = start_run(plan_run(scenario, net), net, context);
    return drive(run, net);
  };
  const RunRecord by_sumo = run_with(true), by_signalsim = run_with(false);
  for (const RunRecord* r : {&by_sumo, &by_signalsim}) {
    ASSERT_FALSE(r->rows.empty());
    EXPECT_FALSE(r->arrived);  // 8 s are not enough for the 300 m
    EXPECT_NEAR(r->rows.back().time, 7.9, 1e-9);  // the last step ends at the sumocfg's end
  }
  EXPECT_EQ(by_sumo.sumo.out_dir, (work / "sumo").string());
  EXPECT_EQ(by_sumo.sumo.log, (work / "sumo" / "sumo.log").string());
  EXPECT_EQ(by_sumo.sumo.args, by_signalsim.sumo.args);
  EXPECT_EQ(by_sumo.sumo.notes, by_signalsim.sumo.notes);
  EXPECT_EQ(by_sumo.sumo.server_options, by_signalsim.sumo.server_options);
  EXPECT_EQ(by_sumo.sumo.backend, by_signalsim.sumo.backend);
  fs::remove_all(work);
}

}  // namespace
}  // namespace signalsim
