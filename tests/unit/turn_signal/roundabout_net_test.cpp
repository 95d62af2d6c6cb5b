// Roundabout roles, leaves_ring_at_end, the exit-signal marking and the decider on a real net built by
// netconvert (tests/data/nets/roundabout.net.xml: a 4-node ring, one arm per node; see build.sh there).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "drive.hpp"
#include "net/net_index.hpp"
#include "route/route_builder.hpp"
#include "turn_signal/exit_signal_marking.hpp"
#include "turn_signal/roundabout_requests.hpp"

namespace signalsim {
namespace {

using ::testing::ElementsAre;

const sumo::NetIndex& net() {
  static const sumo::NetIndex index =
      sumo::NetIndex::load(std::string(SIGNALSIM_TEST_NETS_DIR) + "/roundabout.net.xml");
  return index;
}

RouteMap third_exit_route() { return sumo::build_route(net(), {"in0", "r01", "r12", "r23", "out3"}).map; }

std::vector<std::string> lane_ids(const RouteMap& route) {
  std::vector<std::string> ids;
  for (const Lanelet& l : route.lanelets()) ids.push_back(l.lane_id);
  return ids;
}

RouteMap with_param(const RouteMap& route, std::size_t index, const std::string& key, const std::string& value) {
  std::vector<Lanelet> lanelets(route.lanelets().begin(), route.lanelets().end());
  lanelets.at(index).params[key] = value;
  return RouteMap(std::move(lanelets));
}

TEST(RoundaboutNet, RolesAndLeavesRingAtEnd) {
  const RouteMap route = third_exit_route();
  ASSERT_THAT(lane_ids(route), ElementsAre("in0_0", ":R0_0_0", "r01_0", ":R1_2_0", "r12_0", ":R2_1_0", "r23_0",
                                           ":R3_1_0", "out3_0"));
  using R = RoundaboutRole;
  const std::vector<R> roles{R::None,     R::Entry,    R::Internal, R::Internal, R::Internal,
                             R::Internal, R::Internal, R::Exit,     R::None};
  // Every ring node has an exit: the ring lanes ending there and the internal ring -> ring lanes in it.
  const std::vector<bool> leaves{false, false, true, true, true, true, true, false, false};
  for (std::size_t i = 0; i < route.size(); ++i) {
    EXPECT_EQ(route.at(i).roundabout_role, roles[i]) << route.at(i).lane_id;
    EXPECT_EQ(route.at(i).leaves_ring_at_end, leaves[i]) << route.at(i).lane_id;
  }
}

TEST(RoundaboutNet, MarkingFromThePreviousExit) {
  const RouteMap route = mark_exit_signal_lanes(third_exit_route());
  std::vector<std::string> marked;
  for (const Lanelet& l : route.lanelets())
    if (l.params.contains("enable_exit_turn_signal")) marked.push_back(l.lane_id);
  EXPECT_THAT(marked, ElementsAre("r23_0"));  // after node R2, where out2 branches off
  const RouteMap first = mark_exit_signal_lanes(sumo::build_route(net(), {"in0", "r01", "out1"}).map);
  marked.clear();
  for (const Lanelet& l : first.lanelets())
    if (l.params.contains("enable_exit_turn_signal")) marked.push_back(l.lane_id);
  EXPECT_THAT(marked, ElementsAre("r01_0"));
}

TEST(RoundaboutNet, JapanExitBlinkerWithAndWithoutMarking) {
  const RouteMap plain = third_exit_route();
  const RouteMap marked = mark_exit_signal_lanes(plain);
  const auto params = test::roundabout_params("None", "Left");
  const double previous_exit = plain.at(6).s_start;  // r23_0, leaving node R2 where out2 branches off
  const double exit = plain.at(7).s_start;           // :R3_1_0
  const double exit_end = plain.at(7).s_end();

  test::Drive literal(plain, params, 0.0);
  EXPECT_EQ(literal.to_front(exit).turn, TurnIndicator::Disable);
  EXPECT_EQ(literal.to_front(exit + 0.01).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(literal.to_base(exit_end + 0.01).turn, TurnIndicator::Disable);

  test::Drive law(marked, params, 0.0);
  EXPECT_EQ(law.to_front(previous_exit).turn, TurnIndicator::Disable);
  const auto& on = law.to_front(previous_exit + 0.01);
  EXPECT_EQ(on.turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(on.source, RequestSource::RoundaboutExit);
  EXPECT_EQ(law.to_base(exit_end).turn, TurnIndicator::EnableLeft);
  EXPECT_EQ(law.to_base(exit_end + 0.01).turn, TurnIndicator::Disable);
}

TEST(RoundaboutNet, ExitTagsByInternalLaneIdOrOutgoingEdge) {
  const RouteMap plain = third_exit_route();
  const auto params = test::roundabout_params("None", "None");
  for (const std::string& tag : {std::string("[:R3_1_0]"), std::string("[out3]")}) {
    const RouteMap route = with_param(plain, 1, "exit_turn_signal_right", tag);
    test::Drive drive(route, params, 0.0);
    const auto& d = drive.to_front(route.at(1).s_start - 10.0);
    EXPECT_EQ(d.turn, TurnIndicator::EnableRight) << tag;
    EXPECT_EQ(d.source, RequestSource::RoundaboutEntry) << tag;
  }
  const RouteMap other = with_param(plain, 1, "exit_turn_signal_right", "[:R1_1_0, out1, out2]");
  test::Drive drive(other, params, 0.0);
  EXPECT_EQ(drive.to_front(other.at(1).s_start - 10.0).turn, TurnIndicator::Disable);
}

TEST(RoundaboutNet, ApproachTurnSignalDistanceReachesTheEntry) {
  // in0 carries turn_signal_distance 20 (an edge param): the entry request starts within 20 m.
  const RouteMap route = third_exit_route();
  const double entry = route.at(1).s_start;
  test::Drive drive(route, test::roundabout_params("Left", "None"), 0.0);
  EXPECT_EQ(drive.to_front(entry - 20.0).turn, TurnIndicator::Disable);
  EXPECT_EQ(drive.to_front(entry - 19.5).turn, TurnIndicator::EnableLeft);
}

}  // namespace
}  // namespace signalsim
