// Which SUMO model drives the ego's lateral motion (docs/behaviour.md §S4), end to end on the real
// libsumo: lane changes alone run SUMO's continuous lane change (no sublane model for the other
// vehicles), avoidance, pull out and pull over the sublane model; a user's own options win.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "maneuver_run.hpp"
#include "session/sumo_command_line.hpp"
#include "sim/session_setup.hpp"

namespace signalsim {
namespace {

struct Configured {
  sumo::SessionConfig config;
  std::vector<std::string> command_line;
};

Configured configured_file(const std::string& path, std::vector<std::string> set = {}) {
  const Scenario scenario = load_scenario(path, ScenarioOverrides{std::move(set)});
  const sumo::NetIndex net = sumo::NetIndex::load(scenario.net);
  const sumo::RoutePlan plan = plan_route(scenario, net);
  Configured c;
  c.config = session_config(scenario, plan, plan_lateral(scenario, plan, net), RunContext{});
  c.command_line = sumo::sumo_command_line(c.config, "sumo");
  return c;
}

Configured configured(const std::string& name, std::vector<std::string> set = {}) {
  return configured_file(std::string(SIGNALSIM_SOURCE_DIR) + "/scenarios/" + name + ".yaml", std::move(set));
}

// Whether SUMO's command line gives `option` the number `value` (written exactly: 0.1 has 17 digits).
bool has_option(const Configured& c, const std::string& option, double value) {
  for (std::size_t i = 0; i + 1 < c.command_line.size(); ++i)
    if (c.command_line[i] == option && std::stod(c.command_line[i + 1]) == value) return true;
  return false;
}

bool mentions(const Configured& c, const std::string& option) {
  return std::find(c.command_line.begin(), c.command_line.end(), option) != c.command_line.end();
}

TEST(LateralModel, ALaneChangeRunsSumosContinuousLaneChangeNotTheSublaneModel) {
  const Configured c = configured("lane_change_right");
  EXPECT_DOUBLE_EQ(c.config.lateral_resolution, 0.0);
  EXPECT_DOUBLE_EQ(c.config.lane_change_duration, 0.2);  // two steps of 0.1 s
  EXPECT_TRUE(has_option(c, "--lanechange.duration", 0.2));
  EXPECT_FALSE(mentions(c, "--lateral-resolution"));
}

TEST(LateralModel, AvoidancePullOutAndPullOverRunTheSublaneModel) {
  for (const char* name : {"avoidance_left", "pull_out_left", "pull_over_right"}) {
    const Configured c = configured(name);
    EXPECT_DOUBLE_EQ(c.config.lateral_resolution, 0.1) << name;
    EXPECT_DOUBLE_EQ(c.config.lane_change_duration, 0.0) << name;
    EXPECT_TRUE(has_option(c, "--lateral-resolution", 0.1)) << name;
    EXPECT_FALSE(mentions(c, "--lanechange.duration")) << name;
  }
}

TEST(LateralModel, AUsersOwnOptionsDecideTheModel) {
  // Their sublane model drives the lane change too; their lane-change duration of 0 is a jump in
  // SUMO, so the sublane model drives it; a longer one than a step is used as it is.
  EXPECT_DOUBLE_EQ(configured("lane_change_right", {"sumo_args=[--lateral-resolution, 0.4]"}).config.lateral_resolution,
                   0.4);
  const Configured zero = configured("lane_change_right", {"sumo_args=[--lanechange.duration, 0]"});
  EXPECT_DOUBLE_EQ(zero.config.lateral_resolution, 0.1);
  EXPECT_DOUBLE_EQ(zero.config.lane_change_duration, 0.0);
  const Configured longer = configured("lane_change_right", {"sumo_args=[--lanechange.duration, 3]"});
  EXPECT_DOUBLE_EQ(longer.config.lateral_resolution, 0.0);
  EXPECT_DOUBLE_EQ(longer.config.lane_change_duration, 3.0);
  EXPECT_FALSE(mentions(longer, "--lateral-resolution"));
  // No intersection: a run without lateral motion asks for neither.
  const Configured none = configured("intersection_left");
  EXPECT_FALSE(mentions(none, "--lateral-resolution"));
  EXPECT_FALSE(mentions(none, "--lanechange.duration"));
}

// SUMO refuses a positive lanechange.duration beside the sublane model ("Only one of the options ...",
// naming an option the user did not give): a duration of a step or less for a lane change, or any for
// avoidance, is refused before SUMO starts, naming the user's option.
TEST(LateralModel, AUsersLaneChangeDurationThatNeedsTheSublaneModelIsRefused) {
  for (const auto& [name, duration] : {std::pair{"lane_change_right", "0.1"}, std::pair{"avoidance_left", "3"}}) {
    try {
      (void)configured(name, {std::string("sumo_args=[--lanechange.duration, ") + duration + "]"});
      ADD_FAILURE() << name << " with lanechange.duration " << duration << " was accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("needs SUMO's sublane model"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("but its SUMO options set lanechange.duration " + std::string(duration)),
                std::string::npos)
          << e.what();
    }
  }
}

// bologna_acosta's edge 46 has three lanes; the route to 201 leaves from lane 2. From lane 1 one
// continuous lane change does it; from lane 0 the shift crosses lane 1, where the continuous lane
// change would stop the ego for a step (up to 1.875 * 6.4 m / 50 m * 13.89 m/s * 0.1 s = 0.33 m
// behind the plan): the sublane model drives it, unless the ego is slow enough for that lag to stay
// within 0.1 m.
TEST(LateralModel, AFastShiftOverTwoLanesRunsTheSublaneModel) {
  const std::string path = ::testing::TempDir() + "lateral_model_acosta.yaml";
  {
    std::ofstream out(path);
    out << "name: two_lanes_on_46\nnet: " << SIGNALSIM_SOURCE_DIR
        << "/sumo_nets/bologna_acosta/acosta_buslanes.net.xml\nstep_length: 0.1\nduration: 30\n"
           "ego:\n  route: [\"46\", \"201\"]\n  depart_speed: 5\n";
  }
  const Configured one_lane = configured_file(path, {"ego.depart_lane=1"});
  EXPECT_DOUBLE_EQ(one_lane.config.lane_change_duration, 0.2);
  EXPECT_DOUBLE_EQ(one_lane.config.lateral_resolution, 0.0);
  const Configured two_lanes = configured_file(path, {"ego.depart_lane=0"});
  EXPECT_DOUBLE_EQ(two_lanes.config.lateral_resolution, 0.1);
  EXPECT_DOUBLE_EQ(two_lanes.config.lane_change_duration, 0.0);
  const Configured slow = configured_file(path, {"ego.depart_lane=0", "ego.max_speed=3", "ego.depart_speed=3"});
  EXPECT_DOUBLE_EQ(slow.config.lane_change_duration, 0.2);
  EXPECT_DOUBLE_EQ(slow.config.lateral_resolution, 0.0);
  std::remove(path.c_str());
}

// The ego follows the plan gradually across the lane boundary, and SUMO shows the decider's blinker
// at every step, also in the step its continuous lane change ends (SUMO switches it off there).
TEST(LateralModel, TheContinuousLaneChangeFollowsThePlanAndShowsTheBlinkerThroughout) {
  for (const char* name : {"lane_change_right", "two_lane_changes", "roundabout_two_lane_change_before_exit"}) {
    const test::ManeuverRun r = test::run_bundled(name);
    double worst = 0.0;
    int planned = 0;
    std::set<std::string> lanes;
    for (const TimelineRow& row : r.record.rows) {
      if (row.sumo_signals >= 0) {  // -1: the ego has arrived
        EXPECT_EQ(row.sumo_signals & sumo::kBlinkerMask, signal_mask(row.blinker)) << name << " t=" << row.time;
      }
      if (!row.planned_offset) continue;
      ++planned;
      worst = std::max(worst, std::abs(row.lateral_offset - *row.planned_offset));
      lanes.insert(row.lane);
    }
    EXPECT_GT(planned, 100) << name;
    EXPECT_LT(worst, 0.02) << name << ": the plan's tolerance is 0.2 m; measured 0.009 m at most";
    EXPECT_GE(lanes.size(), 2u) << name << ": the ego changed lanes on the plan's edge";
  }
}

}  // namespace
}  // namespace signalsim
