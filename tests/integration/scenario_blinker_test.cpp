// For each bundled intersection scenario, run the real libsumo and check, step by step, where each
// blinker turns on and off against docs/behaviour.md §T4 / §T6 and the route positions of the net (the numbers
// below were derived independently from the .net.xml files with a separate script).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "scenario/scenario.hpp"
#include "step/route_planning.hpp"
#include "sim/step_loop.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"

namespace signalsim {
namespace {

constexpr double kSearchTime = 3.0;       // turn_signal_search_time
constexpr double kSearchDistance = 30.0;  // turn_signal_intersection_search_distance

/// One stretch of blinker: it turns on at the first step where the turn lane start is within the
/// search distance of the front (docs/behaviour.md §T4.3, strict), and off (or over to the next stretch) at
/// the first step where base_link passed `s_off` (desired end, or the required end when a later
/// request takes over, docs/behaviour.md §T4.3 FIRST_ACTIVE / §T6).
struct Stretch {
  Blinker blinker;
  double s_lane_start;    // route s of the turn lanelet group start
  double fixed_search;    // > 0: the lanelet's turn_signal_distance; else 3 v + 30
  double s_off;           // base_link passes this -> the stretch ends
};

struct Case {
  std::string scenario;
  std::vector<Stretch> stretches;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.scenario; }

std::string path_of(const std::string& scenario) {
  return std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + scenario + ".yaml";
}

class ScenarioBlinker : public ::testing::TestWithParam<Case> {};

TEST_P(ScenarioBlinker, TurnsOnAndOffWhereTheSpecSays) {
  const Case& c = GetParam();
  const Scenario scenario = load_scenario(path_of(c.scenario));
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  for (const Stretch& st : c.stretches) {  // the route builder agrees with the independent numbers
    const std::size_t i = plan.map.index_at(st.s_lane_start + 1e-3);
    EXPECT_NEAR(plan.map.at(i).s_start, st.s_lane_start, 0.01) << "turn lanelet start on the route";
    EXPECT_TRUE(plan.map.at(i).is_internal);
  }

  const RunRecord record = run_scenario(scenario, plan, net);
  ASSERT_TRUE(record.arrived) << "the ego must drive the whole route";
  ASSERT_GT(record.rows.size(), 100u);
  const double b2f = scenario.ego.base_link_to_front;

  // Walk the rows: every change of blinker must be one the stretches predict, at the predicted step.
  std::size_t next = 0;            // the stretch expected to start next
  Blinker current = Blinker::None;
  const Stretch* active = nullptr;
  for (std::size_t k = 0; k < record.rows.size(); ++k) {
    const TimelineRow& row = record.rows[k];
    const double s_base = row.s_front - b2f;
    Blinker expected = current;
    if (active && s_base > active->s_off) {  // the active stretch ended at this step
      active = nullptr;
      expected = Blinker::None;
    }
    if (!active && next < c.stretches.size()) {  // a queued request waits for the active one (§T4.3)
      const Stretch& st = c.stretches[next];
      const double search = st.fixed_search > 0 ? st.fixed_search : kSearchTime * row.speed + kSearchDistance;
      if (st.s_lane_start - row.s_front < search && s_base <= st.s_off) {
        active = &st;
        expected = st.blinker;
        ++next;
      }
    }
    ASSERT_EQ(to_string(row.blinker), to_string(expected))
        << c.scenario << ": step " << k << " t=" << row.time << " s_front=" << row.s_front;
    current = expected;
    if (row.sumo_signals >= 0) {
      ASSERT_EQ(row.sumo_signals & sumo::kBlinkerMask, signal_mask(row.blinker)) << "SUMO shows another mask at t=" << row.time;
    }
  }
  EXPECT_EQ(next, c.stretches.size()) << "every stretch must have started";
  EXPECT_EQ(record.collisions, 0);
}

// Route positions from the nets (turn group start, desired end, required end per docs/behaviour.md §T7).
INSTANTIATE_TEST_SUITE_P(
    Bundled, ScenarioBlinker,
    ::testing::Values(
        Case{"intersection_left", {{Blinker::Left, 189.60, 0, 208.95}}},
        Case{"intersection_right", {{Blinker::Right, 189.60, 0, 198.63}}},
        Case{"intersection_straight", {}},
        Case{"t_junction_left", {{Blinker::Left, 192.80, 0, 206.99}}},
        // turn_signal_distance = 45 on in_S_0 reaches the turn lanelet (docs/behaviour.md §S3).
        Case{"turn_signal_distance_override", {{Blinker::Left, 192.80, 45.0, 206.99}}},
        // Pattern 1 (docs/behaviour.md §T6.3): left until its required end 201.80, then right until B's end.
        Case{"close_turns", {{Blinker::Left, 192.80, 0, 201.80}, {Blinker::Right, 247.59, 0, 256.62}}}),
    [](const auto& info) { return info.param.scenario; });

}  // namespace
}  // namespace signalsim
