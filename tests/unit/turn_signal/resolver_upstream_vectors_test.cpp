// docs/behaviour.md §T9: the upstream test_turn_signal.cpp vectors (Condition1-6) for resolve_turn_signal.
// Path along x, so s == x. Ego x is a C++ float (48.1f == 48.0999985) converted to double;
// base_link2front = 1.0, so s_base = x and s_front = x + 1. Condition1-3 have no roundabout request,
// Condition4 and 5 no intersection request, Condition6 no behaviour request.
#include <gtest/gtest.h>

#include <ostream>
#include <string>
#include <vector>

#include "test_helpers.hpp"
#include "turn_signal/resolver.hpp"

namespace signalsim {
namespace {

using test::kLeft;
using test::kRight;
using test::kDisable;

struct UpstreamVector {
  std::string condition;
  TurnSignalInfo intersection;
  TurnSignalInfo roundabout;
  TurnSignalInfo behaviour;
  float ego_x;
  TurnIndicator expected;
  RequestSource expected_source;  ///< the request whose command wins (the resolver echoes its source)
};

std::ostream& operator<<(std::ostream& os, const UpstreamVector& v) {
  return os << v.condition << " x=" << v.ego_x << " -> " << to_string(v.expected);
}

// (cmd, desired_start, desired_end, required_start, required_end); {} = no request (NO_COMMAND).
const TurnSignalInfo kCondition1Intersection = test::request(kLeft, 0, 65, 35, 48, RequestSource::Intersection);
const TurnSignalInfo kCondition1Behaviour = test::request(kRight, 5, 70, 45, 50, RequestSource::LaneChange);
const TurnSignalInfo kCondition2Intersection = test::request(kLeft, 0, 65, 35, 50, RequestSource::Intersection);
const TurnSignalInfo kCondition2Behaviour = test::request(kRight, 5, 70, 40, 45, RequestSource::LaneChange);
const TurnSignalInfo kCondition3Intersection = test::request(kLeft, 0, 65, 35, 50, RequestSource::Intersection);
const TurnSignalInfo kCondition3Behaviour = test::request(kRight, 5, 70, 30, 45, RequestSource::LaneChange);
// Condition4: a lane change while driving in a roundabout.
const TurnSignalInfo kCondition4Roundabout = test::request(kRight, 0, 70, 20, 25, RequestSource::RoundaboutExit);
const TurnSignalInfo kCondition4Behaviour = test::request(kLeft, 30, 60, 40, 50, RequestSource::LaneChange);
// Condition5: a lane change before exiting a roundabout.
const TurnSignalInfo kCondition5Roundabout = test::request(kRight, 25, 70, 35, 55, RequestSource::RoundaboutExit);
const TurnSignalInfo kCondition5Behaviour = test::request(kLeft, 0, 40, 20, 30, RequestSource::LaneChange);
// Condition6: a roundabout right after an intersection.
const TurnSignalInfo kCondition6Intersection = test::request(kLeft, 0, 40, 20, 30, RequestSource::Intersection);
const TurnSignalInfo kCondition6Roundabout = test::request(kRight, 20, 60, 35, 50, RequestSource::RoundaboutEntry);

// Which request a command comes from in one Condition: its left and its right request (DISABLE: none).
struct Winners {
  RequestSource left;
  RequestSource right;
};

std::vector<UpstreamVector> condition(const std::string& name, const TurnSignalInfo& intersection,
                                      const TurnSignalInfo& roundabout, const TurnSignalInfo& behaviour, Winners winners,
                                      const std::vector<std::pair<float, TurnIndicator>>& expectations) {
  std::vector<UpstreamVector> out;
  for (const auto& [x, expected] : expectations) {
    const RequestSource source = expected == kLeft    ? winners.left
                                 : expected == kRight ? winners.right
                                                      : RequestSource::None;
    out.push_back({name, intersection, roundabout, behaviour, x, expected, source});
  }
  return out;
}

std::vector<UpstreamVector> all_vectors() {
  std::vector<UpstreamVector> all;
  const auto append = [&all](const std::vector<UpstreamVector>& more) { all.insert(all.end(), more.begin(), more.end()); };
  const Winners intersection_left_lane_change_right{RequestSource::Intersection, RequestSource::LaneChange};
  append(condition("Condition1", kCondition1Intersection, {}, kCondition1Behaviour, intersection_left_lane_change_right,
                   {{4.9f, kLeft}, {5.0f, kLeft}, {34.99f, kLeft}, {40.0f, kLeft}, {45.0f, kLeft}, {48.0f, kLeft},
                    {48.1f, kRight}, {50.0f, kRight}, {50.1f, kRight}, {65.0f, kRight}, {65.1f, kRight},
                    {70.1f, kDisable}}));
  append(condition("Condition2", kCondition2Intersection, {}, kCondition2Behaviour, intersection_left_lane_change_right,
                   {{4.9f, kLeft}, {5.0f, kLeft}, {34.99f, kLeft}, {40.0f, kLeft}, {45.0f, kLeft}, {50.0f, kLeft},
                    {50.1f, kLeft}, {65.0f, kLeft}, {65.1f, kRight}, {70.1f, kDisable}}));
  append(condition("Condition3", kCondition3Intersection, {}, kCondition3Behaviour, intersection_left_lane_change_right,
                   {{4.9f, kRight}, {5.0f, kRight}, {29.9f, kRight}, {30.0f, kRight}, {33.9f, kRight}, {35.0f, kLeft},
                    {44.9f, kLeft}, {45.0f, kLeft}, {49.9f, kLeft}, {50.0f, kLeft}, {65.0f, kLeft}, {65.1f, kRight},
                    {70.1f, kDisable}}));
  const Winners lane_change_left_exit_right{RequestSource::LaneChange, RequestSource::RoundaboutExit};
  append(condition("Condition4", {}, kCondition4Roundabout, kCondition4Behaviour, lane_change_left_exit_right,
                   {{29.99f, kRight}, {30.0f, kRight}, {40.0f, kLeft}, {40.1f, kLeft}, {50.0f, kLeft}, {50.01f, kLeft},
                    {60.0f, kLeft}, {60.1f, kRight}, {70.0f, kRight}, {70.1f, kDisable}}));
  append(condition("Condition5", {}, kCondition5Roundabout, kCondition5Behaviour, lane_change_left_exit_right,
                   {{0.0f, kLeft}, {20.0f, kLeft}, {21.0f, kLeft}, {25.0f, kLeft}, {25.1f, kLeft}, {30.0f, kLeft},
                    {35.0f, kRight}, {35.1f, kRight}, {40.0f, kRight}, {40.1f, kRight}, {55.0f, kRight},
                    {55.1f, kRight}, {70.0f, kRight}, {70.1f, kDisable}}));
  append(condition("Condition6", kCondition6Intersection, kCondition6Roundabout, {},
                   {RequestSource::Intersection, RequestSource::RoundaboutEntry},
                   {{0.0f, kLeft}, {20.0f, kLeft}, {20.1f, kLeft}, {30.0f, kLeft}, {35.0f, kRight}, {40.0f, kRight},
                    {40.1f, kRight}, {50.0f, kRight}, {51.0f, kRight}, {60.0f, kRight}, {60.1f, kDisable}}));
  return all;
}

class UpstreamResolverVectors : public ::testing::TestWithParam<UpstreamVector> {};

TEST_P(UpstreamResolverVectors, ResolvesLikeTheReference) {
  const UpstreamVector& v = GetParam();
  const double x = static_cast<double>(v.ego_x);
  const EgoOnRoute ego{.s_front = x + test::kBaseLinkToFront, .s_base = x, .speed = 0.0};
  const ResolvedTurnSignal r = resolve_turn_signal(ego, v.intersection, v.roundabout, v.behaviour);
  EXPECT_EQ(r.command, v.expected) << "got " << to_string(r.command);
  EXPECT_EQ(r.source, v.expected_source);
}

TEST(UpstreamResolverVectorTable, HasEveryVectorOfTheSpec) {
  EXPECT_EQ(all_vectors().size(), 12u + 10u + 13u + 10u + 14u + 11u);
}

INSTANTIATE_TEST_SUITE_P(Spec9, UpstreamResolverVectors, ::testing::ValuesIn(all_vectors()),
                         [](const ::testing::TestParamInfo<UpstreamVector>& info) {
                           return info.param.condition + "_" + std::to_string(info.index);
                         });

}  // namespace
}  // namespace signalsim
