// Lateral motion on the real libsumo: SumoSession::command_lateral_offset drives a ShiftPlan (lane
// change, avoidance, pull over / pull out) with SUMO's sublane model, step by step, and the ego's
// measured lateral offset (SumoSession::lateral_offset_from) follows the plan within 0.2 m at every
// step. Net: sumo_nets/signal_cross, route in_S -> out_N (in_S: two lanes, index 0 on the right).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "planning/shift_line.hpp"
#include "net/net_index.hpp"
#include "session/sumo_session.hpp"

namespace signalsim {
namespace {

constexpr double kStep = 0.1;             // s
constexpr double kBaseLinkToFront = 3.7;  // m: the plans are on base_link's s
constexpr double kVehicleWidth = 1.8;     // m: SUMO's DEFAULT_VEHTYPE, which the ego type copies
constexpr double kTolerance = 0.2;        // m
const std::string kEdge = "in_S";
const std::string kLane0 = "in_S_0";
const std::string kLane1 = "in_S_1";

std::string net_path() { return std::string(SIGNALSIM_SOURCE_DIR) + "/sumo_nets/signal_cross/signal_cross.net.xml"; }

const sumo::NetLane& net_lane(const std::string& lane_id) {
  static const sumo::NetIndex net = sumo::NetIndex::load(net_path());
  const sumo::NetLane* lane = net.lane(lane_id);
  if (lane == nullptr) throw std::runtime_error("no lane " + lane_id);
  return *lane;
}
double lane_width(const std::string& lane_id) { return net_lane(lane_id).width; }
// in_S runs straight north (checked below): a point `offset` left of lane 0's centre has x = this - offset.
double lane0_x() { return net_lane(kLane0).shape.points().front().x; }

sumo::SessionConfig config(double speed) {
  sumo::SessionConfig c;
  c.net = net_path();
  c.route = {"in_S", "out_N"};
  c.step_length = kStep;
  c.depart_lane = 0;
  c.depart_pos = 0.0;
  c.depart_speed = speed;
  c.max_speed = 20.0;
  c.lateral_resolution = 0.1;
  return c;
}

struct Tracking {
  double worst = 0.0;           // max |measured - planned| over every step [m]
  double worst_xy = 0.0;        // the same from the ego's net position (an oracle independent of lanes)
  double min_offset = 1e9;      // measured, from the reference lane centre [m]
  double max_offset = -1e9;
  int steps = 0;
  bool left_edge = false;       // the ego was seen off kEdge before the end of the run
  bool left_lane0 = false;      // ... or off lane 0
  std::string final_lane;
  double final_lateral_lane_position = 0.0;
  // The lane switch as SUMO reports it: measured offset and getLateralLanePosition just before and
  // just after the ego's lane id changed.
  bool switched = false;
  double offset_before_switch = 0.0, lat_before_switch = 0.0;
  double offset_after_switch = 0.0, lat_after_switch = 0.0;
};

// Drives `plan` (offsets from the centre of `reference`) at constant `speed` until base_link
// reaches `s_stop`, commanding the offset for the next step each step.
Tracking drive(const ShiftPlan& plan, double speed, double s_stop, const std::string& reference = kLane0) {
  const auto owner = sumo::open_session(config(speed));
  sumo::SumoSession& session = *owner;
  Tracking t;
  std::string previous_lane;
  double previous_offset = 0.0, previous_lat = 0.0;
  for (;;) {
    const sumo::EgoState e = session.ego();
    if (e.edge != kEdge) {
      t.left_edge = true;
      break;
    }
    if (e.lane != kLane0) t.left_lane0 = true;
    EXPECT_NEAR(e.speed, speed, 0.01) << "t=" << e.time << ": the longitudinal motion is the commanded speed";
    const double s = e.lane_pos - kBaseLinkToFront;  // lanes of in_S share one length: s = lane position
    const double measured = session.lateral_offset_from(reference);
    t.worst = std::max(t.worst, std::abs(measured - plan.offset_at(s)));
    if (reference == kLane0) t.worst_xy = std::max(t.worst_xy, std::abs((lane0_x() - e.x) - plan.offset_at(s)));
    t.min_offset = std::min(t.min_offset, measured);
    t.max_offset = std::max(t.max_offset, measured);
    if (!previous_lane.empty() && e.lane != previous_lane && !t.switched) {
      t.switched = true;
      t.offset_before_switch = previous_offset;
      t.lat_before_switch = previous_lat;
      t.offset_after_switch = measured;
      t.lat_after_switch = e.lateral_offset;
    }
    previous_lane = e.lane;
    previous_offset = measured;
    previous_lat = e.lateral_offset;
    t.final_lane = e.lane;
    t.final_lateral_lane_position = e.lateral_offset;
    if (s >= s_stop) break;
    session.command(0, speed);
    session.command_lateral_offset(plan.offset_at(s + e.speed * kStep), reference);
    if (!session.step()) {
      t.left_edge = true;
      break;
    }
    ++t.steps;
  }
  EXPECT_EQ(session.ego_collisions(), 0);
  return t;
}

void report(const char* name, double speed, const Tracking& t) {
  std::printf("[lateral] %s at %.1f m/s: worst tracking error %.4f m (from x: %.4f m) over %d steps, "
              "offset range [%.3f, %.3f]\n", name, speed, t.worst, t.worst_xy, t.steps, t.min_offset, t.max_offset);
  if (t.switched)
    std::printf("[lateral]   lane switch: offset %.3f (lat %.3f) -> offset %.3f (lat %.3f)\n", t.offset_before_switch,
                t.lat_before_switch, t.offset_after_switch, t.lat_after_switch);
  ::testing::Test::RecordProperty("worst_error_mm", static_cast<int>(std::lround(t.worst * 1000.0)));
}

// (a) lane 0 -> lane 1 over the length the default jerk / acceleration limits ask for.
void lane_change_at(double speed) {
  const double width = 0.5 * (lane_width(kLane0) + lane_width(kLane1));  // centre to centre, left positive
  const double length = ShiftLengthPolicy{}.length_for(width, speed);
  const double s0 = 20.0;
  const ShiftPlan plan = plan_lane_change(s0, width, length);
  const Tracking t = drive(plan, speed, s0 + length + 2.0 * speed);  // 2 s on the target lane
  report("lane change", speed, t);
  EXPECT_FALSE(t.left_edge);
  EXPECT_GT(t.steps, 50);
  EXPECT_LE(t.worst, kTolerance);
  EXPECT_LE(t.worst_xy, kTolerance);
  EXPECT_EQ(t.final_lane, kLane1);
  EXPECT_NEAR(t.final_lateral_lane_position, 0.0, kTolerance) << "centred on the target lane";
  // SUMO moves the ego to lane 1 when its centre crosses the boundary between the lanes.
  ASSERT_TRUE(t.switched);
  const double boundary = 0.5 * lane_width(kLane0);
  EXPECT_LE(t.offset_before_switch, boundary + 1e-6);
  EXPECT_GE(t.offset_after_switch, boundary - 1e-6);
  // The measured offset is continuous across the switch although getLateralLanePosition jumps.
  EXPECT_LT(t.offset_after_switch - t.offset_before_switch, 0.5);
  EXPECT_GT(t.lat_before_switch - t.lat_after_switch, 2.0);
}

TEST(LateralMotion, TheNetHasTheLanesTheTestsAssume) {
  EXPECT_DOUBLE_EQ(lane_width(kLane0), 3.2);
  EXPECT_DOUBLE_EQ(lane_width(kLane1), 3.2);
  for (const std::string& id : {kLane0, kLane1}) {  // straight north, lane 0 on the right (east)
    const auto& points = net_lane(id).shape.points();
    ASSERT_EQ(points.size(), 2u);
    EXPECT_DOUBLE_EQ(points.front().x, points.back().x);
    EXPECT_LT(points.front().y, points.back().y);
  }
  EXPECT_DOUBLE_EQ(net_lane(kLane0).shape.points().front().x - net_lane(kLane1).shape.points().front().x,
                   0.5 * (lane_width(kLane0) + lane_width(kLane1)));
  EXPECT_DOUBLE_EQ(net_lane(kLane0).length, net_lane(kLane1).length);
}

TEST(LateralMotion, OffsetFromAnotherLaneOfTheEdgeIsTheDistanceBetweenTheCentres) {
  const auto owner = sumo::open_session(config(10.0));
  sumo::SumoSession& session = *owner;
  ASSERT_TRUE(session.step());
  EXPECT_NEAR(session.lateral_offset_from(kLane0), 0.0, 1e-9);
  EXPECT_NEAR(session.lateral_offset_from(kLane1), -0.5 * (lane_width(kLane0) + lane_width(kLane1)), 1e-9);
  // A lane of another edge: the plain offset inside the ego's own lane.
  EXPECT_NEAR(session.lateral_offset_from("out_N_1"), session.ego().lateral_offset, 1e-9);
  EXPECT_THROW(session.lateral_offset_from("no_such_lane"), sumo::SumoError);
  EXPECT_THROW(session.command_lateral_offset(0.0, "out_N_0"), sumo::SumoError) << "not the ego's edge";
}

TEST(LateralMotion, CommandingAnOffsetNeedsTheSublaneModel) {
  sumo::SessionConfig c = config(10.0);
  c.lateral_resolution = 0.0;
  const auto owner = sumo::open_session(c);
  sumo::SumoSession& session = *owner;
  EXPECT_THROW(session.command_lateral_offset(0.5, kLane0), sumo::SumoError);
  EXPECT_NEAR(session.lateral_offset_from(kLane0), 0.0, 1e-9);  // measuring works in either model
}

TEST(LateralMotion, ATargetBeyondTheRoadEdgeStopsAtTheEdge) {
  const auto owner = sumo::open_session(config(10.0));
  sumo::SumoSession& session = *owner;
  const double edge_offset = -0.5 * (lane_width(kLane0) - kVehicleWidth);
  for (int k = 0; k < 30; ++k) {
    session.command(0, 10.0);
    session.command_lateral_offset(-1.5, kLane0);
    ASSERT_TRUE(session.step());
    EXPECT_GE(session.lateral_offset_from(kLane0), edge_offset - 1e-6);
  }
  EXPECT_NEAR(session.lateral_offset_from(kLane0), edge_offset, 1e-6);
  EXPECT_EQ(session.ego().lane, kLane0);
}

TEST(LateralMotion, LaneChangeAt10) { lane_change_at(10.0); }
TEST(LateralMotion, LaneChangeAt16) { lane_change_at(16.0); }

// (b) out to +1.0 m past an obstacle, hold, back to the lane centre.
TEST(LateralMotion, AvoidanceShiftOutHoldAndBack) {
  const double speed = 10.0;
  AvoidanceRequest request;
  request.s_object_start = 150.0;
  request.s_object_end = 160.0;
  request.vehicle_width = kVehicleWidth;
  request.clearance = 1.0;
  request.object_left = 1.0 - request.clearance - 0.5 * kVehicleWidth;  // passing offset +1.0 m
  request.object_right = request.object_left - 1.0;
  request.side = AvoidSide::Left;
  request.speed = speed;
  ASSERT_NEAR(avoidance_offset(request), 1.0, 1e-9);
  const ShiftPlan plan = plan_avoidance(request);
  ASSERT_EQ(plan.lines().size(), 2u);
  const Tracking t = drive(plan, speed, plan.lines().back().s_end + 2.0 * speed);
  report("avoidance +1.0 m", speed, t);
  EXPECT_FALSE(t.left_edge);
  EXPECT_LE(t.worst, kTolerance);
  EXPECT_LE(t.worst_xy, kTolerance);
  EXPECT_NEAR(t.max_offset, 1.0, kTolerance);
  EXPECT_FALSE(t.left_lane0) << "1.0 m keeps the ego's centre inside lane 0";
  EXPECT_NEAR(t.final_lateral_lane_position, 0.0, kTolerance);
}

// (c) to the right edge of lane 0 and back: pull over, then pull out.
TEST(LateralMotion, PullOverToTheRoadEdgeAndPullOut) {
  const double speed = 10.0;
  const double edge_offset = -0.5 * (lane_width(kLane0) - kVehicleWidth);  // the ego's right side on the lane edge
  const double length = ShiftLengthPolicy{}.length_for(edge_offset, speed);
  const ShiftPlan over = plan_pull_over(40.0 + length, edge_offset, length);
  const double s_out = over.lines().back().s_end + 30.0;
  const ShiftPlan out = plan_pull_out(s_out, edge_offset, length);
  const ShiftPlan plan({over.lines().front(), out.lines().front()});
  const Tracking t = drive(plan, speed, s_out + length + 2.0 * speed);
  report("pull over / pull out", speed, t);
  EXPECT_FALSE(t.left_edge);
  EXPECT_FALSE(t.left_lane0);
  EXPECT_LE(t.worst, kTolerance);
  EXPECT_LE(t.worst_xy, kTolerance);
  EXPECT_NEAR(t.min_offset, edge_offset, kTolerance);
  EXPECT_GE(t.min_offset, edge_offset - 1e-6) << "never beyond the road edge";
  EXPECT_NEAR(t.final_lateral_lane_position, 0.0, kTolerance);
}

}  // namespace
}  // namespace signalsim
